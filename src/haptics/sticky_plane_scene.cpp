// The sticky shadow plane: Eq. 1 towards the projection C', Eq. 2 on the velocity along the normal.
#include "haptics/sticky_plane_scene.hpp"

#include "haptics/force_models.hpp"

namespace s4d {

StickyPlaneScene::StickyPlaneScene(const Vec3& origin, const Vec3& normal)
    : origin_(origin), normal_(normal.normalized()) {
  params_[kH] = {"H", 500, 0, 10000, "N/m^(1+beta)"};
  params_[kBeta] = {"beta", 0, 0, 1, ""};
  params_[kKd] = {"Kd", 1.0, 0, 10, "N s/m"};
}

ToolOutput StickyPlaneScene::step(const DeviceState& device, double dt) {
  ToolOutput out;
  const Vec3 c = device.position;
  out.anchor = project_on_plane<3>(c, origin_, normal_);
  out.force = sticky_force<3>(c, out.anchor, params_[kH].value, params_[kBeta].value) +
              damping_force<3>(radial_velocity<3>(device.velocity, normal_), params_[kKd].value);
  out.engaged = true;
  return out;
}

}  // namespace s4d
