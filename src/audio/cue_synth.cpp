// The cue sounds as closed-form functions of the sample index, the voice mixer, and the offline
// renderer (see cue_synth.hpp for the sounds chosen and why).
#include "audio/cue_synth.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace s4d {

namespace {

constexpr double kTwoPi = 6.283185307179586;

// Ping (over / above): two notes, each with a 2 ms attack, a 40 ms decay and a 5 ms fade at its end.
constexpr double kPingSplit = 0.070, kPingEnd = 0.180;  // s
constexpr double kPingF1 = 1318.51, kPingF2 = 1760.0;  // Hz, E6 and A6
// Thud (under / below): one gliding note, soft 8 ms attack, 70 ms decay, 10 ms fade.
constexpr double kThudEnd = 0.220;                     // s
constexpr double kThudF0 = 196.0, kThudF1 = 146.83;    // Hz, G3 to D3
// Grab / release chirps.
constexpr double kChirpEnd = 0.050;                    // s
constexpr double kChirpLow = 500.0, kChirpHigh = 1000.0;  // Hz
constexpr double kToneLevel = 0.12;  // depth tone amplitude, below the cues'

double ramp(double x) { return std::clamp(x, 0.0, 1.0); }

// Phase (radians) at time t of a tone gliding linearly from f0 to f1 over `length` s.
double glide_phase(double t, double f0, double f1, double length) {
  return kTwoPi * (f0 * t + (f1 - f0) * t * t / (2 * length));
}

double ping_note(double local, double f, double length) {
  const double env = ramp(local / 0.002) * std::exp(-local / 0.040) * ramp((length - local) / 0.005);
  const double x = kTwoPi * f * local;
  return env * (std::sin(x) + 0.3 * std::sin(2 * x)) / 1.3;
}

}  // namespace

std::string_view cue_name(CueKind kind) {
  switch (kind) {
    case CueKind::crossing_over: return "over";
    case CueKind::crossing_under: return "under";
    case CueKind::curve_above: return "above";
    case CueKind::curve_below: return "below";
    case CueKind::grab: return "grab";
    case CueKind::release: return "release";
  }
  return "?";
}

double cue_duration(CueKind kind) {
  switch (kind) {
    case CueKind::crossing_over:
    case CueKind::curve_above: return kPingEnd;
    case CueKind::crossing_under:
    case CueKind::curve_below: return kThudEnd;
    case CueKind::grab:
    case CueKind::release: return kChirpEnd;
  }
  return 0;
}

float cue_sample(CueKind kind, std::int64_t n, int rate) {
  if (n < 0 || rate <= 0) return 0;
  const double t = static_cast<double>(n) / rate;
  if (!(t < cue_duration(kind))) return 0;
  double v = 0;
  switch (kind) {
    case CueKind::crossing_over:
    case CueKind::curve_above:
      v = t < kPingSplit ? ping_note(t, kPingF1, kPingSplit)
                         : ping_note(t - kPingSplit, kPingF2, kPingEnd - kPingSplit);
      v *= 0.45;
      break;
    case CueKind::crossing_under:
    case CueKind::curve_below: {
      const double a = std::sin(0.5 * 3.141592653589793 * ramp(t / 0.008));  // smooth, soft onset
      const double env = a * a * std::exp(-t / 0.070) * ramp((kThudEnd - t) / 0.010);
      v = 0.5 * env * std::sin(glide_phase(t, kThudF0, kThudF1, kThudEnd));
      break;
    }
    case CueKind::grab:
    case CueKind::release: {
      const bool up = kind == CueKind::grab;
      const double env = std::sin(3.141592653589793 * t / kChirpEnd);
      v = 0.3 * env *
          std::sin(glide_phase(t, up ? kChirpLow : kChirpHigh, up ? kChirpHigh : kChirpLow, kChirpEnd));
      break;
    }
  }
  return static_cast<float>(v);
}

double depth_tone_frequency(double depth) {
  const double d = std::isfinite(depth) ? std::clamp(depth, 0.0, 1.0) : 0.5;
  return 220.0 * std::exp2(2 * d);  // two octaves: equal depth steps sound like equal pitch steps
}

CueMixer::CueMixer(int sample_rate) : rate_(sample_rate > 0 ? sample_rate : kAudioSampleRate) {}

void CueMixer::start(CueKind kind, float gain) {
  Voice* slot = &voices_[0];
  for (Voice& v : voices_) {
    if (v.n < 0) {
      slot = &v;
      break;
    }
    if (v.order < slot->order) slot = &v;  // all busy: the oldest gives way
  }
  slot->kind = kind;
  slot->n = 0;
  slot->length = static_cast<std::int64_t>(std::ceil(cue_duration(kind) * rate_));
  slot->gain = std::isfinite(gain) ? std::clamp(gain, 0.0f, 1.0f) : 1.0f;
  slot->order = ++started_;
}

void CueMixer::set_volume(float v) {
  if (std::isfinite(v)) volume_ = std::clamp(v, 0.0f, 1.0f);
}

void CueMixer::set_depth(double depth) {
  if (std::isfinite(depth)) depth_ = std::clamp(depth, 0.0, 1.0);
}

int CueMixer::active_voices() const {
  int n = 0;
  for (const Voice& v : voices_) n += v.n >= 0;
  return n;
}

void CueMixer::mix(std::span<float> out) {
  // One-pole glides: 15 ms for the tone's pitch, 10 ms for its level.
  const double a_freq = 1 - std::exp(-1.0 / (0.015 * rate_));
  const double a_level = 1 - std::exp(-1.0 / (0.010 * rate_));
  const double target_freq = depth_tone_frequency(depth_);
  if (tone_freq_ <= 0) tone_freq_ = target_freq;
  const double target_level = tone_on_ ? kToneLevel : 0.0;
  for (float& o : out) {
    float s = 0;
    for (Voice& v : voices_) {
      if (v.n < 0) continue;
      s += v.gain * cue_sample(v.kind, v.n, rate_);
      if (++v.n >= v.length) v.n = -1;
    }
    if (tone_level_ > 1e-6 || tone_on_) {
      tone_freq_ += a_freq * (target_freq - tone_freq_);
      tone_level_ += a_level * (target_level - tone_level_);
      tone_phase_ = std::fmod(tone_phase_ + kTwoPi * tone_freq_ / rate_, kTwoPi);
      s += static_cast<float>(tone_level_ * std::sin(tone_phase_));
    }
    o = mute_ ? 0.0f : std::clamp(volume_ * s, -1.0f, 1.0f);
  }
}

std::vector<float> render_cues(std::span<const CueEvent> cues, std::span<const DepthSample> depth,
                               double duration, const SynthSettings& settings) {
  const int rate = settings.sample_rate;
  if (rate < 8000 || rate > 192000)
    throw Error("sample rate " + std::to_string(rate) + " Hz is out of range [8000, 192000]");
  if (!std::isfinite(settings.volume) || settings.volume < 0 || settings.volume > 1)
    throw Error("volume must be in [0, 1]");
  if (!std::isfinite(duration)) throw Error("the rendering's duration must be finite");
  std::vector<CueEvent> sorted(cues.begin(), cues.end());
  std::vector<DepthSample> track(depth.begin(), depth.end());
  double end = duration;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (!std::isfinite(sorted[i].time) || sorted[i].time < 0)
      throw Error("cue " + std::to_string(i) + " is at time " + std::to_string(sorted[i].time) +
                  " s; cue times must be finite and >= 0");
    if (duration <= 0) end = std::max(end, sorted[i].time + cue_duration(sorted[i].kind));
  }
  for (std::size_t i = 0; i < track.size(); ++i)
    if (!std::isfinite(track[i].time) || track[i].time < 0 || !std::isfinite(track[i].depth))
      throw Error("depth sample " + std::to_string(i) + " must have a finite time >= 0 and a finite depth");
  constexpr double kMaxSeconds = 3600;
  if (end > kMaxSeconds)
    throw Error("the rendering would last " + std::to_string(end) + " s; at most 3600 s are rendered");
  const auto onset = [rate](double t) { return static_cast<std::int64_t>(std::llround(t * rate)); };
  std::stable_sort(sorted.begin(), sorted.end(), [](const CueEvent& a, const CueEvent& b) { return a.time < b.time; });
  std::stable_sort(track.begin(), track.end(),
                   [](const DepthSample& a, const DepthSample& b) { return a.time < b.time; });

  const std::int64_t total = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::ceil(end * rate)));
  std::vector<float> out(static_cast<std::size_t>(total), 0.0f);
  CueMixer mixer(rate);
  mixer.set_volume(settings.volume);
  mixer.set_mute(settings.mute);
  mixer.set_depth_tone(settings.depth_tone);
  if (!track.empty()) mixer.set_depth(track.front().depth);
  std::size_t ci = 0, di = 0;
  std::int64_t n = 0;
  while (n < total) {
    while (ci < sorted.size() && onset(sorted[ci].time) <= n) {
      mixer.start(sorted[ci].kind, sorted[ci].gain);
      ++ci;
    }
    while (di < track.size() && onset(track[di].time) <= n) mixer.set_depth(track[di++].depth);
    std::int64_t next = total;
    if (ci < sorted.size()) next = std::min(next, onset(sorted[ci].time));
    if (di < track.size()) next = std::min(next, onset(track[di].time));
    mixer.mix(std::span<float>(out.data() + n, static_cast<std::size_t>(next - n)));
    n = next;
  }
  return out;
}

}  // namespace s4d
