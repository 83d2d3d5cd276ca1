// The force safety layer: one ordered pipeline (reject, clamp, fade, rate-limit) run once per tick.
#include "haptics/force_safety.hpp"

#include <algorithm>

namespace s4d {

SafetyConfig SafetyConfig::for_device(const DeviceCapabilities& caps) {
  SafetyConfig c;
  c.max_force = caps.outputs_force ? caps.max_force : 0.0;
  if (caps.max_force_rate > 0) c.max_rate = caps.max_force_rate;
  c.enable_threshold = std::min(c.enable_threshold, 0.25 * c.max_force);
  return c;
}

const char* safety_phase_name(SafetyPhase p) {
  switch (p) {
    case SafetyPhase::waiting: return "waiting for a small force";
    case SafetyPhase::fading_in: return "fading in";
    case SafetyPhase::active: return "active";
    case SafetyPhase::fading_out: return "fading out";
  }
  return "?";
}

void ForceSafety::set_config(const SafetyConfig& config) {
  config_ = config;
  disarm();
  gain_ = 0;
  last_.setZero();
}

void ForceSafety::disarm() {
  if (armed_) ++counters_.disarms;
  armed_ = false;
}

SafetyPhase ForceSafety::phase() const {
  if (!armed_) return gain_ > 0 ? SafetyPhase::fading_out : SafetyPhase::waiting;
  if (miss_hold_ > 0) return SafetyPhase::fading_out;
  return gain_ >= 1 ? SafetyPhase::active : SafetyPhase::fading_in;
}

Vec3 ForceSafety::apply(const Vec3& requested, const SafetyEvents& events, double dt) {
  if (!(dt > 0) || !std::isfinite(dt)) dt = 0;

  // 1. The device is gone: nothing can be felt, and when it comes back the hand may be anywhere.
  if (!events.device_connected) {
    disarm();
    gain_ = 0;
    miss_hold_ = 0;
    last_.setZero();
    return last_;
  }

  // 2. Reject non-finite requests; a NaN means the simulation broke, so start over from zero.
  Vec3 f = requested;
  if (!f.allFinite()) {
    ++counters_.nonfinite;
    f.setZero();
    disarm();
  }
  if (events.scene_reset) disarm();
  if (events.deadline_missed) miss_hold_ = config_.miss_hold_time;

  // 3. Magnitude clamp to the device's peak force.
  const double mag = f.norm();
  if (mag > config_.max_force) {
    ++counters_.clamped;
    f *= mag > 0 ? config_.max_force / mag : 0.0;
  }

  // 4. Fade: re-arm only once disarmed output is zero and the request is small (no jolt on enable).
  if (!armed_ && gain_ <= 0 && f.norm() <= config_.enable_threshold) armed_ = true;
  const bool hold_down = !armed_ || miss_hold_ > 0;
  if (hold_down) {
    gain_ = config_.fade_out_time > 0 ? std::max(0.0, gain_ - dt / config_.fade_out_time) : 0.0;
  } else {
    gain_ = config_.fade_in_time > 0 ? std::min(1.0, gain_ + dt / config_.fade_in_time) : 1.0;
  }
  miss_hold_ = std::max(0.0, miss_hold_ - dt);
  Vec3 out = gain_ * f;

  // 5. Rate limit relative to what was sent last tick. Both ends lie in the max_force ball, so the
  // limited point does too.
  const Vec3 delta = out - last_;
  const double step = delta.norm(), max_step = config_.max_rate * dt;
  if (step > max_step) {
    ++counters_.rate_limited;
    out = last_ + delta * (max_step / step);
  }
  last_ = out;
  return out;
}

}  // namespace s4d
