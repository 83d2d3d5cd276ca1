// The ribbon tool's stroke: samples on the drawing plane (or at the device's point), the ribbon
// built on release, the scene and its simulation extended.
#include "interact/tools/ribbon_tool.hpp"

#include <cmath>
#include <cstdio>

#include "interact/session/session.hpp"

namespace s4d {

std::string RibbonTool::help() const {
  return "sketch a ribbon: drag its centre line; hold shift where it should pass below what it crosses (above "
         "otherwise); wheel: drawing depth; Esc stops";
}

void RibbonTool::add(const Vec3& p, double time, bool under) {
  if (!p.allFinite()) return;
  if (!stroke_.empty() && ((p - stroke_.back().at).norm() < 1e-12 || time - t0_ < stroke_.back().time)) return;
  stroke_.push_back({p, time - t0_, under});
}

bool RibbonTool::press(const ToolInput& in, Session& s) {
  stroke_.clear();
  t0_ = in.time;
  add(in.view.on_plane_through(in.view.centre + depth_ * in.view.toward_eye), in.time, in.shift);
  return true;
}

void RibbonTool::drag(const ToolInput& in, Session& s) {
  if (!device_drawing_) add(in.view.on_plane_through(in.view.centre + depth_ * in.view.toward_eye), in.time, in.shift);
}

void RibbonTool::release(const ToolInput& in, Session& s) {
  if (device_drawing_) return;
  std::vector<RibbonStrokeSample> stroke;
  stroke.swap(stroke_);
  finish(stroke, in.view.toward_eye, in.view.pixel_size * in.view.window.y(), s);
}

bool RibbonTool::finish(const std::vector<RibbonStrokeSample>& stroke, const Vec3& toward_eye, double view_size,
                        Session& s) {
  last_stroke_ = stroke;
  if (stroke.size() < 3) {
    message_ = "a click is not a stroke; drag the ribbon's centre line";
    return false;
  }
  RibbonSketchOptions o = options;
  if (!(o.width > 0)) o.width = 0.04 * view_size;  // a ribbon a twenty-fifth of the view wide
  // A stroke that comes back to where it began is a loop, as a knot's stroke closes there.
  double length = 0;
  for (std::size_t i = 1; i < stroke.size(); ++i) length += (stroke[i].at - stroke[i - 1].at).norm();
  const double gap = (stroke.back().at - stroke.front().at).norm();
  const bool came_back = !o.closed && gap <= 1.5 * o.width && length > 6 * o.width;
  if (came_back) o.closed = true;
  try {
    const SketchObstacles obstacles = sketch_obstacles(s.scene());
    const SketchedRibbon r = ribbon_from_sketch(stroke, obstacles.surfaces, s.scene().frame, toward_eye, o, obstacles.names);
    s.record("sketch a ribbon");
    const std::string name = add_sketched_ribbon(s.scene(), r);
    last_ = r;
    made_ = true;
    int below = 0;
    for (const RibbonPassage& p : r.passages) below += p.below;
    char b[256];
    std::snprintf(b, sizeof b, "sketched %s%s: %zu passage(s), %zu above and %d below in w; simulating it", name.c_str(),
                  came_back ? " (a loop: the stroke came back to its start)" : "", r.passages.size(),
                  r.passages.size() - static_cast<std::size_t>(below), below);
    message_ = b;
    finished_ = true;
    s.objects_changed();  // the bodies there keep their motion and pins
    return true;
  } catch (const std::exception& e) {
    message_ = std::string("no ribbon: ") + e.what();
    return false;
  }
}

bool RibbonTool::wheel(double steps, const ToolInput& in, Session& s) {
  if (!std::isfinite(steps)) return false;
  depth_ += steps * 20 * in.view.pixel_size;
  char b[96];
  std::snprintf(b, sizeof b, "drawing plane %.3g in front of the view's centre", depth_);
  message_ = b;
  return true;
}

bool RibbonTool::key(ToolKey k, const ToolInput& in, Session& s) {
  if (k == ToolKey::kEscape && drawing()) {
    stroke_.clear();
    message_ = "stroke dropped";
    return true;
  }
  return false;
}

// A device draws where its point is, in 3D, while its first button is held.
void RibbonTool::update(const ToolInput& in, Session& s) {
  const HapticSnapshot* snap = s.snapshot();
  if (!snap || std::string_view(snap->device_name) == "mouse") return;
  const bool down = snap->device.buttons & 1u;
  const Vec3 p = s.mapping().to_shadow(snap->device.position);
  if (down && !device_drawing_) {
    device_drawing_ = true;
    stroke_.clear();
    t0_ = in.time;
  }
  if (down) add(p, in.time, (snap->device.buttons & 2u) != 0 || in.shift);
  if (!down && device_drawing_) {
    device_drawing_ = false;
    std::vector<RibbonStrokeSample> stroke;
    stroke.swap(stroke_);
    finish(stroke, in.view.toward_eye, in.view.pixel_size * in.view.window.y(), s);
  }
}

void RibbonTool::overlay(Overlay& o, const Session& s) const {
  for (std::size_t i = 1; i < stroke_.size(); ++i)
    o.lines.push_back({stroke_[i - 1].at, stroke_[i].at,
                       stroke_[i].under ? overlay_colour(0.35, 0.6, 1) : overlay_colour(0.95, 0.95, 0.95), 3});
  if (!made_ || drawing()) return;
  for (const RibbonPassage& p : last_.passages)
    o.dots.push_back({p.place, p.below ? overlay_colour(0.25, 0.45, 1) : overlay_colour(0.95, 0.25, 0.2), 6, true});
}

}  // namespace s4d
