// SpacenavDevice: a 3D mouse (SpaceMouse) through libspnav and the spacenavd daemon. Input only, rate
// control: the cap's deflection sets the stylus velocity, so it drives tools like a slow arm without
// force output. Compiled against libspnav when the build defines S4D_HAVE_SPNAV.
#pragma once
#include <array>

#include "haptics/device.hpp"

namespace s4d {

struct SpacenavConfig {
  double full_speed = 0.1;   // m/s at full deflection
  int full_deflection = 350;  // raw axis value of a fully pushed cap
  int dead_zone = 8;          // raw units ignored around rest (sensor noise)
  Vec3 half_extent = Vec3(0.08, 0.06, 0.035);  // m, workspace box
};

class SpacenavDevice final : public Device {
 public:
  // Connects to spacenavd; throws Error saying why not (no daemon, or built without libspnav).
  explicit SpacenavDevice(const SpacenavConfig& config = {});
  ~SpacenavDevice() override;
  std::string_view name() const override { return "spacenav"; }
  const DeviceCapabilities& capabilities() const override { return caps_; }
  DeviceStatus read(const DeviceInput& in, DeviceState& out) override;
  void write_force(const Vec3&) override {}  // no actuators
  bool reconnect() override;

  // Raw 6-DOF axes last received: x, y, z, rx, ry, rz (the rotations are exposed for view control).
  const std::array<int, 6>& axes() const { return axes_; }
  static bool available_in_build();

 private:
  SpacenavConfig config_;
  DeviceCapabilities caps_;
  std::array<int, 6> axes_{};
  Vec3 position_ = Vec3::Zero();
  std::uint32_t buttons_ = 0;
  [[maybe_unused]] bool open_ = false;  // unused in a build without libspnav (the web page)
};

}  // namespace s4d
