// What the UI (a tool, a panel, a script) asks of a running live simulation, as typed values: one
// struct per request, all in one std::variant that crosses to the loop thread in a SceneCommand
// and is applied there by one visitor (LiveSimulation::command). Trivially copyable on purpose
// (the queue copies bytes), so points are plain arrays, not Eigen vectors. Larger things (a whole
// state, the shadow's curves) go through LiveHandover instead, which hands over heap objects.
// Sections: [SECTION] the clock and the script, [SECTION] physics, [SECTION] pins,
// [SECTION] the hand, [SECTION] the view and the device, [SECTION] exploring and relaxing,
// [SECTION] sketching a knot by touch
#pragma once
#include <array>
#include <variant>

#include "core/frame.hpp"
#include "core/vec.hpp"
#include "haptics/haptic_scene.hpp"
#include "interact/live/device_mapping.hpp"
#include "io/scene.hpp"
#include "physics/model.hpp"

namespace s4d::live {

using Point3 = std::array<double, 3>;
inline Point3 point(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
inline Vec3 vec(const Point3& p) { return Vec3(p[0], p[1], p[2]); }

// [SECTION] the clock and the script
struct Play {};
struct Pause {};
struct StepOnce {};    // one time step, also while paused
struct Reset {};       // back to the start: positions, velocities, pins, script, time; a scenario's
                       // by-hand set-up (ScriptMode::kByHand) holds from there
struct PlayScript {};  // restart from the start with the scenario's script
struct StopScript {};  // let go of what the script holds, keep the state; the by-hand set-up holds on
struct SetTimeScale {
  double scale = 1;  // simulated seconds per second, clamped to [0.01, 4]
};

// [SECTION] physics
// PhysicsSettings as plain values (its integrator by enum, not by name).
struct SetPhysics {
  double time_step = 1e-3, thickness = 0.02;
  std::array<double, 4> gravity{};
  double mass = 1e-3, stiffness = 50, shear_scale = 0.5, bending_scale = 0.1, beta = 0;
  double damping = 0.02, spring_damping = 0.02, friction = 0.3, max_step_motion = 0;
  bool collisions = true;
  Integrator integrator = Integrator::kSymplecticEuler;

  static SetPhysics from(const PhysicsSettings& s);  // throws Error on an unknown integrator
  PhysicsSettings settings() const;
  bool finite() const;
};

// [SECTION] pins
enum class PinAction : int { kPin, kUnpin, kToggle };
struct Pin {
  int vertex = -1;
  PinAction action = PinAction::kPin;
};
struct ClearPins {};

// [SECTION] the hand
// kShadow: the band pulls in the shadow (w stays free); kAlongRay: along the shadow ray (w, or a
// knot's depth), the shadow held.
enum class GrabMode : int { kShadow = 0, kAlongRay = 1 };
struct Grab {
  int vertex = -1;
  GrabMode mode = GrabMode::kShadow;
  Point3 hand{};              // shadow space: where the hand is
  int carry_rings = 0;        // 0: the rubber band; > 0: the patch of that many rings of mesh edges
                              // around the vertex follows the hand and stays held where it is let go
};
struct GrabNearest {          // what a device's button does: the vertex nearest a point
  Point3 point{};             // shadow space
  double reach = 0;           // scene units
  GrabMode mode = GrabMode::kShadow;
  int carry_rings = 0;
};
struct Release {};            // a curve (edited like clay) rests where it was left
struct SetGrabMode {          // re-anchored where the hand and the vertex are now
  GrabMode mode = GrabMode::kShadow;
};
struct SetDeviceButton {      // what a device's first button does from now on
  DeviceButton action = DeviceButton::kGrab;
  int carry_rings = 0;
};

// [SECTION] the view and the device
struct SetFrame {             // the 4D view frame (worlds of R^3 ignore it)
  std::array<double, 16> rows{};  // row-major
  double perspective = 0;         // the 4D eye's distance (Frame::perspective), 0 orthographic
  static SetFrame from(const Frame<4>& f);
  Frame<4> frame() const;
};
struct SetMapping {
  std::array<double, 3> centre{}, workspace_centre{};
  std::array<double, 9> axes{};  // row-major
  double metres_per_unit = 0.05;
  static SetMapping from(const DeviceMapping& m);
  DeviceMapping mapping() const;
  bool valid() const;  // finite, with a positive scale
};

// [SECTION] exploring and relaxing
struct StartExploring {  // the probe placed nearest `at` (shadow); in R^3 on the knot image last offered
  Point3 at{};
};
struct StopExploring {};
struct StartRelaxing {};  // the knots (closed curves of R^3) relax live
struct StopRelaxing {};

// [SECTION] sketching a knot by touch (CurveSketch)
struct SketchBegin {     // starts sketching (strokes so far are kept)
  double plane_z = 0;    // m, device
};
struct SketchEnd {};        // stops sketching and forgets the strokes
struct SketchBackspace {};  // removes the last segment (the one being drawn, or the last one drawn)
struct SketchClear {};      // forgets the strokes, keeps sketching (after the knot joined the scene)

using Request = std::variant<Play, Pause, StepOnce, Reset, PlayScript, StopScript, SetTimeScale, SetPhysics, Pin,
                             ClearPins, Grab, GrabNearest, Release, SetGrabMode, SetDeviceButton, SetFrame, SetMapping,
                             StartExploring, StopExploring, StartRelaxing, StopRelaxing, SketchBegin, SketchEnd,
                             SketchBackspace, SketchClear>;

// The request boxed for the haptic loop's queue (HapticLoop::send).
inline SceneCommand command(const Request& r) { return SceneCommand::of(r); }
// The request a command carries, or null when it carries something else.
inline const Request* request(const SceneCommand& c) { return c.get<Request>(); }

}  // namespace s4d::live
