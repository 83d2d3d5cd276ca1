// Opens the GUI when the build has one and a display is present; explains what to do otherwise.
#pragma once
#include <string>

namespace s4d::cli {

// What the window opens with (see app/gui_app.hpp's GuiOptions).
struct GuiLaunch {
  std::string open_spec;
  int frames = 0;
  std::string window_shot;
  std::string device = "mouse";
  std::string input;
  std::string autosave;
  double autosave_seconds = 30;
  bool restore = false;
  unsigned exercise_seed = 0;
  int width = 1280, height = 800;
  float ui_scale = 0;
};
// Returns the process exit code.
int launch_gui(const GuiLaunch& launch);
// True when DISPLAY or WAYLAND_DISPLAY is set.
bool has_display();

}  // namespace s4d::cli
