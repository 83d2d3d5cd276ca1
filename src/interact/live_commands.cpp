// The live simulation's requests as SceneCommands (built on the UI side, read by the core).
#include <algorithm>
#include <cmath>

#include "interact/live_core.hpp"
#include "interact/live_simulation.hpp"

namespace s4d {
namespace {

constexpr const char* kIntegrators[] = {"symplectic-euler", "paper-euler"};

int integrator_code(const std::string& name) {
  const Integrator i = parse_integrator(name);
  return i == Integrator::kPaperEuler ? 1 : 0;
}

}  // namespace

SceneCommand live_command(LiveCode code, int i0, int i1) {
  SceneCommand c;
  c.code = static_cast<int>(code);
  c.i[0] = i0;
  c.i[1] = i1;
  return c;
}

SceneCommand live_time_scale(double scale) {
  SceneCommand c = live_command(LiveCode::kTimeScale);
  c.x[0] = scale;
  return c;
}

SceneCommand live_settings(const PhysicsSettings& s) {
  SceneCommand c = live_command(LiveCode::kSettings, integrator_code(s.integrator));
  const double v[] = {s.time_step, s.thickness, s.gravity[0], s.gravity[1], s.gravity[2], s.gravity[3],
                      s.mass, s.stiffness, s.shear_scale, s.bending_scale, s.beta, s.damping,
                      s.spring_damping, s.friction, s.max_step_motion, s.collisions ? 1.0 : 0.0};
  std::copy(std::begin(v), std::end(v), c.x);
  return c;
}

SceneCommand live_grab(int vertex, int mode, const Vec3& hand, double carry_radius) {
  SceneCommand c = live_command(LiveCode::kGrab, vertex, mode);
  for (int k = 0; k < 3; ++k) c.x[k] = hand[k];
  c.x[3] = carry_radius;
  return c;
}

SceneCommand live_grab_nearest(const Vec3& point, double radius, int mode, double carry_radius) {
  SceneCommand c = live_command(LiveCode::kGrabNearest, 0, mode);
  for (int k = 0; k < 3; ++k) c.x[k] = point[k];
  c.x[3] = radius;
  c.x[4] = carry_radius;
  return c;
}

SceneCommand live_frame(const Frame<4>& frame) {
  SceneCommand c = live_command(LiveCode::kFrame);
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) c.x[4 * r + k] = frame.matrix()(r, k);
  return c;
}

SceneCommand live_explore(bool on, const Vec3& at) {
  SceneCommand c = live_command(LiveCode::kExplore, 0, on ? 1 : 0);
  for (int k = 0; k < 3; ++k) c.x[k] = at[k];
  return c;
}

SceneCommand live_relax(bool on) { return live_command(LiveCode::kRelax, 0, on ? 1 : 0); }

SceneCommand live_mapping(const DeviceMapping& m) {
  SceneCommand c = live_command(LiveCode::kMapping);
  for (int k = 0; k < 3; ++k) c.x[k] = m.centre[k];
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) c.x[3 + 3 * r + k] = m.axes(r, k);
  c.x[12] = m.metres_per_unit;
  for (int k = 0; k < 3; ++k) c.x[13 + k] = m.workspace_centre[k];
  return c;
}

namespace live_detail {

PhysicsSettings settings_of(const SceneCommand& c) {
  PhysicsSettings s;
  s.time_step = c.x[0];
  s.thickness = c.x[1];
  s.gravity = Vec4(c.x[2], c.x[3], c.x[4], c.x[5]);
  s.mass = c.x[6];
  s.stiffness = c.x[7];
  s.shear_scale = c.x[8];
  s.bending_scale = c.x[9];
  s.beta = c.x[10];
  s.damping = c.x[11];
  s.spring_damping = c.x[12];
  s.friction = c.x[13];
  s.max_step_motion = c.x[14];
  s.collisions = c.x[15] != 0;
  s.integrator = kIntegrators[std::clamp(c.i[0], 0, 1)];
  return s;
}

}  // namespace live_detail

}  // namespace s4d
