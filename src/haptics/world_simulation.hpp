// WorldSimulation<D>: the physics World<D> (3D or 4D mass-spring cloth) seen by the rubber band in the
// device's 3D space: vertices are projected with the view frame and scaled into the workspace, and the
// 3D tool force is lifted back into the shadow subspace of R^D (the paper's 5.1.3 "external force").
#pragma once
#include <vector>

#include "core/frame.hpp"
#include "haptics/rubber_band_scene.hpp"
#include "physics/world.hpp"

namespace s4d {

template <int D>
class WorldSimulation final : public GrabbableSimulation {
  static_assert(D == 3 || D == 4, "the device space holds shadows of R^3 and R^4 only");

 public:
  // device = offset + scale * shadow(world); forces scale by the same factor (power is preserved:
  // F_dev . v_dev = (scale F_dev) . v_world).
  WorldSimulation(World<D> world, const Frame<D>& frame, double scale, const Vec3& offset = Vec3::Zero());

  int vertex_count() const override { return world_.vertex_count(); }
  Vec3 shadow_position(int v) const override {
    return offset_ + scale_ * lift(frame_.shadow(world_.positions()[v]));
  }
  Vec3 shadow_velocity(int v) const override { return scale_ * lift(frame_.shadow(world_.velocities()[v])); }
  void set_external_force(int v, const Vec3& f) override;
  void step(double dt) override { world_.step(dt); }
  void reset() override;
  int point_dimension() const override { return D; }
  void copy_points(std::span<double> out) const override;

  const World<D>& world() const { return world_; }
  World<D>& world() { return world_; }

 private:
  // Shadow coordinates (D-1 of them) padded to the device's three.
  static Vec3 lift(const Vec<D - 1>& q) {
    Vec3 p = Vec3::Zero();
    p.template head<D - 1>() = q;
    return p;
  }

  World<D> world_;
  Frame<D> frame_;
  double scale_;
  Vec3 offset_;
  int forced_ = -1;                 // the vertex currently carrying the tool force
  std::vector<Vec<D>> zero_v_;      // nv, zeros for reset (sized once)
};

}  // namespace s4d
