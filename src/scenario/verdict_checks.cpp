// Knot checks on ribbon centre lines (through the knot engine) and mesh components.
#include "scenario/verdict_checks.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "core/frame.hpp"
#include "core/plane.hpp"
#include "knots/knot_diagram.hpp"
#include "knots/knot_invariants.hpp"
#include "proximity/shadow_crossings.hpp"
#include "proximity/shadow_intersections.hpp"

namespace s4d {

std::vector<Vec3> ribbon_centre_line(const std::vector<Vec4>& x, const Grid& grid) {
  std::vector<Vec3> c;
  for (int i = 0; i < grid.rows; ++i) {
    Vec4 s = Vec4::Zero();
    for (int j = 0; j < grid.cols; ++j) s += x[grid.index(i, j)];
    c.push_back((s / grid.cols).head<3>());
  }
  return c;
}

namespace {

// A few views: the three axis views and two oblique ones (generic for our shapes).
std::vector<Frame<3>> views() {
  std::vector<Frame<3>> v(5);
  v[1].rotate(Plane{1, 2}, 1.5707963267948966);  // look along y
  v[2].rotate(Plane{0, 2}, 1.5707963267948966);  // look along x
  v[3].rotate(Plane{0, 2}, 0.37);
  v[3].rotate(Plane{1, 2}, 0.61);
  v[4].rotate(Plane{0, 1}, 0.93);
  v[4].rotate(Plane{1, 2}, -0.47);
  return v;
}

}  // namespace

KnotCheck check_knot(const std::vector<Vec3>& centre, const Vec3& via, const Vec3& along) {
  KnotCheck k;
  if (centre.size() < 4) {
    k.error = "centre line too short";
    return k;
  }
  // Close far away: beyond every crossing the knot could have, so the closure adds none.
  Vec3 lo = centre[0], hi = centre[0];
  for (const Vec3& p : centre) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double far = 4 * (hi - lo).norm() + 1;
  const std::size_t n = centre.size();
  const Vec3 da = (centre[0] - centre[std::min<std::size_t>(3, n - 1)]).normalized();
  const Vec3 db = (centre[n - 1] - centre[n - 1 - std::min<std::size_t>(3, n - 1)]).normalized();
  Polyline<3> closed;
  closed.closed = true;
  closed.points = centre;
  const Vec3 eb = centre[n - 1] + far * db, ea = centre[0] + far * da;
  const Vec3 mid = 0.5 * (ea + eb) + far * via.normalized();
  closed.points.push_back(eb);
  closed.points.push_back(eb + far * via.normalized());
  closed.points.push_back(mid);
  closed.points.push_back(ea + far * via.normalized());
  closed.points.push_back(ea);
  Curve<3> curve;
  curve.components.push_back(closed);
  Curve<3> open;
  open.components.push_back(Polyline<3>{centre, false});

  k.min_crossings = 1 << 30;
  for (const Frame<3>& f : views()) {
    const int c = static_cast<int>(shadow_crossings<3>(curve, f).crossings.size());
    k.min_crossings = std::min(k.min_crossings, c);
    k.max_crossings = std::max(k.max_crossings, c);
    if (std::abs(f.axis(2).dot(along.normalized())) > 0.866) continue;
    k.open_crossings = std::max(k.open_crossings,
                                static_cast<int>(shadow_crossings<3>(open, f).crossings.size()));
  }
  try {
    const KnotDiagram d = diagram_from_curve(curve, views()[3]);
    const KnotInvariants inv = compute_invariants(d);
    k.determinant = static_cast<long>(inv.determinant);
    k.simplified_crossings = inv.simplified_crossings;
    k.fingerprint = std::min(inv.fingerprint, inv.mirror_fingerprint);
  } catch (const Error& e) {
    k.error = e.what();
  }
  return k;
}

ShadowCheck check_shadow(const Surface<4>& surface, const std::string& view) {
  Frame<4> frame;
  apply_rotations(frame, parse_rotation_list(view, 4));
  const ShadowIntersections si = shadow_intersections(surface, frame);
  ShadowCheck c;
  c.total_length = si.total_length;
  c.segments = static_cast<int>(si.segments.size());
  c.curves = static_cast<int>(si.curves.size());
  c.true_curves = si.true_curves;
  c.coplanar_pairs = si.coplanar_pairs;
  return c;
}

std::vector<int> vertex_components(int nv, const std::vector<Triangle>& tris, int* count) {
  std::vector<int> parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (const Triangle& t : tris) {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  std::vector<int> label(nv, -1), root_label(nv, -1);
  int k = 0;
  for (int v = 0; v < nv; ++v) {
    const int r = find(v);
    if (root_label[r] < 0) root_label[r] = k++;
    label[v] = root_label[r];
  }
  *count = k;
  return label;
}

}  // namespace s4d
