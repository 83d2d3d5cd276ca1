// Tool: the one shape every shadow-space tool has (docs/architecture.md). The window hands
// the active tool the mouse as a view ray (press / drag / release / hover, keys and the wheel);
// a device reaches the same tools through the haptic loop. A tool acts on the Session — it
// sends commands to the live simulation or changes the document — and draws its overlay.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/camera.hpp"
#include "core/frame.hpp"
#include "core/vec.hpp"
#include "interact/live/device_mapping.hpp"

namespace s4d {

class Session;

// Where the hand is, as the camera sees it, in shadow space (scene units).
struct ToolView {
  Vec3 eye = Vec3(0, 0, 5);
  Vec3 ray = Vec3(0, 0, -1);  // unit, from the eye through the cursor
  Vec3 right = Vec3::UnitX(), up = Vec3::UnitY(), toward_eye = Vec3::UnitZ();  // the camera's axes
  Vec3 centre = Vec3::Zero();  // the point the camera looks at
  double pixel_size = 0.01;    // scene units per pixel at the centre's depth
  Vec2 cursor = Vec2::Zero();  // pixels, y down
  Vec2 window = Vec2(1, 1);    // pixels
  Frame<4> frame;              // how objects of R^4 are seen (their shadow)
  Camera camera;               // the view itself (for tools that work on the screen's image)

  // Where the ray meets the plane through `point` facing the eye (the point itself when the ray
  // runs along the plane).
  Vec3 on_plane_through(const Vec3& point) const {
    const double den = ray.dot(toward_eye);
    if (std::abs(den) < 1e-12) return point;
    const double t = (point - eye).dot(toward_eye) / den;
    return t > 0 ? Vec3(eye + t * ray) : point;
  }
};

struct ToolInput {
  ToolView view;
  bool shift = false, ctrl = false, alt = false;
  double time = 0;  // s, the window's clock
};

// kUndo / kRedo: Ctrl+Z / Ctrl+Shift+Z, offered to the tool first, so that work it holds and has
// not yet made a step of the history (strokes not finished) is undone piece by piece, not lost.
enum class ToolKey { kTab, kPin, kEscape, kBackspace, kEnter, kUndo, kRedo,
                     kCarry, kSmaller, kLarger };  // C, [ and ]: the Touch tool's carry and its radius

// What a tool draws over the picture: in shadow space (projected by the window) or in pixels.
struct Overlay {
  struct Line {
    Vec3 a, b;
    std::uint32_t rgba;
    float width;
  };
  struct Dot {
    Vec3 at;
    std::uint32_t rgba;
    float radius;  // pixels
    bool filled;
  };
  struct ScreenLine {
    Vec2 a, b;
    std::uint32_t rgba;
    float width;
  };
  std::vector<Line> lines;
  std::vector<Dot> dots;
  std::vector<ScreenLine> screen_lines;
};

// 0xAABBGGRR as Dear ImGui packs it, from components in [0, 1].
inline std::uint32_t overlay_colour(double r, double g, double b, double a = 1) {
  auto c = [](double v) { return static_cast<std::uint32_t>(std::clamp(v, 0.0, 1.0) * 255 + 0.5); };
  return c(r) | (c(g) << 8) | (c(b) << 16) | (c(a) << 24);
}


class Tool {
 public:
  virtual ~Tool() = default;
  virtual const char* name() const = 0;
  // One line for the status bar: what the buttons and keys do now.
  virtual std::string help() const = 0;

  // The left button. press returns true when the tool takes the drag (false: the view turns).
  virtual bool press(const ToolInput&, Session&) { return false; }
  virtual void drag(const ToolInput&, Session&) {}
  virtual void release(const ToolInput&, Session&) {}
  // The cursor over the view with no button held (also while a drag is elsewhere: not called).
  virtual void hover(const ToolInput&, Session&) {}
  // True when consumed (the right button, a key, the wheel; unconsumed wheel zooms).
  virtual bool right_click(const ToolInput&, Session&) { return false; }
  virtual bool key(ToolKey, const ToolInput&, Session&) { return false; }
  virtual bool wheel(double steps, const ToolInput&, Session&) { return false; }
  // Each frame, after the session's refresh: keep up with the simulation (the device's point).
  virtual void update(const ToolInput&, Session&) {}
  virtual DeviceButton device_button() const { return DeviceButton::kNone; }
  // With kGrab: the rings of the patch a device's button carries (0: the rubber band).
  virtual int device_carry_rings() const { return 0; }
  virtual void overlay(Overlay&, const Session&) const {}
  // A status message for the window (what just happened), taken once.
  std::string take_message() { return std::exchange(message_, std::string()); }
  // True once after the tool made what it was chosen for (a sketch finished): the window then
  // returns to Touch and frames the new object.
  bool take_finished() { return std::exchange(finished_, false); }

 protected:
  std::string message_;
  bool finished_ = false;
};

}  // namespace s4d
