#include "gui_launch.hpp"

#include <cstdlib>
#include <iostream>

#ifdef S4D_HAVE_GUI
#include "app/gui_app.hpp"
#endif

namespace s4d::cli {

bool has_display() {
#ifdef __EMSCRIPTEN__
  return true;  // the web page: its canvas
#endif
  const char* x = std::getenv("DISPLAY");
  const char* w = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (w && *w);
}

int launch_gui(const GuiLaunch& launch) {
  if (!has_display()) {
    std::cerr << "shadow4d: no display (DISPLAY/WAYLAND_DISPLAY unset). Headless commands work:\n"
                 "  shadow4d demo            render the paper's objects to PNG\n"
                 "  shadow4d render OBJECT --out file.png\n"
                 "  shadow4d --help          all commands\n";
    return 1;
  }
#ifdef S4D_HAVE_GUI
  GuiOptions options;
  options.open_spec = launch.open_spec;
  options.frames = launch.frames;
  options.window_shot = launch.window_shot;
  options.device = launch.device;
  options.input = launch.input;
  options.autosave = launch.autosave;
  options.autosave_seconds = launch.autosave_seconds;
  options.restore = launch.restore;
  options.exercise_seed = launch.exercise_seed;
  options.width = launch.width;
  options.height = launch.height;
  options.ui_scale = launch.ui_scale;
  return run_gui_app(options);
#else
  std::cerr << "shadow4d: this build has no GUI (configure with -DS4D_BUILD_GUI=ON)\n";
  return 1;
#endif
}

}  // namespace s4d::cli
