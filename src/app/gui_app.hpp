// The shadow4d window: GLFW + OpenGL 3.3 + Dear ImGui around the Renderer and the Session.
#pragma once
#include <string>

namespace s4d {

struct GuiOptions {
  std::string open_spec;         // scene, scenario, mesh, curve or generator call to open at start
  int frames = 0;                // > 0: quit after this many frames (smoke tests, scripted shots)
  std::string window_shot;       // when set, the last frame (panels included) is saved here
  int width = 1280, height = 800;
  float ui_scale = 0;            // > 0: the monitor's content scale as if it were this (--ui-scale)
  std::string device = "mouse";  // the haptic loop's device (--device)
  std::string input;             // an input file of timed events (see app/window_input.hpp)
  std::string autosave;          // the autosave file; empty: interact/autosave's default
  double autosave_seconds = 30;  // 0: no autosaves
  bool restore = false;          // take up an unfinished run's autosave without asking
  unsigned exercise_seed = 0;    // the knot exercises' choices: 0 at random, else the same every run
};

// Returns the process exit code; never throws (errors are shown in the window or printed).
int run_gui_app(const GuiOptions& options);
inline int run_gui_app(const std::string& open_spec) {
  GuiOptions options;
  options.open_spec = open_spec;
  return run_gui_app(options);
}

}  // namespace s4d
