// Ready-made haptic sessions shared by `shadow4d haptics`, the jitter benchmark and the GUI: the scene
// by name (sticky plane, or a rubber band on a 4D cloth from the physics) and a scripted hand path for
// the simulated arm and the headless mouse.
#pragma once
#include <memory>
#include <string>
#include <string_view>

#include "haptics/haptic_scene.hpp"

namespace s4d {

inline constexpr const char* kSceneChoiceHelp = "plane|cloth";

struct SceneChoice {
  std::string name = "plane";  // "plane" (sticky-plane) or "cloth" (rubber-band)
  int cloth_n = 16;            // vertices per side of the 4D cloth
  double cloth_size = 0.1;     // m, side of the cloth (device units: it fits the Omni workspace)
  bool collisions = true;      // the physics' collision avoidance
  bool async_physics = false;  // step the cloth on its own thread (AsyncSimulation), not in the loop
};

// Throws Error for an unknown name or a cloth_n outside [2, 256]. Accepts the recorded scene names
// ("sticky-plane", "rubber-band") too, so replays rebuild the scene they were recorded with.
std::unique_ptr<HapticScene> make_haptic_scene(const SceneChoice& choice);

// The demo hand: starts at `start`, presses `press` m along -z, and draws 2 cm circles at 0.5 Hz.
Vec3 demo_hand_path(double t, const Vec3& start, double press = 0.003);

}  // namespace s4d
