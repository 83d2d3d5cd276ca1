// StickyPlaneScene: the paper's 2D/3D sketching contact (4.1) without a simulation: the stylus is held
// on the shadow plane by Eq. 1 plus the radial damping of Eq. 2, and glides freely along it.
#pragma once
#include <array>

#include "haptics/haptic_scene.hpp"

namespace s4d {

class StickyPlaneScene final : public HapticScene {
 public:
  enum Param { kH, kBeta, kKd, kParamCount };

  // The plane passes through `origin` with unit normal `normal` (device coordinates, m).
  explicit StickyPlaneScene(const Vec3& origin = Vec3::Zero(), const Vec3& normal = Vec3::UnitZ());

  std::string_view name() const override { return "sticky-plane"; }
  ToolOutput step(const DeviceState& device, double dt) override;
  void reset() override {}
  std::span<SceneParam> params() override { return params_; }

  const Vec3& origin() const { return origin_; }
  const Vec3& normal() const { return normal_; }

 private:
  Vec3 origin_, normal_;
  std::array<SceneParam, kParamCount> params_;
};

}  // namespace s4d
