#include "interact/knot_sketch_tool.hpp"

#include <cmath>

#include "core/error.hpp"
#include "interact/session.hpp"

namespace s4d {

SketchPlane::SketchPlane(const Camera& camera) {
  const Eigen::Quaterniond q = camera.orientation.normalized();
  centre = camera.target;
  right = q * Vec3::UnitX();
  up = q * Vec3::UnitY();
  toward_eye = q * Vec3::UnitZ();
}

bool SketchPlane::cursor_to_plane(const Camera& camera, const Vec2& cursor, const Vec2& window,
                                  Vec2& at) const {
  if (!(window.x() > 0 && window.y() > 0) || !cursor.allFinite()) return false;
  // The line of sight in eye coordinates (the eye looks down -z), then in the world.
  const double t = std::tan(camera.fov_y / 2);
  const Vec3 d_eye(camera.aspect * t * (2 * cursor.x() / window.x() - 1), t * (1 - 2 * cursor.y() / window.y()), -1);
  const Vec3 dir = camera.orientation.normalized() * d_eye;
  const Vec3 eye = camera.eye();
  const double denom = dir.dot(toward_eye);
  if (!(std::abs(denom) > 1e-12)) return false;
  const double s = (centre - eye).dot(toward_eye) / denom;
  if (!(s > 0) || !std::isfinite(s)) return false;
  const Vec3 p = eye + s * dir - centre;
  at = Vec2(p.dot(right), p.dot(up));
  return true;
}

void SketchTool::begin(const Camera& camera, const Vec2& cursor, const Vec2& window, double time, bool under) {
  cancel();
  camera_ = camera;
  plane_ = SketchPlane(camera);
  add(cursor, window, time, under);
}

void SketchTool::add(const Vec2& cursor, const Vec2& window, double time, bool under) {
  Vec2 at;
  if (!plane_.cursor_to_plane(camera_, cursor, window, at)) return;
  if (!stroke_.empty() && (at == stroke_.back().at || time < stroke_.back().time)) return;
  const double t0 = stroke_.empty() ? time : stroke_.front().time;
  stroke_.push_back({at, time - t0, under});
  screen_.emplace_back(cursor, under);
}

Curve<3> SketchTool::finish() {
  last_ = std::move(stroke_);
  cancel();
  // Objects of R^3 are drawn as they are, so the knot's points are where they were drawn.
  SketchedKnot k = knot_from_sketch(last_);
  for (Vec3& p : k.curve.components[0].points) p = plane_.to_shadow(p);
  return k.curve;
}

void SketchTool::cancel() {
  stroke_.clear();
  screen_.clear();
}

std::string KnotSketchTool::help() const {
  return "sketch: drag to draw a closed curve; hold shift where it passes under; Esc stops";
}

bool KnotSketchTool::press(const ToolInput& in, Session& s) {
  stroke_.begin(in.view.camera, in.view.cursor, in.view.window, in.time, in.shift);
  return true;
}

void KnotSketchTool::drag(const ToolInput& in, Session& s) {
  if (stroke_.drawing()) stroke_.add(in.view.cursor, in.view.window, in.time, in.shift);
}

void KnotSketchTool::release(const ToolInput& in, Session& s) {
  if (!stroke_.drawing()) return;
  if (stroke_.screen().size() < 3) {
    stroke_.cancel();
    message_ = "a click is not a stroke; " + help();
    return;
  }
  SceneObject obj;
  try {
    obj.shape = stroke_.finish();
  } catch (const std::exception& e) {
    message_ = std::string("no knot: ") + e.what();
    return;
  }
  int n = 1;
  for (const SceneObject& o : s.scene().objects) n += o.name.rfind("sketch-", 0) == 0;
  obj.name = "sketch-" + std::to_string(n);
  s.record("sketch a knot");
  s.scene().objects.push_back(std::move(obj));
  s.scene().view.intersections = true;  // its crossings and Gauss code
  message_ = "sketched " + s.scene().objects.back().name + "; " + help();
}

bool KnotSketchTool::key(ToolKey k, const ToolInput&, Session&) {
  if (k != ToolKey::kEscape || !stroke_.drawing()) return false;
  stroke_.cancel();
  message_ = "stroke dropped";
  return true;
}

// The stroke so far: white where it passes over, blue where under.
void KnotSketchTool::overlay(Overlay& o, const Session&) const {
  const auto& pts = stroke_.screen();
  for (std::size_t i = 1; i < pts.size(); ++i)
    o.screen_lines.push_back({pts[i - 1].first, pts[i].first,
                              pts[i].second ? overlay_colour(0.35, 0.6, 1) : overlay_colour(0.95, 0.95, 0.95), 3});
}

}  // namespace s4d
