// Sound cues of the paper's auditory feedback (4.3.2): the kinds both studios emit, the pure
// synthesiser that turns timed cues (and a depth track) into mono PCM, and the voice mixer that the
// offline renderer and the live player share, so a WAV holds exactly what the speakers play.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace s4d {

inline constexpr int kAudioSampleRate = 44100;  // Hz

// What happened. Over/above and under/below share a sound each (one studio runs at a time and the
// meaning is the same: "the strand/sheet you follow is the one on top"):
//  - over / above: a bright, high, rising two-note ping, E6 then A6 (1318.5 Hz, 1760 Hz), sine plus
//    a second harmonic, sharp attack, 180 ms;
//  - under / below: a low, dull, falling thud, G3 gliding to D3 (196 Hz to 147 Hz), pure sine with a
//    soft attack, 220 ms.
// Three octaves apart and opposite in contour and timbre, they are told apart without looking.
//  - grab: a short rising chirp (500 to 1000 Hz, 50 ms); release: the same falling.
// A continuous tone whose pitch follows a depth in [0, 1] (220 Hz at 0 to 880 Hz at 1) can be
// added; it is off unless asked for.
enum class CueKind : std::uint8_t { crossing_over, crossing_under, curve_above, curve_below, grab, release };
inline constexpr int kCueKindCount = 6;

// "over", "under", "above", "below", "grab", "release".
std::string_view cue_name(CueKind kind);

// The cue's length in seconds (its samples beyond are zero).
double cue_duration(CueKind kind);

// Sample n (0 = onset) of a cue at `rate` Hz, before volume: in [-0.5, 0.5], zero outside the cue.
// A pure function, so a voice is just (kind, n, gain).
float cue_sample(CueKind kind, std::int64_t n, int rate = kAudioSampleRate);

// The depth tone's frequency (Hz) for a depth in [0, 1] (clamped).
double depth_tone_frequency(double depth);

// Mixes the cues that are sounding and the optional depth tone. Not thread-safe: the player owns
// one on its audio thread; the offline renderer another. No allocation after construction.
class CueMixer {
 public:
  static constexpr int kMaxVoices = 16;  // a 17th cue replaces the oldest

  explicit CueMixer(int sample_rate = kAudioSampleRate);

  void start(CueKind kind, float gain = 1);  // gain in [0, 1], clamped; NaN plays at 1
  void set_volume(float v);                  // [0, 1], clamped; NaN ignored
  void set_mute(bool m) { mute_ = m; }       // muted: zeros out, voices still advance
  void set_depth_tone(bool on) { tone_on_ = on; }
  void set_depth(double depth);              // [0, 1], clamped; NaN ignored
  // Overwrites `out` with the next out.size() samples.
  void mix(std::span<float> out);

  int sample_rate() const { return rate_; }
  int active_voices() const;
  float volume() const { return volume_; }
  bool muted() const { return mute_; }

 private:
  struct Voice {
    CueKind kind = CueKind::grab;
    std::int64_t n = -1;  // samples since onset; < 0: free
    std::int64_t length = 0;
    float gain = 1;
    std::uint64_t order = 0;  // start order, to replace the oldest
  };
  int rate_;
  std::array<Voice, kMaxVoices> voices_{};
  std::uint64_t started_ = 0;
  float volume_ = 0.8f;
  bool mute_ = false;
  bool tone_on_ = false;
  double depth_ = 0.5;
  double tone_freq_ = 0;    // Hz, glides towards the depth's frequency
  double tone_phase_ = 0;   // radians
  double tone_level_ = 0;   // fades in and out so switching the tone does not click
};

// One cue at a time in seconds from the start of the rendering.
struct CueEvent {
  double time = 0;  // s
  CueKind kind = CueKind::curve_above;
  float gain = 1;
};

// The depth the tone follows from `time` on (until the next sample).
struct DepthSample {
  double time = 0;  // s
  double depth = 0.5;
};

struct SynthSettings {
  int sample_rate = kAudioSampleRate;  // Hz, in [8000, 192000]
  float volume = 0.8f;                 // [0, 1]
  bool mute = false;
  bool depth_tone = false;             // play the depth track as a tone
};

// Renders the cues (any order) and the depth track into mono samples in [-1, 1]; cue i begins at
// sample round(time_i * rate). `duration` (s) sets the length; <= 0 ends with the last cue. Throws
// Error for a non-finite or negative time, a non-finite depth, or settings out of range.
std::vector<float> render_cues(std::span<const CueEvent> cues, std::span<const DepthSample> depth,
                               double duration, const SynthSettings& settings = {});

}  // namespace s4d
