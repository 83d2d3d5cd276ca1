// AudioPlayer: plays cues live through SDL2 (an audio callback mixing with the same CueMixer the WAV
// renderer uses). Never blocks or throws into the caller: without a device (CI, SSH, a build without
// SDL2) it stays silent and says why in status(), and the app carries on.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "audio/cue_synth.hpp"

namespace s4d {

struct AudioPlayerOptions {
  std::string driver;                  // SDL audio driver ("pulseaudio", "alsa", "dummy"); empty: SDL's choice
  int sample_rate = kAudioSampleRate;  // Hz asked of the device; SDL converts if it differs
  int buffer_frames = 512;             // callback size: about 12 ms at 44.1 kHz
};

class AudioPlayer {
 public:
  explicit AudioPlayer(const AudioPlayerOptions& options = {}) noexcept;
  ~AudioPlayer();
  AudioPlayer(const AudioPlayer&) = delete;
  AudioPlayer& operator=(const AudioPlayer&) = delete;

  // True when a device is open and cues are heard.
  bool available() const noexcept;
  // One sentence: "sound through SDL2 (pulseaudio, 44100 Hz)" or why there is none.
  const std::string& status() const noexcept;

  // Any thread (the UI's, typically). A cue starts at the next audio callback; when the small queue of
  // pending cues is full (64 within one callback) the cue is dropped and counted. No-op when silent.
  void play(CueKind kind, float gain = 1) noexcept;
  void set_volume(float volume) noexcept;  // [0, 1], clamped; NaN ignored
  float volume() const noexcept;
  void set_mute(bool mute) noexcept;
  bool muted() const noexcept;
  void set_depth_tone(bool on) noexcept;   // the continuous pitch-follows-depth tone (off by default)
  void set_depth(double depth) noexcept;   // [0, 1], clamped; NaN ignored

  // What the audio thread has done (tests, the status panel).
  std::uint64_t cues_started() const noexcept;
  std::uint64_t cues_dropped() const noexcept;
  std::uint64_t frames_rendered() const noexcept;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace s4d
