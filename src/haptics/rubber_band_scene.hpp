// RubberBandScene (paper 5.1.4): the pointer holds a picked simulation vertex through a damped spring;
// the pointer feels the spring, the simulation receives its reaction as an external force.
#pragma once
#include <array>
#include <memory>

#include "haptics/haptic_scene.hpp"

namespace s4d {

// A simulation whose vertices the rubber band can hold, seen in the 3D shadow space in device
// coordinates (m). A 4D cloth adapter projects its vertices with the view frame and lifts the 3D force
// back into the shadow subspace of R^4. Loop-thread only; no allocation in step().
class GrabbableSimulation {
 public:
  virtual ~GrabbableSimulation() = default;
  virtual int vertex_count() const = 0;
  virtual Vec3 shadow_position(int v) const = 0;  // m
  virtual Vec3 shadow_velocity(int v) const = 0;  // m/s
  // External force (N, shadow coordinates) on vertex v during the following step(s); replaces the
  // previous one. A negative v clears it.
  virtual void set_external_force(int v, const Vec3& f) = 0;
  virtual void step(double dt) = 0;
  virtual void reset() = 0;
  // For rendering: all vertices, flattened (point_dimension() values each).
  virtual int point_dimension() const { return 3; }
  virtual void copy_points(std::span<double> out) const;
  // The vertex nearest to p in the shadow (brute force; picking happens once per grab).
  virtual int nearest_vertex(const Vec3& p) const;
};

class RubberBandScene final : public HapticScene {
 public:
  enum Param { kK, kB, kSubsteps, kHold, kParamCount };

  explicit RubberBandScene(std::unique_ptr<GrabbableSimulation> sim);

  std::string_view name() const override { return "rubber-band"; }
  ToolOutput step(const DeviceState& device, double dt) override;
  void reset() override;
  std::span<SceneParam> params() override { return params_; }
  int point_count() const override { return sim_->vertex_count(); }
  int point_dimension() const override { return sim_->point_dimension(); }
  void copy_points(std::span<double> out) const override { sim_->copy_points(out); }

  int picked_vertex() const { return picked_; }  // -1 when nothing is held
  const GrabbableSimulation& simulation() const { return *sim_; }

 private:
  std::unique_ptr<GrabbableSimulation> sim_;
  std::array<SceneParam, kParamCount> params_;
  int picked_ = -1;
};

}  // namespace s4d
