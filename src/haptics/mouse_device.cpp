// The mouse proxy: backward Euler on the coupling spring (stable for any stiffness and step), the scene
// force explicit, the proxy kept inside the workspace box.
#include "haptics/mouse_device.hpp"

namespace s4d {

MouseDevice::MouseDevice(const MouseProxyConfig& config) : config_(config) {
  caps_.workspace_min = -config.half_extent;
  caps_.workspace_max = config.half_extent;
  // The proxy "feels" forces like an arm would, with generous limits: nothing physical can be hurt,
  // but the same safety layer keeps the proxy motion free of jolts.
  caps_.max_force = 5;
  caps_.max_continuous_force = 5;
  caps_.max_stiffness = 2000;
  caps_.max_force_rate = 2000;
  caps_.outputs_force = true;
  caps_.nominal_rate = 1000;
}

DeviceStatus MouseDevice::read(const DeviceInput& in, DeviceState& out) {
  if (in.pointer_valid) {
    target_ = caps_.clamp(in.pointer_target);
    buttons_ = in.pointer_buttons;
  }
  const double m = config_.mass, k = config_.coupling.k, b = config_.coupling.b, dt = in.dt;
  // m (v1 - v0)/dt = k (target - x0 - dt v1) - b v1 + F  =>  solve for v1.
  const Vec3 v1 = (m * v_ + dt * (k * (target_ - x_) + force_)) / (m + dt * b + dt * dt * k);
  Vec3 x1 = x_ + dt * v1;
  v_ = v1;
  for (int i = 0; i < 3; ++i) {  // the box walls stop the proxy
    if (x1[i] < caps_.workspace_min[i] || x1[i] > caps_.workspace_max[i]) v_[i] = 0;
  }
  x_ = caps_.clamp(x1);
  out.position = x_;
  out.velocity = v_;
  out.target = target_;
  out.buttons = buttons_;
  return DeviceStatus::ok;
}

}  // namespace s4d
