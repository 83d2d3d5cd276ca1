// MouseDevice: the no-arm path. The GUI pointer (cursor plus wheel for depth) sets a target; a virtual
// proxy mass follows it through a virtual-coupling spring and is pushed by the scene's force, so the
// tools behave as with an arm and the force shows as the proxy's lag behind the cursor.
#pragma once
#include "haptics/device.hpp"
#include "haptics/force_models.hpp"

namespace s4d {

struct MouseProxyConfig {
  double mass = 0.05;       // kg, virtual proxy mass
  DampedSpring coupling{300, 6};  // N/m and N s/m between the cursor target and the proxy (about critical)
  Vec3 half_extent = Vec3(0.08, 0.06, 0.035);  // m, the Omni-sized box the cursor maps into
};

class MouseDevice final : public Device {
 public:
  explicit MouseDevice(const MouseProxyConfig& config = {});
  std::string_view name() const override { return "mouse"; }
  const DeviceCapabilities& capabilities() const override { return caps_; }
  DeviceStatus read(const DeviceInput& in, DeviceState& out) override;
  void write_force(const Vec3& force) override { force_ = force; }

  const Vec3& proxy_position() const { return x_; }

 private:
  MouseProxyConfig config_;
  DeviceCapabilities caps_;
  Vec3 x_ = Vec3::Zero(), v_ = Vec3::Zero();  // m, m/s: proxy state
  Vec3 target_ = Vec3::Zero();                // m, last cursor target
  Vec3 force_ = Vec3::Zero();                 // N, scene force on the proxy
  std::uint32_t buttons_ = 0;
};

}  // namespace s4d
