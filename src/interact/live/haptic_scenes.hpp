// The haptic loop's ready-made scenes for `shadow4d haptics`, its benchmarks and tests: the sticky
// plane (haptics layer), or a 4D cloth that is a Scene built by the one world builder and run by
// the live simulation, hung by its top corners; where a scripted hand starts on each.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "haptics/device.hpp"
#include "haptics/haptic_scene.hpp"
#include "interact/live/device_mapping.hpp"
#include "interact/live/live_simulation.hpp"
#include "io/scene.hpp"

namespace s4d {

inline constexpr const char* kHapticSceneHelp = "plane|cloth";

struct HapticSceneChoice {
  std::string name = "plane";  // "plane" (the sticky plane) or "cloth" (a live simulation)
  int cloth_n = 16;            // vertices per side of the 4D cloth
  double cloth_size = 0.1;     // m, side of the cloth: scene units are device metres here
  bool collisions = true;      // the physics' collision avoidance
  bool async_physics = false;  // step the cloth's World on its own thread, not in the tick
};

// The cloth of `shadow4d haptics --scene cloth` as a scene: an n × n "cloth" generator object of
// side `size` in the xy plane of R^4, gravity along -y, the physics' defaults otherwise, seen
// through a frame turned 0.4 rad in xw (the shadow mixes x and w). Throws s4d::Error for n
// outside [2, 256].
Scene haptic_cloth_scene(int n, double size, bool collisions);
// Its two top corners (local vertex indices), which hold it up.
std::vector<int> haptic_cloth_corners(int n);

// The live simulation of `scene` (see live_simulation.hpp) with the vertices `held` of the
// object named `object` (a surface of R^4) held where they start — from the first step and again after every reset
// (a live simulation's reset lets go of pins, which in the window are the user's; here they are
// part of the scene). The hold is a scenario script, so a 64² table of held vertices costs one
// command. `name` is what the scene calls itself (recordings store it). Throws s4d::Error like
// make_live_simulation, or for a vertex out of range.
std::unique_ptr<HapticScene> make_held_live_simulation(std::string name, const Scene& scene, const std::string& object,
                                                       std::vector<int> held, const LiveOptions& options);

// The device mapping that fits the ball around the shadow of the scene's surfaces (seen through
// scene.frame) into the device's workspace, axes unturned.
DeviceMapping fit_to_workspace(const Scene& scene, const DeviceCapabilities& caps);

// The shadow (scene units) of vertex `v` of object `o` of the scene through its frame.
Vec3 shadow_of_vertex(const Scene& scene, int o, int v);

struct HapticSceneSetup {
  std::unique_ptr<HapticScene> scene;
  Vec3 hand_start = Vec3(0.02, 0, 0);  // m, device: where a scripted hand starts
  int held_vertex = -1;                // the vertex at hand_start that button 1 grabs (-1: none)
  double press = 0.003;                // m the demo hand presses along -z (the plane; 0 on the cloth)
};

// The scene by name: "plane" or "sticky-plane"; "cloth", or "rubber-band" (the name older
// recordings carry). Throws s4d::Error for an unknown name or a cloth_n outside [2, 256].
HapticSceneSetup make_haptic_scene(const HapticSceneChoice& choice);

}  // namespace s4d
