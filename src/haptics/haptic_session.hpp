// The scripted hand shared by `shadow4d haptics`, its benchmark and the headless mouse: circles
// drawn on the sticky plane or on the cloth vertex it holds. (The scenes by name are the interact
// layer's: interact/live/haptic_scenes.hpp.)
#pragma once
#include "core/vec.hpp"

namespace s4d {

// The demo hand: starts at `start`, presses `press` m along -z over 0.3 s, then draws 2 cm circles
// at 0.5 Hz.
Vec3 demo_hand_path(double t, const Vec3& start, double press = 0.003);

}  // namespace s4d
