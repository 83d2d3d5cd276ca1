// shadow4d: with no sub-command opens the GUI (optionally on a file); sub-commands run headless.
#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

#include "command.hpp"
#include "core/data_paths.hpp"
#include "core/error.hpp"
#include "gui_launch.hpp"

int main(int argc, char** argv) {
  CLI::App app{"shadow4d - touch and edit higher-dimensional objects through their shadows.\n"
               "With no sub-command, opens the app window (on a display)."};
  app.require_subcommand(0, 1);
  s4d::cli::GuiLaunch gui;
  app.add_option("file", gui.open_spec,
                 "scene or scenario (.json), mesh (.off/.4off), curve (.vect/.txt) or generator call to open");
  app.add_option("--frames", gui.frames, "GUI: quit after this many frames (for scripted screenshots)")
      ->group("GUI scripting")->check(CLI::NonNegativeNumber);
  app.add_option("--window-shot", gui.window_shot, "GUI: save the window, panels included, at the last frame")
      ->group("GUI scripting");
  app.add_option("--input", gui.input,
                 "GUI: play timed mouse and key events from this file (lines 'FRAME EVENT ARGS': move X Y, "
                 "move-by DX DY, move-view X Y (half-sides of the view from its centre), move-to-vertex N [DX DY] (where simulated vertex N is on the screen then), "
                 "press left, release left, scroll DY, key NAME, key-down NAME, key-up NAME, type TEXT, open SPEC, "
                 "shot FILE, dump FILE, quit, wait: until background work is done)")
      ->group("GUI scripting");
  app.add_option("--autosave", gui.autosave,
                 "GUI: the autosave file (default $XDG_STATE_HOME/shadow4d/autosave.s4d or ~/.local/state/...)");
  app.add_option("--autosave-seconds", gui.autosave_seconds, "GUI: seconds between autosaves (0: none)")
      ->check(CLI::Range(0.0, 1e6));
  app.add_option("--exercise-seed", gui.exercise_seed,
                 "GUI: the knot exercises' choices (0: at random; another number: the same every run, e.g. for a class)")
      ->group("GUI scripting");
  std::string size;
  app.add_option("--size", size, "GUI: the window's size in pixels, WxH (default 1280x800)")
      ->check([](const std::string& v) {
        int w = 0, h = 0;
        char x = 0;
        return std::sscanf(v.c_str(), "%d%c%d", &w, &x, &h) == 3 && (x == 'x' || x == 'X') && w >= 200 && h >= 150 &&
                       w <= 16384 && h <= 16384
                   ? std::string()
                   : std::string("--size wants WxH, e.g. 1280x800 (200x150 to 16384x16384)");
      });
  app.add_option("--ui-scale", gui.ui_scale,
                 "GUI: the panels' and fonts' scale as if the monitor's content scale were this (default: the monitor's)")
      ->check(CLI::Range(0.5, 4.0));
  app.add_flag("--restore", gui.restore, "GUI: take up the autosave a crashed or killed run left, without asking");
  app.add_option(
      "--device", gui.device,
      "GUI: the haptic loop's device: mouse (default), sim, replay:FILE, spacenav, openhaptics");
  // The version, and where the data was found: an installed program names its own share folder.
  app.set_version_flag("--version", [] {
    std::string why;
    const std::optional<s4d::DataDirs> d = s4d::try_data_dirs(&why);
    return std::string("shadow4d " S4D_VERSION "\ndata: ") +
           (d ? d->root.string() + " (" + d->found_by + ")" : "not found: " + why);
  });
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "log more");
  s4d::cli::add_registered_commands(app);

  try {
    app.parse(argc, argv);
    spdlog::set_level(verbose ? spdlog::level::debug : spdlog::level::info);
    if (!size.empty()) {
      char x = 0;
      std::sscanf(size.c_str(), "%d%c%d", &gui.width, &x, &gui.height);
    }
    if (app.get_subcommands().empty()) return s4d::cli::launch_gui(gui);
  } catch (const CLI::ParseError& e) {
    // --help is 0; a usage error (CLI11's own codes, 100 and up) is the README's 1, its message
    // saying what was wrong and to run --help.
    return app.exit(e) == 0 ? 0 : 1;
  } catch (const s4d::cli::ExitStatus& e) {
    return e.code;
  } catch (const s4d::Error& e) {
    std::cerr << "shadow4d: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "shadow4d: unexpected error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
