#include "shape/shape.hpp"

namespace s4d {

namespace {
Vec4 lift(const Vec3& p) { return {p.x(), p.y(), p.z(), 0.0}; }
}  // namespace

Curve<4> lift_to_4d(const Curve<3>& c) {
  Curve<4> out;
  for (const auto& comp : c.components) {
    Polyline<4> p;
    p.closed = comp.closed;
    p.points.reserve(comp.points.size());
    for (const auto& q : comp.points) p.points.push_back(lift(q));
    out.components.push_back(std::move(p));
  }
  return out;
}

Surface<4> lift_to_4d(const Surface<3>& s) {
  Surface<4> out;
  out.vertices.reserve(s.vertices.size());
  for (const auto& q : s.vertices) out.vertices.push_back(lift(q));
  out.triangles = s.triangles;
  out.grid = s.grid;
  return out;
}

}  // namespace s4d
