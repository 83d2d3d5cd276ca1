// LiveSimulation: the scene's surfaces as one World<D>, run by the haptic loop as its scene —
// the rubber band from the hand to a held vertex (paper 5.1.4), pins, play / pause / step,
// live physics settings and the scenario's script. The loop thread owns it; the UI reaches it
// only through live::Requests (interact/live/live_requests.hpp) and reads the loop's snapshots.
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
#include "interact/live/device_mapping.hpp"
#include "interact/live/live_requests.hpp"
#include "io/scene.hpp"
#include "scenario/scenario.hpp"

namespace s4d {

// SceneEvent kinds of the live simulation.
inline constexpr int kEventPassedAbove = 1;  // the probe's sheet passed another's shadow above in w
inline constexpr int kEventPassedBelow = 2;
inline constexpr int kEventCrossedOver = 3;   // the probe's strand passed a crossing over (label: its number)
inline constexpr int kEventCrossedUnder = 4;  // ... under

struct LiveOptions {
  bool async_physics = false;  // step the World on its own thread (the window); false: in the tick
  bool start_playing = true;
  DeviceButton button = DeviceButton::kGrab;  // until a SetDeviceButton request arrives
  int button_carry = 0;                       // the rings that button carries (kGrab; 0: the band)
  // Where Reset goes (copied), when not the scene simulated from now: the start of bodies that
  // were there before an object was added, the new ones as they were added (Session::add_object).
  const Scene* reset_to = nullptr;
  DeviceMapping mapping;       // until a SetMapping request arrives
  Frame<4> frame;              // until a SetFrame request arrives
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
  // The shadow's intersection curves for the explorer (interact/live/surface_explorer.hpp's
  // build_crossing_table on a recent state and the current frame); the latest offer wins, the
  // tick installs it without allocating. No-op for a world of R^3.
  virtual void offer_crossings(std::unique_ptr<CrossingTable> table) = 0;
  // The knots' image for the curve explorer (interact/live/curve_explorer.hpp's build_curve_image of the
  // scene's curves in shadow space, seen through the camera's axes); latest offer wins. No-op in R^4.
  virtual void offer_curve_image(std::unique_ptr<CurveImage> image) = 0;
  // Puts the World in `state` at the next step and pauses it (a state of the wrong size or with a
  // non-finite value is refused, with the reason in the status message).
  virtual void offer_state(std::unique_ptr<WorldState> state) = 0;
};

// Builds the World of the scene's surfaces, or of its curves when it has none
// (scenario/world_builder). `scenario`, when given, supplies the script PlayScript plays. Throws
// s4d::Error with the reason the scene cannot be simulated (nothing to simulate, a surface or
// curve already meeting itself, bad parameters).
//
// Curves are edited like clay: the band pulls a strand and its neighbours follow through the
// chain's springs, collision avoidance keeps every strand from passing through another (so a
// drag is an isotopy), and on release the springs rest where the curve was left.
std::unique_ptr<HapticScene> make_live_simulation(const Scene& scene, const Scenario* scenario,
                                                  const LiveOptions& options);

}  // namespace s4d
