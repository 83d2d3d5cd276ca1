// The ribbon tool's stroke: samples on the drawing plane (or at the device's point), the ribbon
// built on release, the scene and its simulation extended.
#include "interact/tools/ribbon_tool.hpp"

#include <cmath>
#include <cstdio>

#include "interact/session/session.hpp"

namespace s4d {

std::string RibbonTool::help() const {
  if (!kept_.stroke.empty() && !drawing())
    return "the stroke made no ribbon and is kept: [ ] narrow or widen the ribbon (or the Ribbon panel), Enter tries "
           "it again, Esc drops it; or draw it again";
  return "sketch a ribbon: drag its centre line; hold shift where it should pass below what it crosses (above "
         "otherwise); wheel: drawing depth; [ ] its width; Esc stops";
}

void RibbonTool::add(const Vec3& p, double time, bool under) {
  if (!p.allFinite()) return;
  if (!stroke_.empty() && ((p - stroke_.back().at).norm() < 1e-12 || time - t0_ < stroke_.back().time)) return;
  stroke_.push_back({p, time - t0_, under});
}

bool RibbonTool::press(const ToolInput& in, Session& s) {
  stroke_.clear();
  drop_kept();  // a new stroke replaces the one kept
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
  const double width = options.width > 0 ? options.width : 0.04 * view_size;
  return build({stroke, toward_eye, view_size, !options.closed && ribbon_stroke_comes_back(stroke, width)}, s);
}

bool RibbonTool::retry(Session& s) {
  if (kept_.stroke.empty()) return false;
  const Attempt a = kept_;
  return build(a, s);
}

void RibbonTool::drop_kept() {
  kept_ = {};
  fold_at_.reset();
  suggested_width_ = 0;
  refusal_.clear();
}

bool RibbonTool::build(const Attempt& a, Session& s) {
  RibbonSketchOptions o = options;
  if (!(o.width > 0)) o.width = 0.04 * a.view_size;  // a ribbon a twenty-fifth of the view wide
  if (a.came_back) o.closed = true;
  last_width_ = o.width;
  try {
    const SketchObstacles obstacles = sketch_obstacles(s.scene());
    const SketchedRibbon r = ribbon_from_sketch(a.stroke, obstacles.surfaces, s.scene().frame, a.toward_eye, o,
                                                obstacles.names);
    s.record("sketch a ribbon");
    const std::string name = add_sketched_ribbon(s.scene(), r);
    last_ = r;
    made_ = true;
    drop_kept();
    int below = 0;
    for (const RibbonPassage& p : r.passages) below += p.below;
    char b[256];
    std::snprintf(b, sizeof b, "sketched %s%s: %zu passage(s), %zu above and %d below in w; simulating it", name.c_str(),
                  a.came_back ? " (a loop: the stroke came back to its start)" : "", r.passages.size(),
                  r.passages.size() - static_cast<std::size_t>(below), below);
    message_ = b;
    if (!r.changes.empty()) message_ += "; " + r.changes;
    finished_ = true;
    s.objects_changed();  // the bodies there keep their motion and pins
    return true;
  } catch (const std::exception& e) {
    // Kept, drawn where it was, so that a changed width (or the same after a turn of the view)
    // can try it again without drawing it anew.
    kept_ = a;
    const auto* fold = dynamic_cast<const RibbonFoldError*>(&e);
    fold_at_ = fold ? std::optional<Vec3>(fold->place) : std::nullopt;
    suggested_width_ = fold ? fold->widest : 0;
    refusal_ = e.what();
    message_ = std::string("no ribbon: ") + e.what() +
               ". The stroke is kept: change the width ([ ] or the Ribbon panel) and press Enter to try it again, "
               "or draw it again; Esc drops it";
    return false;
  }
}

void RibbonTool::set_width(double w, Session& s) {
  if (!(w > 0) || !std::isfinite(w)) return;
  s.record("change the ribbon's width");
  options.width = w;
  char b[160];
  std::snprintf(b, sizeof b, "ribbon width %.3g%s", w,
                kept_.stroke.empty() ? "" : " (Enter tries the kept stroke with it)");
  message_ = b;
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
  if (k == ToolKey::kEscape && !kept_.stroke.empty()) {
    drop_kept();
    message_ = "the kept stroke is dropped";
    return true;
  }
  if (k == ToolKey::kEnter && !kept_.stroke.empty() && !drawing()) {
    retry(s);
    return true;
  }
  if ((k == ToolKey::kSmaller || k == ToolKey::kLarger) && !drawing()) {
    const double now = options.width > 0 ? options.width
                       : last_width_ > 0  ? last_width_
                                          : 0.04 * in.view.pixel_size * in.view.window.y();
    set_width(now * (k == ToolKey::kLarger ? 1.25 : 0.8), s);
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
  if (drawing()) return;
  // The kept stroke in orange, its fold ringed.
  const std::vector<RibbonStrokeSample>& k = kept_.stroke;
  for (std::size_t i = 1; i < k.size(); ++i)
    o.lines.push_back({k[i - 1].at, k[i].at, k[i].under ? overlay_colour(0.35, 0.6, 1) : overlay_colour(1, 0.6, 0.15), 3});
  if (!k.empty() && kept_.came_back) o.lines.push_back({k.back().at, k.front().at, overlay_colour(1, 0.6, 0.15, 0.5), 2});
  if (fold_at_) o.dots.push_back({*fold_at_, overlay_colour(1, 0.2, 0.2), 12, false});
  if (!made_ || !k.empty()) return;
  for (const RibbonPassage& p : last_.passages)
    o.dots.push_back({p.place, p.below ? overlay_colour(0.25, 0.45, 1) : overlay_colour(0.95, 0.25, 0.2), 6, true});
}

}  // namespace s4d
