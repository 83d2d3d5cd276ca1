// LiveSimulation: the scene's surfaces as one World<D>, run by the haptic loop as its scene —
// the rubber band from the hand to a held vertex (paper 5.1.4), pins, play / pause / step,
// live physics settings and the scenario's script. The loop thread owns it; the UI reaches it
// only through SceneCommands (live_commands below) and reads the loop's snapshots.
//
// With `async_physics` the World steps on a thread of its own that follows the haptic clock, so
// a slow step (a cloth folded onto itself) never stalls the 1 kHz loop: the band then reads the
// latest published state and the simulation falls behind real time instead of the loop.
#pragma once
#include <memory>
#include <optional>
#include <span>
#include <vector>
#include <string>

#include "haptics/haptic_scene.hpp"
#include "interact/device_mapping.hpp"
#include "interact/tool.hpp"
#include "io/scene.hpp"
#include "scenario/scenario.hpp"

namespace s4d {

// SceneCommand codes of the live simulation; build them with the live_* functions.
enum class LiveCode : int {
  kPlay = 1,
  kPause,
  kStepOnce,   // one time_step, also while paused
  kReset,      // back to the start: positions, velocities, pins, script, time; a scenario's by-hand
               // set-up (ScriptMode::kByHand) holds from there
  kTimeScale,  // x0: simulated seconds per second, in [0.01, 4]
  kSettings,   // x: PhysicsSettings (see live_settings)
  kPin,        // i0: vertex, pinned where it is
  kUnpin,      // i0: vertex
  kTogglePin,  // i0: vertex
  kClearPins,
  kGrab,         // i0: vertex, i1: mode (0 shadow, 1 along the shadow ray: w, or a knot's depth);
                 // x0..x2: the hand's point in shadow space; x3: carry radius (0: the rubber band;
                 // > 0: the patch that far around the vertex, along the surface, follows the hand
                 // kinematically and stays held where it is let go)
  kGrabNearest,  // x0..x2: shadow point, x3: radius (scene units), x4: carry radius; i1: mode — the
                 // device's button
  kRelease,      // a curve (edited like clay) rests where it was left
  kGrabMode,     // i1: mode, re-anchored where the hand and the vertex are now
  kFrame,        // x0..x15: the 4D view frame, row-major (R^3 worlds ignore it)
  kMapping,      // x0..2 centre, x3..11 axes (row-major), x12 metres per unit, x13..15 workspace centre
  kPlayScript,   // restart from the start with the scenario's script
  kStopScript,   // let go of what the script holds, keep the state; the by-hand set-up holds on
  kExplore,      // i1: 1 starts exploring with the probe placed nearest x0..x2 (shadow), 0 stops; in R^3
                 // the probe walks the knot image last offered (offer_curve_image)
  kRelax,        // i1: 1 starts relaxing the knots (closed curves of R^3) live, 0 stops
  kDeviceButton, // i1: DeviceButton, what a device's first button does from now on; x0: carry radius
};

// SceneEvent kinds of the live simulation.
inline constexpr int kEventPassedAbove = 1;  // the probe's sheet passed another's shadow above in w
inline constexpr int kEventPassedBelow = 2;
inline constexpr int kEventCrossedOver = 3;   // the probe's strand passed a crossing over (label: its number)
inline constexpr int kEventCrossedUnder = 4;  // ... under

SceneCommand live_command(LiveCode code, int i0 = 0, int i1 = 0);
SceneCommand live_time_scale(double scale);
SceneCommand live_settings(const PhysicsSettings& settings);
SceneCommand live_grab(int vertex, int mode, const Vec3& hand, double carry_radius = 0);
SceneCommand live_grab_nearest(const Vec3& point, double radius, int mode, double carry_radius = 0);
SceneCommand live_frame(const Frame<4>& frame);
SceneCommand live_mapping(const DeviceMapping& mapping);
SceneCommand live_explore(bool on, const Vec3& at = Vec3::Zero());
SceneCommand live_relax(bool on);

struct LiveOptions {
  bool async_physics = false;  // step the World on its own thread (the window); false: in the tick
  bool start_playing = true;
  DeviceButton button = DeviceButton::kGrab;  // until a kDeviceButton command arrives
  double button_carry = 0;                    // the carry radius of that button (kGrab)
  // Where Reset goes (copied), when not the scene simulated from now: the start of bodies that
  // were there before an object was added, the new ones as they were added (Session::add_object).
  const Scene* reset_to = nullptr;
  DeviceMapping mapping;       // until a kMapping command arrives
  Frame<4> frame;              // until a kFrame command arrives
  int max_steps_per_tick = 4;  // inline: the most World steps one tick may run (the rest is lag)
};

// The scene's parameters (HapticScene::params), settable from the Haptics panel and commands.
enum LiveParam { kBandStiffness, kBandDamping, kBandMaxForce, kForceScale, kExploreStiffness, kExploreDamping,
                 kLiveParamCount };

struct CrossingTable;
struct CurveImage;

// A state to put the World in at once (an undo, a restored session): every vertex's position
// and velocity (nv × D each, body order) and the pinned vertices. The simulation pauses there
// unless `play`.
struct WorldState {
  std::vector<double> positions, velocities;
  std::vector<int> pinned;
  bool play = false;  // go on playing from it (a restored session that was playing)
  double time = -1;   // s simulated, for a restored session; negative: the World's own goes on (undo)
  // Numbers the offers (the Session counts them); SceneStatus::state_revision says which one the
  // World is in, so the UI knows when the snapshot shows the restored state.
  std::uint64_t revision = 0;
  // The shapes were edited (a crossing changed, an undo of a curve's drag): the springs rest here
  // and the contact layer is fitted to the new gaps, as for a fresh start.
  bool reshape = false;
};

// What the UI hands a running live simulation directly (thread-safe, never blocking either side).
class LiveHandover {
 public:
  virtual ~LiveHandover() = default;
  // The world's triangles (global vertex indices), fixed for the simulation's life.
  virtual std::span<const Triangle> triangles() const = 0;
  // The shadow's intersection curves for the explorer (interact/surface_explorer.hpp's
  // build_crossing_table on a recent state and the current frame); the latest offer wins, the
  // tick installs it without allocating. No-op for a world of R^3.
  virtual void offer_crossings(std::unique_ptr<CrossingTable> table) = 0;
  // The knots' image for the curve explorer (interact/curve_explorer.hpp's build_curve_image of the
  // scene's curves in shadow space, seen through the camera's axes); latest offer wins. No-op in R^4.
  virtual void offer_curve_image(std::unique_ptr<CurveImage> image) = 0;
  // Puts the World in `state` at the next step and pauses it (a state of the wrong size or with a
  // non-finite value is refused, with the reason in the status message).
  virtual void offer_state(std::unique_ptr<WorldState> state) = 0;
};

// Builds the World of the scene's surfaces, or of its curves when it has none
// (scenario/world_builder). `scenario`, when given, supplies the script kPlayScript plays. Throws
// s4d::Error with the reason the scene cannot be simulated (nothing to simulate, a surface or
// curve already meeting itself, bad parameters).
//
// Curves are edited like clay: the band pulls a strand and its neighbours follow through the
// chain's springs, collision avoidance keeps every strand from passing through another (so a
// drag is an isotopy), and on release the springs rest where the curve was left.
std::unique_ptr<HapticScene> make_live_simulation(const Scene& scene, const Scenario* scenario,
                                                  const LiveOptions& options);

}  // namespace s4d
