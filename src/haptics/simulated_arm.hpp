// SimulatedArm: a device model with the PHANToM Omni's published limits (3.3 N peak, 0.88 N continuous,
// about 1 N/mm, 160 x 120 x 70 mm) held by a model hand (spring-damper to where the user aims). Tests
// use it to check stability; the UI offers it as the "simulated device".
#pragma once
#include <atomic>
#include <functional>

#include "haptics/device.hpp"

namespace s4d {

struct SimulatedArmConfig {
  double effector_mass = 0.045;   // kg, apparent mass of the stylus tip
  double hand_mass = 0.1;         // kg, fingers and wrist lumped with the stylus (firm grasp)
  double device_damping = 0.01;   // N s/m, joint friction seen at the tip
  double hand_stiffness = 300;    // N/m, grasp stiffness (about 100-1000 for a relaxed-to-firm grip)
  double hand_damping = 2.0;      // N s/m
  double encoder_step = 5.5e-5;   // m, position resolution (Omni: > 450 dpi)
  double velocity_cutoff = 200;   // Hz, low-pass on the differentiated encoder position
  double thermal_time = 5.0;      // s, time constant of the motor heating estimate
  double wall_stiffness = 5000;   // N/m, mechanical end stops at the workspace box
  int substeps = 10;              // integration steps per servo tick (zero-order-hold motor force)
};

class SimulatedArm final : public Device {
 public:
  explicit SimulatedArm(const SimulatedArmConfig& config = {});
  std::string_view name() const override { return "sim"; }
  const DeviceCapabilities& capabilities() const override { return caps_; }
  DeviceStatus read(const DeviceInput& in, DeviceState& out) override;
  void write_force(const Vec3& force) override;
  bool reconnect() override { return connected_.load(std::memory_order_relaxed); }

  // Where the hand aims as a function of time (s); without one it follows the GUI pointer, or stays
  // where it is. Set before the loop starts.
  void set_hand_script(std::function<Vec3(double)> script) { script_ = std::move(script); }
  // Fault injection (any thread): unplug / replug the simulated cable.
  void set_connected(bool c) { connected_.store(c, std::memory_order_relaxed); }
  void set_position(const Vec3& p);  // places the stylus (at rest) and the hand there

  // Ground truth for tests (not what the loop sees: that is quantised and filtered).
  const Vec3& true_position() const { return x_; }
  const Vec3& true_velocity() const { return v_; }
  const Vec3& hand_target() const { return hand_; }
  const Vec3& motor_force() const { return motor_; }  // N, after the device's own saturation
  double time() const { return t_; }
  double mechanical_energy() const;  // J: kinetic + hand spring
  bool thermally_limited() const { return thermal_limited_; }

 private:
  SimulatedArmConfig config_;
  DeviceCapabilities caps_;
  std::function<Vec3(double)> script_;
  std::atomic<bool> connected_{true};
  Vec3 x_ = Vec3::Zero(), v_ = Vec3::Zero();        // m, m/s: stylus tip
  Vec3 hand_ = Vec3::Zero(), hand_v_ = Vec3::Zero();  // m, m/s: where the hand aims
  Vec3 motor_ = Vec3::Zero();                       // N, force the motors produce
  Vec3 sensed_x_ = Vec3::Zero(), sensed_v_ = Vec3::Zero();
  double heat_ = 0;  // N^2, low-passed squared force
  double t_ = 0;     // s
  bool thermal_limited_ = false;
  bool first_read_ = true;
};

}  // namespace s4d
