// The haptics panel (Dear ImGui): device choice, live loop period statistics with a plot, safety state,
// force-model parameters; plus the force arrow and pointer mapping the window needs for the mouse path.
#pragma once
#include <array>
#include <string>

#include "haptics/haptic_loop.hpp"

namespace s4d {

// UI state the caller keeps between frames (immediate mode: the caller owns the data).
struct HapticsPanelState {
  int device_choice = 0;                 // index into haptics_panel_devices()
  std::array<char, 512> replay_file{};   // path typed for "replay"
  std::string error;                     // last failure (e.g. "no spacenavd"), shown until the next try
  bool open = true;
  float arrow_scale = 0.01f;             // m per N of the drawn force arrow
  std::string requested_device;          // set by "Switch device": the caller opens it (and says why not)
};

// Draws the "Haptics" window. `snap` is this frame's loop.snapshot() (one read per frame, shared with
// the renderer: the snapshot has a single reader). "Switch device" leaves the spec in
// ui.requested_device for the caller, whose errors go to ui.error (the current device keeps running).
// The panel's contents; the caller places it (a section of the window's left column).
void draw_haptics_panel(HapticsPanelState& ui, HapticLoop& loop, const HapticSnapshot& snap);

// The device choices in the panel's order, as --device spells them (replay takes the typed file).
const char* const* haptics_panel_devices(int* count);

// What the renderer draws for the force: an arrow from the device point along the output force,
// `metres_per_newton` long per newton, coloured from green (no force) to red (the device's peak), and
// the tool's anchor (C' on the shadow, or the held vertex: the rubber band's other end).
struct ForceArrow {
  Vec3 from = Vec3::Zero();    // m, device coordinates
  Vec3 to = Vec3::Zero();      // m
  Vec3 anchor = Vec3::Zero();  // m
  Vec3 target = Vec3::Zero();  // m, the cursor / hand: its distance to `from` is the proxy lag
  std::array<float, 4> rgba{0, 1, 0, 1};
  bool engaged = false;        // draw the rubber band / contact line from `from` to `anchor`
};
ForceArrow force_arrow(const HapticSnapshot& snap, double metres_per_newton);

// Maps a cursor in normalised window coordinates (x, y in [-1, 1], y up) and a wheel depth in [-1, 1]
// into the device workspace, the target the mouse backend's proxy follows (pass it to set_pointer).
Vec3 pointer_to_workspace(const DeviceCapabilities& caps, double nx, double ny, double depth);

}  // namespace s4d
