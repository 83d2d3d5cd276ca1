// Tangents and rotation-minimising normals of 3D polylines (see polyline_ops.hpp).
#include "shape/polyline_ops.hpp"

namespace s4d {

std::vector<Vec3> polyline_tangents(const std::vector<Vec3>& points, bool closed) {
  const std::size_t n = points.size();
  if (n < 2) throw Error("a polyline needs two points to have tangents");
  std::vector<Vec3> t(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& prev = (i > 0) ? points[i - 1] : (closed ? points[n - 1] : points[i]);
    const Vec3& next = (i + 1 < n) ? points[i + 1] : (closed ? points[0] : points[i]);
    const Vec3 d = next - prev;
    const double len = d.norm();
    if (!(len > 0)) throw Error("a polyline has repeated points, so no tangent is defined there");
    t[i] = d / len;
  }
  return t;
}

std::vector<Vec3> rotation_minimising_normals(const std::vector<Vec3>& points, bool closed,
                                              const Vec3& initial) {
  const std::vector<Vec3> t = polyline_tangents(points, closed);
  std::vector<Vec3> r(points.size());
  Vec3 r0 = initial - initial.dot(t[0]) * t[0];
  if (!(r0.norm() > 1e-9 * initial.norm()))
    throw Error("the initial ribbon normal is parallel to the curve's first tangent");
  r[0] = r0.normalized();
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    // Reflect across the bisector plane of the step, then across the plane that takes the
    // reflected tangent onto the next tangent: the composition is the RMF's rotation.
    const Vec3 v1 = points[i + 1] - points[i];
    const double c1 = v1.squaredNorm();
    const Vec3 rl = r[i] - (2.0 / c1) * v1.dot(r[i]) * v1;
    const Vec3 tl = t[i] - (2.0 / c1) * v1.dot(t[i]) * v1;
    const Vec3 v2 = t[i + 1] - tl;
    const double c2 = v2.squaredNorm();
    Vec3 next = c2 > 1e-300 ? Vec3(rl - (2.0 / c2) * v2.dot(rl) * v2) : rl;
    // Keep exactly unit and perpendicular: rounding would otherwise drift over thousands of steps.
    next -= next.dot(t[i + 1]) * t[i + 1];
    r[i + 1] = next.normalized();
  }
  return r;
}

}  // namespace s4d
