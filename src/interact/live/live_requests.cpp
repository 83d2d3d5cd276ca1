// The live requests' conversions from and to the engine's own types.
#include "interact/live/live_requests.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace s4d::live {

namespace {
bool all_finite(std::initializer_list<double> v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}
}  // namespace

SetPhysics SetPhysics::from(const PhysicsSettings& s) {
  SetPhysics p;
  p.time_step = s.time_step;
  p.thickness = s.thickness;
  for (int k = 0; k < 4; ++k) p.gravity[static_cast<std::size_t>(k)] = s.gravity[k];
  p.mass = s.mass;
  p.stiffness = s.stiffness;
  p.shear_scale = s.shear_scale;
  p.bending_scale = s.bending_scale;
  p.beta = s.beta;
  p.damping = s.damping;
  p.spring_damping = s.spring_damping;
  p.friction = s.friction;
  p.max_step_motion = s.max_step_motion;
  p.collisions = s.collisions;
  p.integrator = parse_integrator(s.integrator);
  return p;
}

PhysicsSettings SetPhysics::settings() const {
  PhysicsSettings s;
  s.time_step = time_step;
  s.thickness = thickness;
  s.gravity = Vec4(gravity[0], gravity[1], gravity[2], gravity[3]);
  s.mass = mass;
  s.stiffness = stiffness;
  s.shear_scale = shear_scale;
  s.bending_scale = bending_scale;
  s.beta = beta;
  s.damping = damping;
  s.spring_damping = spring_damping;
  s.friction = friction;
  s.max_step_motion = max_step_motion;
  s.collisions = collisions;
  s.integrator = integrator_name(integrator);
  return s;
}

bool SetPhysics::finite() const {
  return all_finite({time_step, thickness, gravity[0], gravity[1], gravity[2], gravity[3], mass, stiffness,
                     shear_scale, bending_scale, beta, damping, spring_damping, friction, max_step_motion});
}

SetFrame SetFrame::from(const Frame<4>& f) {
  SetFrame s;
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) s.rows[static_cast<std::size_t>(4 * r + k)] = f.matrix()(r, k);
  s.perspective = f.perspective();
  return s;
}

Frame<4> SetFrame::frame() const {
  Mat<4> m;
  for (int i = 0; i < 16; ++i) m(i / 4, i % 4) = rows[static_cast<std::size_t>(i)];
  Frame<4> f(m);
  if (Frame<4>::perspective_error(perspective).empty()) f.set_perspective(perspective);  // else orthographic
  return f;
}

SetMapping SetMapping::from(const DeviceMapping& m) {
  SetMapping s;
  for (int k = 0; k < 3; ++k) {
    s.centre[static_cast<std::size_t>(k)] = m.centre[k];
    s.workspace_centre[static_cast<std::size_t>(k)] = m.workspace_centre[k];
    for (int c = 0; c < 3; ++c) s.axes[static_cast<std::size_t>(3 * k + c)] = m.axes(k, c);
  }
  s.metres_per_unit = m.metres_per_unit;
  return s;
}

DeviceMapping SetMapping::mapping() const {
  DeviceMapping m;
  for (int k = 0; k < 3; ++k) {
    m.centre[k] = centre[static_cast<std::size_t>(k)];
    m.workspace_centre[k] = workspace_centre[static_cast<std::size_t>(k)];
    for (int c = 0; c < 3; ++c) m.axes(k, c) = axes[static_cast<std::size_t>(3 * k + c)];
  }
  m.metres_per_unit = metres_per_unit;
  return m;
}

bool SetMapping::valid() const {
  const DeviceMapping m = mapping();
  return m.centre.allFinite() && m.workspace_centre.allFinite() && m.axes.allFinite() &&
         std::isfinite(metres_per_unit) && metres_per_unit > 0;
}

}  // namespace s4d::live
