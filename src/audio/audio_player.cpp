// The SDL2 back end of AudioPlayer. The callback runs on SDL's audio thread: it takes the pending cues
// with try_lock (it never waits for the UI), reads volume/mute/depth from atomics and mixes. Built
// without SDL2 the player is a silent stub with a status sentence. In the web page (emscripten,
// whose SDL2 is a port it cannot download here) the same mixing feeds Web Audio: a script
// processor asks for each block on the page's thread, between frames.
#include "audio/audio_player.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <mutex>

#if defined(__EMSCRIPTEN__)
#include <emscripten/emscripten.h>
#endif
#if defined(S4D_HAVE_SDL2)
#include <SDL.h>
#if defined(S4D_HAVE_ALSA)
#include <alsa/asoundlib.h>
#endif
#endif

namespace s4d {

struct AudioPlayer::Impl {
  std::string status;
  bool open = false;
  std::atomic<float> volume{0.8f};
  std::atomic<bool> mute{false}, tone{false};
  std::atomic<double> depth{0.5};
  std::atomic<std::uint64_t> started{0}, dropped{0}, frames{0};

  struct Pending {
    CueKind kind;
    float gain;
  };
  std::mutex pending_mutex;  // held by producers briefly, by the callback only through try_lock
  std::array<Pending, 64> pending{};
  int pending_count = 0;

#if defined(S4D_HAVE_SDL2)
  SDL_AudioDeviceID device = 0;
  bool subsystem = false;

  static void callback(void* user, Uint8* stream, int len) {
    auto* self = static_cast<Impl*>(user);
    self->fill(reinterpret_cast<float*>(stream), static_cast<std::size_t>(len) / sizeof(float));
  }
#endif
#if defined(S4D_HAVE_SDL2) || defined(__EMSCRIPTEN__)
  CueMixer mixer{kAudioSampleRate};  // audio thread only once the device runs
  void fill(float* out, std::size_t n) {
    if (pending_mutex.try_lock()) {
      for (int i = 0; i < pending_count; ++i) mixer.start(pending[i].kind, pending[i].gain);
      started.fetch_add(pending_count, std::memory_order_relaxed);
      pending_count = 0;
      pending_mutex.unlock();
    }
    mixer.set_volume(volume.load(std::memory_order_relaxed));
    mixer.set_mute(mute.load(std::memory_order_relaxed));
    mixer.set_depth_tone(tone.load(std::memory_order_relaxed));
    mixer.set_depth(depth.load(std::memory_order_relaxed));
    mixer.mix(std::span<float>(out, n));
    frames.fetch_add(n, std::memory_order_relaxed);
  }
#endif
};

#if defined(S4D_HAVE_SDL2)
namespace {
#if defined(S4D_HAVE_ALSA)
// ALSA prints every failed probe of a missing sound card on stderr (eight lines on a machine with
// none); the status line says once why sound is off instead.
extern "C" void quiet_alsa(const char*, int, const char*, int, const char*, ...) {}
void silence_alsa() { snd_lib_error_set_handler(quiet_alsa); }
#else
void silence_alsa() {}
#endif
}  // namespace
#endif

AudioPlayer::AudioPlayer(const AudioPlayerOptions& options) noexcept {
  try {
    impl_ = std::make_unique<Impl>();
  } catch (...) {
    return;  // out of memory: silent, status() says so
  }
#if defined(S4D_HAVE_SDL2)
  Impl& m = *impl_;
  try {
    // SDL would catch SIGINT and SIGTERM and only queue an SDL_QUIT no one reads: the program's own
    // handlers (core/stop_signal) end the window cleanly.
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    silence_alsa();
    if (!options.driver.empty()) SDL_SetHint(SDL_HINT_AUDIODRIVER, options.driver.c_str());
    const bool init_ok = SDL_InitSubSystem(SDL_INIT_AUDIO) == 0;
    if (!options.driver.empty()) SDL_ResetHint(SDL_HINT_AUDIODRIVER);
    if (!init_ok) {
      m.status = options.driver.empty()
                     ? std::string("no sound: SDL found no audio device (") + SDL_GetError() + "); cues are silent"
                     : "no sound: SDL could not start the audio driver '" + options.driver + "' (" +
                           SDL_GetError() + "); cues are silent";
      return;
    }
    m.subsystem = true;
    const char* current = SDL_GetCurrentAudioDriver();
    const std::string driver = current ? current : "?";
    if (!options.driver.empty() && driver != options.driver) {
      m.status = "no sound: the audio driver '" + options.driver + "' was asked for but SDL already runs '" +
                 driver + "'; cues are silent";
      return;
    }
    SDL_AudioSpec want{}, have{};
    want.freq = options.sample_rate > 0 ? options.sample_rate : kAudioSampleRate;
    want.format = AUDIO_F32SYS;
    want.channels = 1;
    want.samples = static_cast<Uint16>(options.buffer_frames >= 64 && options.buffer_frames <= 8192
                                           ? options.buffer_frames
                                           : 512);
    want.callback = &Impl::callback;
    want.userdata = &m;
    m.mixer = CueMixer(want.freq);  // before the device exists: no race with the callback
    // No allowed changes: SDL converts to the device's format, so the callback always sees f32 mono.
    m.device = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);
    if (m.device == 0) {
      m.status = "no sound: SDL's " + driver + " driver could not open an output device (" + SDL_GetError() +
                 "); cues are silent";
      return;
    }
    m.open = true;
    m.status = "sound through SDL2 (" + driver + ", " + std::to_string(want.freq) + " Hz)";
    SDL_PauseAudioDevice(m.device, 0);
  } catch (...) {
    m.status = "no sound: the audio device could not be set up; cues are silent";
  }
#elif defined(__EMSCRIPTEN__)
  (void)options;
  Impl& m = *impl_;
  // clang-format off
  const int rate = EM_ASM_INT({
    const Context = window.AudioContext || window.webkitAudioContext;
    if (!Context) return 0;
    const context = new Context();
    const node = context.createScriptProcessor(1024, 0, 1);
    const block = _malloc(1024 * 4);
    node.onaudioprocess = function(e) {
      const out = e.outputBuffer.getChannelData(0);
      _s4d_audio_fill($0, block, out.length);
      out.set(HEAPF32.subarray(block >> 2, (block >> 2) + out.length));
    };
    node.connect(context.destination);
    // Browsers start sound only after a user's gesture: the first click, key or touch resumes it
    // (a touch counts as one when the finger lifts).
    const resume = function() { if (context.state !== "running") context.resume(); };
    for (const type of ["pointerdown", "pointerup", "keydown", "touchend"]) window.addEventListener(type, resume, true);
    Module.s4dAudio = new Object();
    Module.s4dAudio.context = context;
    Module.s4dAudio.node = node;
    return context.sampleRate;
  }, &m);
  // clang-format on
  if (rate <= 0) {
    m.status = "no sound: this browser has no Web Audio; cues are silent";
    return;
  }
  m.mixer = CueMixer(rate);  // before the first block: Web Audio calls back between frames only
  m.open = true;
  m.status = "sound through Web Audio (" + std::to_string(rate) + " Hz; it starts at the first click, key or touch)";
#else
  (void)options;
  impl_->status = "no sound: this build has no SDL2 (libsdl2-dev was not found); cues are silent";
#endif
}

AudioPlayer::~AudioPlayer() {
#if defined(__EMSCRIPTEN__)
  // clang-format off
  EM_ASM({
    if (!Module.s4dAudio) return;
    Module.s4dAudio.node.onaudioprocess = null;  // it would call into this player's memory
    Module.s4dAudio.context.close();
    Module.s4dAudio = null;
  });
  // clang-format on
#endif
#if defined(S4D_HAVE_SDL2)
  if (!impl_) return;
  if (impl_->device != 0) SDL_CloseAudioDevice(impl_->device);  // joins the audio thread
  if (impl_->subsystem) SDL_QuitSubSystem(SDL_INIT_AUDIO);
#endif
}

bool AudioPlayer::available() const noexcept { return impl_ && impl_->open; }

const std::string& AudioPlayer::status() const noexcept {
  static const std::string kNoMemory = "no sound: out of memory; cues are silent";
  return impl_ ? impl_->status : kNoMemory;
}

void AudioPlayer::play(CueKind kind, float gain) noexcept {
  if (!available()) return;
  std::lock_guard<std::mutex> lock(impl_->pending_mutex);  // the callback holds it for a few copies at most
  if (impl_->pending_count < static_cast<int>(impl_->pending.size()))
    impl_->pending[impl_->pending_count++] = {kind, gain};
  else
    impl_->dropped.fetch_add(1, std::memory_order_relaxed);
}

void AudioPlayer::set_volume(float v) noexcept {
  if (impl_ && std::isfinite(v)) impl_->volume.store(std::clamp(v, 0.0f, 1.0f));
}
float AudioPlayer::volume() const noexcept { return impl_ ? impl_->volume.load() : 0.0f; }
void AudioPlayer::set_mute(bool mute) noexcept {
  if (impl_) impl_->mute.store(mute);
}
bool AudioPlayer::muted() const noexcept { return impl_ && impl_->mute.load(); }
void AudioPlayer::set_depth_tone(bool on) noexcept {
  if (impl_) impl_->tone.store(on);
}
void AudioPlayer::set_depth(double d) noexcept {
  if (impl_ && std::isfinite(d)) impl_->depth.store(std::clamp(d, 0.0, 1.0));
}
std::uint64_t AudioPlayer::cues_started() const noexcept { return impl_ ? impl_->started.load() : 0; }
std::uint64_t AudioPlayer::cues_dropped() const noexcept { return impl_ ? impl_->dropped.load() : 0; }
std::uint64_t AudioPlayer::frames_rendered() const noexcept { return impl_ ? impl_->frames.load() : 0; }

}  // namespace s4d

#if defined(__EMSCRIPTEN__)
// Web Audio's block callback (the constructor's script processor): n mixed samples into out.
extern "C" EMSCRIPTEN_KEEPALIVE void s4d_audio_fill(s4d::AudioPlayer::Impl* impl, float* out, int n) {
  if (impl && out && n > 0) impl->fill(out, static_cast<std::size_t>(n));
}
#endif
