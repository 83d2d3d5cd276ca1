#include "gui_launch.hpp"

#include <cstdlib>
#include <iostream>

#ifdef S4D_HAVE_GUI
#include "app/gui_app.hpp"
#endif

namespace s4d::cli {

bool has_display() {
  const char* x = std::getenv("DISPLAY");
  const char* w = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (w && *w);
}

int launch_gui(const std::string& open_spec, int frames, const std::string& window_shot,
               const std::string& device) {
  if (!has_display()) {
    std::cerr << "shadow4d: no display (DISPLAY/WAYLAND_DISPLAY unset). Headless commands work:\n"
                 "  shadow4d demo            render the paper's objects to PNG\n"
                 "  shadow4d render OBJECT --out file.png\n"
                 "  shadow4d --help          all commands\n";
    return 1;
  }
#ifdef S4D_HAVE_GUI
  GuiOptions options;
  options.open_spec = open_spec;
  options.frames = frames;
  options.window_shot = window_shot;
  options.device = device;
  return run_gui_app(options);
#else
  std::cerr << "shadow4d: this build has no GUI (configure with -DS4D_BUILD_GUI=ON)\n";
  return 1;
#endif
}

}  // namespace s4d::cli
