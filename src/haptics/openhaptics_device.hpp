// OpenHapticsDevice: a thin adapter from the PHANToM Omni / Touch (OpenHaptics HDAPI) to Device. Built
// only when CMake finds HD/hd.h and libHD (S4D_HAVE_OPENHAPTICS); otherwise constructing it throws.
#pragma once
#include <memory>

#include "haptics/device.hpp"

namespace s4d {

class OpenHapticsDevice final : public Device {
 public:
  // Initialises the default HD device and starts its servo scheduler; throws Error on failure.
  OpenHapticsDevice();
  ~OpenHapticsDevice() override;
  std::string_view name() const override { return "openhaptics"; }
  const DeviceCapabilities& capabilities() const override { return caps_; }
  DeviceStatus read(const DeviceInput& in, DeviceState& out) override;
  void write_force(const Vec3& force) override;
  bool reconnect() override;
  static bool available_in_build();

  struct Impl;  // HDAPI state, hidden so this header needs no HD/hd.h

 private:
  DeviceCapabilities caps_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace s4d
