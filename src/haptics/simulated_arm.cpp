// The simulated Omni: motor saturation and thermal derating, a hand spring-damper, end stops, encoder
// quantisation and a filtered velocity estimate, integrated with semi-implicit Euler substeps.
#include "haptics/simulated_arm.hpp"

#include <algorithm>
#include <cmath>

namespace s4d {

SimulatedArm::SimulatedArm(const SimulatedArmConfig& config) : config_(config) {
  caps_.workspace_min = -Vec3(0.080, 0.060, 0.035);  // m: 160 x 120 x 70 mm
  caps_.workspace_max = Vec3(0.080, 0.060, 0.035);
  caps_.max_force = 3.3;              // N
  caps_.max_continuous_force = 0.88;  // N
  caps_.max_stiffness = 1000;         // N/m (about 1 N/mm)
  caps_.max_force_rate = 1000;        // N/s
  caps_.outputs_force = true;
  caps_.nominal_rate = 1000;
}

void SimulatedArm::set_position(const Vec3& p) {
  x_ = hand_ = sensed_x_ = caps_.clamp(p);
  v_.setZero();
  hand_v_.setZero();
  sensed_v_.setZero();
  first_read_ = true;
}

double SimulatedArm::mechanical_energy() const {
  const double m = config_.effector_mass + config_.hand_mass;
  return 0.5 * m * v_.squaredNorm() + 0.5 * config_.hand_stiffness * (hand_ - x_).squaredNorm();
}

void SimulatedArm::write_force(const Vec3& force) {
  Vec3 f = force.allFinite() ? force : Vec3::Zero();
  const double n = f.norm();
  if (n > caps_.max_force) f *= caps_.max_force / n;  // amplifier saturation
  // Thermal protection: while the low-passed RMS force is above the continuous rating, the output is
  // held to that rating, so the RMS settles at it (the Omni's firmware protects its motors likewise).
  thermal_limited_ = std::sqrt(heat_) > caps_.max_continuous_force;
  const double m = f.norm();
  if (thermal_limited_ && m > caps_.max_continuous_force) f *= caps_.max_continuous_force / m;
  motor_ = f;
}

DeviceStatus SimulatedArm::read(const DeviceInput& in, DeviceState& out) {
  const double dt = in.dt;
  // Where the hand aims this tick; its velocity feeds the hand damper.
  Vec3 aim = hand_;
  if (script_) {
    aim = script_(t_ + dt);
  } else if (in.pointer_valid) {
    aim = in.pointer_target;
  }
  hand_v_ = dt > 0 ? Vec3((aim - hand_) / dt) : Vec3::Zero();
  hand_ = aim;

  // The stylus keeps moving whether or not the cable is plugged in; only the motors stop.
  const bool connected = connected_.load(std::memory_order_relaxed);
  if (!connected) motor_.setZero();
  const double m = config_.effector_mass + config_.hand_mass;
  const int n = std::max(1, config_.substeps);
  const double h = dt / n;
  for (int s = 0; s < n; ++s) {
    Vec3 f = motor_ + config_.hand_stiffness * (hand_ - x_) + config_.hand_damping * (hand_v_ - v_) -
             config_.device_damping * v_;
    for (int i = 0; i < 3; ++i) {  // end stops
      if (x_[i] < caps_.workspace_min[i]) f[i] += config_.wall_stiffness * (caps_.workspace_min[i] - x_[i]);
      if (x_[i] > caps_.workspace_max[i]) f[i] += config_.wall_stiffness * (caps_.workspace_max[i] - x_[i]);
    }
    v_ += (h / m) * f;
    x_ += h * v_;
  }
  const double a = dt / config_.thermal_time;
  heat_ += std::min(1.0, a) * (motor_.squaredNorm() - heat_);
  t_ += dt;
  if (!connected) return DeviceStatus::disconnected;

  // What the encoders report: quantised position, velocity by filtered differences.
  const double q = config_.encoder_step;
  Vec3 sensed = q > 0 ? Vec3((x_ / q).array().round() * q) : x_;
  if (first_read_) {
    sensed_x_ = sensed;
    first_read_ = false;
  }
  const Vec3 raw_v = dt > 0 ? Vec3((sensed - sensed_x_) / dt) : Vec3::Zero();
  const double alpha = 1.0 - std::exp(-2.0 * M_PI * config_.velocity_cutoff * dt);
  sensed_v_ += alpha * (raw_v - sensed_v_);
  sensed_x_ = sensed;
  out.position = sensed_x_;
  out.velocity = sensed_v_;
  out.target = hand_;
  out.buttons = in.pointer_valid ? in.pointer_buttons : 0;
  return DeviceStatus::ok;
}

}  // namespace s4d
