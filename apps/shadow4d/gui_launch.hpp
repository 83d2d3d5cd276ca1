// Opens the GUI when the build has one and a display is present; explains what to do otherwise.
#pragma once
#include <string>

namespace s4d::cli {

// Returns the process exit code.
// `frames` > 0 quits after that many frames, saving the window to `window_shot` if set.
// `device` (mouse|sim|replay:FILE|spacenav|openhaptics) starts the haptic loop with that device.
int launch_gui(const std::string& open_spec, int frames = 0, const std::string& window_shot = {},
               const std::string& device = {});
// True when DISPLAY or WAYLAND_DISPLAY is set.
bool has_display();

}  // namespace s4d::cli
