// Whether two segments of the plane cross at interior points of both: the test behind every
// crossing a sketch makes (knots/sketch, knots/sketch_link).
#pragma once
#include "core/vec.hpp"

namespace s4d {

// True when p0p1 and q0q1 cross strictly inside both; s and t are then the crossing's parameters
// along each (p0 + s (p1 - p0) = q0 + t (q1 - q0)). Parallel segments never cross.
inline bool segments_cross(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1, double& s, double& t) {
  const Vec2 r = p1 - p0, d = q1 - q0, w = q0 - p0;
  const double den = r.x() * d.y() - r.y() * d.x();
  if (den == 0) return false;
  s = (w.x() * d.y() - w.y() * d.x()) / den;
  t = (w.x() * r.y() - w.y() * r.x()) / den;
  return s > 0 && s < 1 && t > 0 && t < 1;
}

}  // namespace s4d
