#include "app/sketch_tool.hpp"

#include <cmath>

#include "core/error.hpp"

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

}  // namespace s4d
