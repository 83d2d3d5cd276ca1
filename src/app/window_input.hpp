// WindowInput: the one place the window's mouse and keys arrive — from GLFW's callbacks, or from
// an input file of timed events (--input FILE), through the same function — so a test under
// Xvfb can drive the real window deterministically, frame by frame.
//
// Input file: one event per line, `# comments`, each line `FRAME EVENT ARGS`:
//   12 move X Y            cursor to window pixel (X, Y)
//   12 move-by DX DY       cursor moved by (DX, DY) pixels from where it is
//   12 move-view X Y       cursor to a point of the 3D view wherever the panels put it: (X, Y)
//                          in half-sides (the smaller side) of the view from its centre, Y up
//   12 move-to-hint N marker|target [DX DY]  cursor to where the scenario's marker N (from 1), or
//                          its target, is drawn when the event plays
//   12 move-to-vertex N [DX DY]  cursor to where simulated vertex N is on the screen when the
//                          event plays (offset by DX, DY), its own sheet preferred where the
//                          shadow folds others onto it
//   13 press left|right|middle        14 release left|right|middle
//   15 scroll DY           the wheel (positive: away from the user)
//   16 key-down NAME       17 key-up NAME       18 key NAME (down and up)
//      NAME: a letter or digit, TAB, ESCAPE, ENTER, BACKSPACE, DELETE, SPACE, LEFT_SHIFT,
//      LEFT_CONTROL, LEFT_ALT, RIGHT_SHIFT, RIGHT_CONTROL, RIGHT_ALT, F1, F12, UP, DOWN, LEFT, RIGHT,
//      LEFT_BRACKET, RIGHT_BRACKET, SLASH
//   19 type TEXT           TEXT typed (characters) into the focused text field
//   19 open SPEC           open a scene, scenario, mesh, curve or generator call
//   20 shot FILE.png       save the window (panels included) after this frame
//   21 dump FILE.json      write the session's state (simulation, checks, vertex positions)
//   21 dump -              the same as one line "dump {...}" on the standard output (the web
//                          page's console)
//   22 quit
//   23 wait-time T         the script's frames stop counting until the simulation's time is T s
//   23 wait-sim S          ... until S s more of simulated time have passed
//   23 wait                the script's frames stop counting until the window's background work
//                          (naming, making a table knot, checking an exercise) is done (60 s at most)
// The file's frames count only frames that show the session's latest state: while an undone or
// redone state is on its way to the simulation, the file waits (gui_app.cpp).
#pragma once
#include <array>
#include <deque>
#include <filesystem>
#include <string>
#include <vector>

#include "core/vec.hpp"

struct GLFWwindow;

namespace s4d {

struct InputEvent {
  enum class Kind { move, move_by, press, release, scroll, key_down, key_up, chr, open, shot, dump, quit, wait,
                    move_to_vertex, move_view, move_to_hint, wait_time };
  Kind kind = Kind::move;
  int frame = 0;      // the file's frame (0 for live events)
  Vec2 at = Vec2::Zero();
  int button = 0;     // 0 left, 1 right, 2 middle
  double scroll = 0;  // also wait-time's T
  int key = 0;        // GLFW key code
  unsigned codepoint = 0;
  std::string text;   // open / shot / dump argument
  int vertex = -1;    // move_to_vertex: the simulated vertex (its pixel offset by `at`)
};

// Reads an input file; throws ParseError (file:line: what is wrong) on a malformed line.
std::vector<InputEvent> read_input_file(const std::filesystem::path& path);

class WindowInput {
 public:
  // Installs the GLFW callbacks on `window` (ImGui's backend must be initialised without its
  // own callbacks); the window's user pointer is set to this object.
  void attach(GLFWwindow* window);
  // Scripted events, played at their frames.
  void set_script(std::vector<InputEvent> events) { script_.assign(events.begin(), events.end()); }
  bool scripted() const { return !script_.empty() || had_script_; }

  // Start of a frame: applies the live events that arrived and the script's events of `frame`
  // to the state; the commands (open, shot, dump, quit) are returned for the window to act on.
  std::vector<InputEvent> begin_frame(int frame);
  // After ImGui's backend NewFrame: the mouse and modifier state into ImGui's IO.
  void write_to_imgui() const;

  Vec2 cursor() const { return cursor_; }
  bool down(int button) const { return held_[static_cast<std::size_t>(button)]; }
  bool pressed(int button) const { return pressed_[static_cast<std::size_t>(button)]; }    // this frame
  bool released(int button) const { return released_[static_cast<std::size_t>(button)]; }  // this frame
  double wheel() const { return wheel_; }  // this frame
  bool key_pressed(int key) const;         // went down this frame
  bool key_down(int key) const;
  bool shift() const, ctrl() const, alt() const;
  Vec2 cursor_delta() const { return cursor_ - last_cursor_; }

  // Puts the pointer at `pixel` now (the input file's move-to-vertex, once the window knows where).
  void move_to(const Vec2& pixel) { cursor_ = pixel; }
  // GLFW's callbacks land here (public for the C trampolines).
  void live(const InputEvent& e) { live_.push_back(e); }
  GLFWwindow* window() const { return window_; }

 private:
  void apply(const InputEvent& e);

  GLFWwindow* window_ = nullptr;
  std::deque<InputEvent> script_;
  bool had_script_ = false;
  std::vector<InputEvent> live_;
  Vec2 cursor_ = Vec2::Zero(), last_cursor_ = Vec2::Zero();
  std::array<bool, 3> held_{}, pressed_{}, released_{};
  double wheel_ = 0;
  std::vector<int> keys_down_, keys_pressed_;
};

}  // namespace s4d
