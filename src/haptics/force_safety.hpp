// ForceSafety::apply, the one function every force passes through on its way to a device: it rejects
// non-finite values, clamps magnitude and rate of change, fades in at start and fades out on missed
// deadlines, resets and disconnects.
#pragma once
#include <cstdint>

#include "core/vec.hpp"
#include "haptics/device.hpp"

namespace s4d {

struct SafetyConfig {
  double max_force = 3.3;         // N, never exceeded
  double max_rate = 1000;         // N/s, largest change of output per second (no kicks)
  double fade_in_time = 0.5;      // s, from zero to full force once enabled
  double fade_out_time = 0.05;    // s, from full force to zero on trouble
  double enable_threshold = 0.3;  // N, forces are enabled only once the requested force is this small
  double miss_hold_time = 0.2;    // s, force stays faded out this long after the last missed deadline
  // Limits taken from the device; a device that outputs no force gets max_force = 0.
  static SafetyConfig for_device(const DeviceCapabilities& caps);
};

// What happened this tick, as seen by the loop.
struct SafetyEvents {
  bool deadline_missed = false;  // the previous tick overran its deadline
  bool scene_reset = false;      // the simulation was reset: the force may jump
  bool device_connected = true;  // false: the device vanished, nothing may be sent
};

enum class SafetyPhase : std::uint8_t {
  waiting,     // disarmed: output zero until the requested force is small
  fading_in,   // armed, ramping up
  active,      // full force
  fading_out,  // ramping down after a missed deadline, reset or bad value
};
const char* safety_phase_name(SafetyPhase p);

// Counted, never thrown: the loop must not stop on bad numbers (see STYLE.md, MuJoCo's warnings).
struct SafetyCounters {
  std::uint64_t nonfinite = 0;     // requests with NaN or inf, replaced by zero
  std::uint64_t clamped = 0;       // requests above max_force
  std::uint64_t rate_limited = 0;  // ticks where the change of output was limited
  std::uint64_t disarms = 0;       // resets, bad values and disconnects that forced a fresh fade-in
};

class ForceSafety {
 public:
  explicit ForceSafety(const SafetyConfig& config = {}) : config_(config) {}

  // The one function: the safe force (N) to write this tick for the `requested` one. dt in s.
  Vec3 apply(const Vec3& requested, const SafetyEvents& events, double dt);

  // New limits (another device); the output restarts from zero with a fade-in.
  void set_config(const SafetyConfig& config);
  const SafetyConfig& config() const { return config_; }
  double gain() const { return gain_; }  // 0..1, the fade factor
  SafetyPhase phase() const;
  const SafetyCounters& counters() const { return counters_; }
  const Vec3& last_output() const { return last_; }

 private:
  void disarm();

  SafetyConfig config_;
  SafetyCounters counters_;
  Vec3 last_ = Vec3::Zero();  // N, what was sent last tick
  double gain_ = 0;
  double miss_hold_ = 0;      // s left before a missed deadline stops holding the force down
  bool armed_ = false;
};

}  // namespace s4d
