// The window's input: GLFW callbacks and the input file meet in apply(); ImGui is fed from the
// resulting state, so panels and the view see scripted events exactly as real ones.
#include "app/window_input.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <algorithm>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "io/text_scanner.hpp"

namespace s4d {

#ifdef __EMSCRIPTEN__
constexpr bool kPageBuild = true;
#else
constexpr bool kPageBuild = false;
#endif

namespace {

const std::map<std::string, int>& key_names() {
  static const std::map<std::string, int> names = [] {
    std::map<std::string, int> m{
        {"TAB", GLFW_KEY_TAB},           {"ESCAPE", GLFW_KEY_ESCAPE},         {"ENTER", GLFW_KEY_ENTER},
        {"BACKSPACE", GLFW_KEY_BACKSPACE}, {"DELETE", GLFW_KEY_DELETE},       {"SPACE", GLFW_KEY_SPACE},
        {"LEFT_SHIFT", GLFW_KEY_LEFT_SHIFT}, {"LEFT_CONTROL", GLFW_KEY_LEFT_CONTROL},
        {"LEFT_ALT", GLFW_KEY_LEFT_ALT}, {"RIGHT_SHIFT", GLFW_KEY_RIGHT_SHIFT},
        {"RIGHT_CONTROL", GLFW_KEY_RIGHT_CONTROL}, {"RIGHT_ALT", GLFW_KEY_RIGHT_ALT}, {"F12", GLFW_KEY_F12},
        {"UP", GLFW_KEY_UP},             {"DOWN", GLFW_KEY_DOWN},             {"LEFT", GLFW_KEY_LEFT},
        {"RIGHT", GLFW_KEY_RIGHT},       {"LEFT_BRACKET", GLFW_KEY_LEFT_BRACKET}, {"RIGHT_BRACKET", GLFW_KEY_RIGHT_BRACKET},
        {"SLASH", GLFW_KEY_SLASH},       {"F1", GLFW_KEY_F1}};
    for (char c = 'A'; c <= 'Z'; ++c) m[std::string(1, c)] = GLFW_KEY_A + (c - 'A');
    for (char c = '0'; c <= '9'; ++c) m[std::string(1, c)] = GLFW_KEY_0 + (c - '0');
    return m;
  }();
  return names;
}

int button_of(const std::string& name) {
  if (name == "left") return 0;
  if (name == "right") return 1;
  if (name == "middle") return 2;
  return -1;
}

WindowInput* self(GLFWwindow* w) { return static_cast<WindowInput*>(glfwGetWindowUserPointer(w)); }

void on_cursor(GLFWwindow* w, double x, double y) {
  InputEvent e;
  e.kind = InputEvent::Kind::move;
  e.at = Vec2(x, y);
  self(w)->live(e);
}

void on_button(GLFWwindow* w, int button, int action, int mods) {
  ImGui_ImplGlfw_MouseButtonCallback(w, button, action, mods);
  if (button < 0 || button > 2) return;
  InputEvent e;
  e.kind = action == GLFW_PRESS ? InputEvent::Kind::press : InputEvent::Kind::release;
  e.button = button == GLFW_MOUSE_BUTTON_LEFT ? 0 : button == GLFW_MOUSE_BUTTON_RIGHT ? 1 : 2;
  self(w)->live(e);
}

void on_scroll(GLFWwindow* w, double, double dy) {
  InputEvent e;
  e.kind = InputEvent::Kind::scroll;
  e.scroll = dy;
  self(w)->live(e);
}

void on_key(GLFWwindow* w, int key, int, int action, int) {
  if (action == GLFW_REPEAT) return;
  InputEvent e;
  e.kind = action == GLFW_PRESS ? InputEvent::Kind::key_down : InputEvent::Kind::key_up;
  e.key = key;
  self(w)->live(e);
}

void on_char(GLFWwindow* w, unsigned int c) {
  InputEvent e;
  e.kind = InputEvent::Kind::chr;
  e.codepoint = c;
  self(w)->live(e);
}

// A file dropped on the window opens as File > Open would (in the web page: the user's own file,
// which the browser hands over into the page's memory; the first of several).
void on_drop(GLFWwindow* w, int count, const char** paths) {
  if (count < 1 || !paths[0]) return;
  InputEvent e;
  e.kind = InputEvent::Kind::open;
  e.text = paths[0];
  self(w)->live(e);
}

void on_focus(GLFWwindow* w, int focused) { ImGui_ImplGlfw_WindowFocusCallback(w, focused); }
void on_enter(GLFWwindow* w, int entered) { ImGui_ImplGlfw_CursorEnterCallback(w, entered); }

// A pointer event's optional trailing "DX DY" in pixels (none: no offset).
template <typename Fail>
Vec2 optional_offset(std::istringstream& ls, const std::string& word, const Fail& fail) {
  double dx = 0, dy = 0;
  if (!(ls >> dx)) {
    ls.clear();
    return Vec2::Zero();
  }
  if (!(ls >> dy) || !std::isfinite(dx) || !std::isfinite(dy)) fail(word + "'s offset needs two finite pixel numbers");
  return Vec2(dx, dy);
}

}  // namespace

std::vector<InputEvent> read_input_file(const std::filesystem::path& path) {
  std::istringstream in(read_text_file(path));
  std::vector<InputEvent> out;
  std::string line;
  int number = 0, last_frame = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream ls(line);
    std::string word;
    InputEvent e;
    if (!(ls >> e.frame)) {
      if (ls.clear(), ls >> word) throw ParseError(path.string(), number, "a line starts with a frame number");
      continue;
    }
    auto fail = [&](const std::string& m) { throw ParseError(path.string(), number, m); };
    if (e.frame < 1 || e.frame > 10'000'000) fail("frame must be in [1, 10000000]");
    if (e.frame < last_frame) fail("frames must not go back (" + std::to_string(e.frame) + " after " + std::to_string(last_frame) + ")");
    last_frame = e.frame;
    if (!(ls >> word)) fail("an event is missing after the frame number");
    std::string arg;
    if (word == "move") {
      double x = 0, y = 0;
      if (!(ls >> x >> y) || !std::isfinite(x) || !std::isfinite(y)) fail("move needs two finite pixel coordinates");
      e.kind = InputEvent::Kind::move;
      e.at = Vec2(x, y);
    } else if (word == "move-by") {
      double x = 0, y = 0;
      if (!(ls >> x >> y) || !std::isfinite(x) || !std::isfinite(y)) fail("move-by needs two finite pixel offsets");
      e.kind = InputEvent::Kind::move_by;
      e.at = Vec2(x, y);
    } else if (word == "move-view") {
      // A point of the 3D view, wherever the panels put it: (X, Y) in half-sides (the smaller
      // side) of the view from its centre, Y up (the view's ball spans about -0.9..0.9 after F).
      double x = 0, y = 0;
      if (!(ls >> x >> y) || !std::isfinite(x) || !std::isfinite(y)) fail("move-view needs two finite numbers (half-sides of the view from its centre)");
      e.kind = InputEvent::Kind::move_view;
      e.at = Vec2(x, y);
    } else if (word == "move-to-hint") {
      if (!(ls >> e.vertex) || e.vertex < 1) fail("move-to-hint needs a marker number (1 or more)");
      if (!(ls >> e.text) || (e.text != "marker" && e.text != "target")) fail("move-to-hint N needs marker or target");
      e.kind = InputEvent::Kind::move_to_hint;
      e.at = optional_offset(ls, word, fail);
    } else if (word == "move-to-vertex") {
      // The pointer to where a simulated vertex is on the screen when the event plays (scripts
      // that follow a moving surface), offset by DX DY pixels.
      if (!(ls >> e.vertex) || e.vertex < 0) fail("move-to-vertex needs a vertex number (0 or more)");
      e.kind = InputEvent::Kind::move_to_vertex;
      e.at = optional_offset(ls, word, fail);
    } else if (word == "press" || word == "release") {
      if (!(ls >> arg) || button_of(arg) < 0) fail(word + " needs left, right or middle");
      e.kind = word == "press" ? InputEvent::Kind::press : InputEvent::Kind::release;
      e.button = button_of(arg);
    } else if (word == "scroll") {
      if (!(ls >> e.scroll) || !std::isfinite(e.scroll) || std::abs(e.scroll) > 1000) fail("scroll needs a finite amount");
      e.kind = InputEvent::Kind::scroll;
    } else if (word == "key-down" || word == "key-up" || word == "key") {
      if (!(ls >> arg)) fail(word + " needs a key name");
      std::transform(arg.begin(), arg.end(), arg.begin(), [](unsigned char c) { return std::toupper(c); });
      const auto it = key_names().find(arg);
      if (it == key_names().end()) fail("unknown key '" + arg + "'");
      e.key = it->second;
      e.kind = word == "key-up" ? InputEvent::Kind::key_up : InputEvent::Kind::key_down;
      out.push_back(e);
      if (word == "key") {  // down and up on the same frame: pressed_ keeps it visible
        e.kind = InputEvent::Kind::key_up;
        out.push_back(e);
      }
      continue;
    } else if (word == "open" || word == "shot" || word == "dump") {
      std::getline(ls >> std::ws, e.text);
      while (!e.text.empty() && std::isspace(static_cast<unsigned char>(e.text.back()))) e.text.pop_back();
      if (e.text.empty()) fail(word + " needs a file");
      e.kind = word == "open" ? InputEvent::Kind::open : word == "shot" ? InputEvent::Kind::shot : InputEvent::Kind::dump;
    } else if (word == "type") {  // text typed into the focused field, one character per event
      std::getline(ls >> std::ws, arg);
      if (arg.empty()) fail("type needs the text to type");
      e.kind = InputEvent::Kind::chr;
      for (unsigned char c : arg) {
        e.codepoint = c;
        out.push_back(e);
      }
      continue;
    } else if (word == "quit") {
      e.kind = InputEvent::Kind::quit;
    } else if (word == "wait") {
      e.kind = InputEvent::Kind::wait;
    } else if (word == "wait-time" || word == "wait-sim") {
      // As a person waits for what the instruction says to happen (the sphere to settle): the
      // file's frames stop until the simulation's clock reaches T s (wait-sim: S s more than when
      // the event plays), 60 s of wall time at most.
      if (!(ls >> e.scroll) || !std::isfinite(e.scroll) || e.scroll < 0 || e.scroll > 1e4)
        fail(word + " needs a simulated time in seconds (0 to 10000)");
      e.kind = InputEvent::Kind::wait_time;
      e.text = word;
    } else {
      fail("unknown event '" + word +
           "' (move, move-by, move-view, move-to-hint, move-to-vertex, press, release, scroll, key, key-down, key-up, type, open, shot, dump, "
           "quit, wait, wait-time, wait-sim)");
    }
    if (ls >> arg) fail("unexpected '" + arg + "' at the end of the line");
    out.push_back(e);
  }
  return out;
}

void WindowInput::attach(GLFWwindow* window) {
  window_ = window;
  glfwSetWindowUserPointer(window, this);
  glfwSetCursorPosCallback(window, on_cursor);
  glfwSetMouseButtonCallback(window, on_button);
  glfwSetScrollCallback(window, on_scroll);
  glfwSetKeyCallback(window, on_key);
  glfwSetCharCallback(window, on_char);
  glfwSetWindowFocusCallback(window, on_focus);
  glfwSetCursorEnterCallback(window, on_enter);
  glfwSetDropCallback(window, on_drop);
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  cursor_ = last_cursor_ = Vec2(x, y);
}

void WindowInput::apply(const InputEvent& e) {
  switch (e.kind) {
    case InputEvent::Kind::move: cursor_ = e.at; break;
    case InputEvent::Kind::move_by: cursor_ += e.at; break;
    case InputEvent::Kind::press:
      held_[static_cast<std::size_t>(e.button)] = true;
      pressed_[static_cast<std::size_t>(e.button)] = true;
      break;
    case InputEvent::Kind::release:
      held_[static_cast<std::size_t>(e.button)] = false;
      released_[static_cast<std::size_t>(e.button)] = true;
      break;
    case InputEvent::Kind::scroll: wheel_ += e.scroll; break;
    case InputEvent::Kind::key_down:
      if (!key_down(e.key)) keys_down_.push_back(e.key);
      keys_pressed_.push_back(e.key);
      if (window_) ImGui_ImplGlfw_KeyCallback(window_, e.key, 0, GLFW_PRESS, 0);
      break;
    case InputEvent::Kind::key_up:
      std::erase(keys_down_, e.key);
      if (window_) ImGui_ImplGlfw_KeyCallback(window_, e.key, 0, GLFW_RELEASE, 0);
      break;
    case InputEvent::Kind::chr:
      if (window_) ImGui_ImplGlfw_CharCallback(window_, e.codepoint);
      break;
    default: break;
  }
}

std::vector<InputEvent> WindowInput::begin_frame(int frame) {
  last_cursor_ = cursor_;
  pressed_.fill(false);
  released_.fill(false);
  wheel_ = 0;
  keys_pressed_.clear();
  std::vector<InputEvent> commands;
  std::vector<InputEvent> events;
  events.swap(live_);
  if (!script_.empty()) had_script_ = true;
  // A scripted run on the desktop ignores the real pointer (Xvfb's may sit anywhere) but keeps the
  // keys, typed text and files dropped or chosen (a page's test presses Ctrl+O and picks a file).
  // The page's pointer moves only when someone moves it: its tests touch the screen through it.
  if (had_script_ && !kPageBuild)
    std::erase_if(events, [](const InputEvent& e) {
      using K = InputEvent::Kind;
      return e.kind == K::move || e.kind == K::move_by || e.kind == K::press || e.kind == K::release ||
             e.kind == K::scroll;
    });
  while (!script_.empty() && script_.front().frame <= frame) {
    events.push_back(script_.front());
    script_.pop_front();
  }
  for (const InputEvent& e : events) {
    if (e.kind == InputEvent::Kind::open || e.kind == InputEvent::Kind::shot || e.kind == InputEvent::Kind::dump ||
        e.kind == InputEvent::Kind::quit || e.kind == InputEvent::Kind::wait || e.kind == InputEvent::Kind::move_to_vertex ||
        e.kind == InputEvent::Kind::move_view || e.kind == InputEvent::Kind::move_to_hint ||
        e.kind == InputEvent::Kind::wait_time)
      commands.push_back(e);
    else
      apply(e);
  }
  return commands;
}

void WindowInput::write_to_imgui() const {
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(static_cast<float>(cursor_.x()), static_cast<float>(cursor_.y()));
  for (int b = 0; b < 3; ++b) io.MouseDown[b] = held_[static_cast<std::size_t>(b)] || pressed_[static_cast<std::size_t>(b)];
  io.MouseWheel += static_cast<float>(wheel_);
}

bool WindowInput::key_pressed(int key) const {
  return std::find(keys_pressed_.begin(), keys_pressed_.end(), key) != keys_pressed_.end();
}
bool WindowInput::key_down(int key) const {
  return std::find(keys_down_.begin(), keys_down_.end(), key) != keys_down_.end();
}
bool WindowInput::shift() const { return key_down(GLFW_KEY_LEFT_SHIFT) || key_down(GLFW_KEY_RIGHT_SHIFT); }
bool WindowInput::ctrl() const { return key_down(GLFW_KEY_LEFT_CONTROL) || key_down(GLFW_KEY_RIGHT_CONTROL); }
bool WindowInput::alt() const { return key_down(GLFW_KEY_LEFT_ALT) || key_down(GLFW_KEY_RIGHT_ALT); }

}  // namespace s4d
