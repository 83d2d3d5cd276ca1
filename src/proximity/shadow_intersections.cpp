// Finder (b): triangle-triangle intersection segments of a surface's 3D shadow, with 4D depths,
// chained into curves (see shadow_intersections.hpp).
#include "proximity/shadow_intersections.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>

#include "proximity/bvh.hpp"
#include "proximity/self_intersections.hpp"

namespace s4d {

namespace {

struct ShadowMesh {
  std::vector<Vec3> x;      // nv × 3, shadow coordinates
  std::vector<double> w;    // nv, 4D depth
  const std::vector<Triangle>* tris = nullptr;
  std::vector<Box<3>> boxes;
  Frame<4> frame;           // reads the depth at a point of a shadow triangle (perspective-correct)
};

ShadowMesh project(const Surface<4>& s, const Frame<4>& f) {
  ShadowMesh m;
  m.x.reserve(s.vertices.size());
  m.w.reserve(s.vertices.size());
  for (const auto& v : s.vertices) {
    m.x.push_back(f.shadow(v));
    m.w.push_back(f.depth(v));
  }
  m.tris = &s.triangles;
  m.frame = f;
  m.boxes.reserve(s.triangles.size());
  for (const auto& t : s.triangles) {
    Box<3> b;
    for (int v : t) b.add(m.x[v]);
    m.boxes.push_back(b);
  }
  return m;
}

// The part of triangle T on the plane n·p = c: a segment, as its two end points with the
// barycentric weights of each. False when T misses the plane or lies in it (`coplanar`).
// Signed distances within rounding of zero are snapped to zero, so triangles that are coplanar
// in the shadow (every flat piece of a surface) are recognised as such, not cut by noise.
struct Cut {
  Vec3 e[2];
  std::array<double, 3> bary[2];
};
bool cut_by_plane(const std::array<Vec3, 3>& x, const Vec3& n, double c, double eps, Cut& cut,
                  bool& coplanar) {
  std::array<double, 3> d;
  for (int i = 0; i < 3; ++i) {
    d[i] = n.dot(x[i]) - c;
    if (std::abs(d[i]) <= eps) d[i] = 0;
  }
  coplanar = d[0] == 0 && d[1] == 0 && d[2] == 0;
  if (coplanar) return false;
  if ((d[0] > 0 && d[1] > 0 && d[2] > 0) || (d[0] < 0 && d[1] < 0 && d[2] < 0)) return false;
  int k = 0;
  for (int i = 0; i < 3 && k < 2; ++i) {
    const int j = (i + 1) % 3;
    if (d[i] == 0) {  // vertex on the plane
      cut.e[k] = x[i];
      cut.bary[k] = {0, 0, 0};
      cut.bary[k][i] = 1;
      ++k;
    } else if ((d[i] < 0 && d[j] > 0) || (d[i] > 0 && d[j] < 0)) {  // edge crosses it
      const double t = d[i] / (d[i] - d[j]);
      cut.e[k] = x[i] + t * (x[j] - x[i]);
      cut.bary[k] = {0, 0, 0};
      cut.bary[k][i] = 1 - t;
      cut.bary[k][j] = t;
      ++k;
    }
  }
  if (k == 1) {  // touches at a single vertex
    cut.e[1] = cut.e[0];
    cut.bary[1] = cut.bary[0];
  }
  return k >= 1;
}

// Do two coplanar triangles overlap with positive area? Separating axis test in the plane
// (drop the normal's largest coordinate), the six edge normals as candidate axes.
bool coplanar_overlap(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b, const Vec3& n) {
  int drop = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[drop])) drop = k;
  const int i0 = drop == 0 ? 1 : 0, i1 = drop == 2 ? 1 : 2;
  std::array<Vec2, 3> p, q;
  for (int k = 0; k < 3; ++k) {
    p[k] = Vec2(a[k][i0], a[k][i1]);
    q[k] = Vec2(b[k][i0], b[k][i1]);
  }
  for (const auto* t : {&p, &q})
    for (int e = 0; e < 3; ++e) {
      const Vec2 d = (*t)[(e + 1) % 3] - (*t)[e];
      const Vec2 axis(-d.y(), d.x());
      double pmin = 1e300, pmax = -1e300, qmin = 1e300, qmax = -1e300;
      for (int k = 0; k < 3; ++k) {
        pmin = std::min(pmin, axis.dot(p[k]));
        pmax = std::max(pmax, axis.dot(p[k]));
        qmin = std::min(qmin, axis.dot(q[k]));
        qmax = std::max(qmax, axis.dot(q[k]));
      }
      const double slack = 1e-12 * (pmax - pmin + qmax - qmin);
      if (pmax <= qmin + slack || qmax <= pmin + slack) return false;
    }
  return true;
}

std::array<double, 3> lerp(const std::array<double, 3>& a, const std::array<double, 3>& b,
                           double t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

// Intersection segment of the shadows of triangle ia of `ma` and ib of `mb`.
void intersect_pair(const ShadowMesh& ma, int ia, const ShadowMesh& mb, int ib,
                    ShadowIntersections& out) {
  const Triangle& ta = (*ma.tris)[ia];
  const Triangle& tb = (*mb.tris)[ib];
  const std::array<Vec3, 3> xa{ma.x[ta[0]], ma.x[ta[1]], ma.x[ta[2]]};
  const std::array<Vec3, 3> xb{mb.x[tb[0]], mb.x[tb[1]], mb.x[tb[2]]};
  const std::array<double, 3> wa{ma.w[ta[0]], ma.w[ta[1]], ma.w[ta[2]]};
  const std::array<double, 3> wb{mb.w[tb[0]], mb.w[tb[1]], mb.w[tb[2]]};
  const Vec3 na = (xa[1] - xa[0]).cross(xa[2] - xa[0]);
  const Vec3 nb = (xb[1] - xb[0]).cross(xb[2] - xb[0]);
  if (!(na.squaredNorm() > 0) || !(nb.squaredNorm() > 0)) return;  // shadow seen edge-on
  double scale = 0;
  for (int k = 0; k < 3; ++k) scale = std::max({scale, xa[k].lpNorm<Eigen::Infinity>(),
                                                xb[k].lpNorm<Eigen::Infinity>()});
  constexpr double kRound = 64 * std::numeric_limits<double>::epsilon();
  Cut ca, cb;
  bool cop_a = false, cop_b = false;
  if (!cut_by_plane(xa, nb, nb.dot(xb[0]), kRound * nb.norm() * scale, ca, cop_a)) {
    if (cop_a && coplanar_overlap(xa, xb, nb)) ++out.coplanar_pairs;
    return;
  }
  if (!cut_by_plane(xb, na, na.dot(xa[0]), kRound * na.norm() * scale, cb, cop_b)) return;
  // Both cuts lie on the line where the two planes meet; overlap their intervals along it.
  const Vec3 dir = na.cross(nb);
  if (!(dir.squaredNorm() > 0)) return;
  const double a0 = dir.dot(ca.e[0]), a1 = dir.dot(ca.e[1]);
  const double b0 = dir.dot(cb.e[0]), b1 = dir.dot(cb.e[1]);
  const double lo = std::max(std::min(a0, a1), std::min(b0, b1));
  const double hi = std::min(std::max(a0, a1), std::max(b0, b1));
  if (!(hi > lo)) return;  // disjoint, or touching at a single point (no length)
  ShadowSegment seg;
  seg.a = ia;
  seg.b = ib;
  const double values[2] = {lo, hi};
  for (int k = 0; k < 2; ++k) {
    const double ua = a1 != a0 ? (values[k] - a0) / (a1 - a0) : 0.0;
    const double ub = b1 != b0 ? (values[k] - b0) / (b1 - b0) : 0.0;
    const std::array<double, 3> ba = lerp(ca.bary[0], ca.bary[1], ua);
    const std::array<double, 3> bb = lerp(cb.bary[0], cb.bary[1], ub);
    const Vec3 p = ca.e[0] + ua * (ca.e[1] - ca.e[0]);
    (k == 0 ? seg.p0 : seg.p1) = p;
    (k == 0 ? seg.depth_a0 : seg.depth_a1) = ma.frame.depth_at(ba, wa);
    (k == 0 ? seg.depth_b0 : seg.depth_b1) = mb.frame.depth_at(bb, wb);
  }
  // The depth difference is linear along the segment (nearly, in perspective); a sign change is a true 4D meeting.
  const double f0 = seg.depth_a0 - seg.depth_b0, f1 = seg.depth_a1 - seg.depth_b1;
  if ((f0 <= 0 && f1 >= 0) || (f0 >= 0 && f1 <= 0)) {
    seg.true_intersection = true;
    const double t = f0 != f1 ? f0 / (f0 - f1) : 0.5;
    seg.meet = seg.p0 + t * (seg.p1 - seg.p0);
  }
  out.segments.push_back(seg);
}

// Walks the segments into strokes: from every end or branch node (degree other than 2) along
// nodes of degree 2, then once around each loop left. node[2s + k] is the node of segment s's
// end k (-1: an end of its own); joints take their node's representative, so that neighbouring
// segments meet exactly.
void walk_strokes(ShadowIntersections& r, const std::vector<int>& node, const std::vector<int>& degree,
                  const std::vector<Vec3>& reps) {
  const int ns = static_cast<int>(r.segments.size());
  std::vector<int> offset(reps.size() + 1, 0), incident(2 * static_cast<std::size_t>(ns));
  for (int e = 0; e < 2 * ns; ++e)
    if (node[e] >= 0) ++offset[node[e] + 1];
  for (std::size_t n = 0; n < reps.size(); ++n) offset[n + 1] += offset[n];
  std::vector<int> fill(offset.begin(), offset.end() - 1);
  for (int e = 0; e < 2 * ns; ++e)
    if (node[e] >= 0) incident[fill[node[e]]++] = e;
  auto end_point = [&](int e) {
    const ShadowSegment& s = r.segments[e / 2];
    return node[e] >= 0 ? reps[node[e]] : (e % 2 == 0 ? s.p0 : s.p1);
  };
  std::vector<char> used(ns, 0);
  // From end e of an unused segment onward, while the far node has exactly one other segment.
  auto walk = [&](int e) {
    ShadowStroke k;
    k.points.push_back(end_point(e));
    for (;;) {
      const int s = e / 2, far = e ^ 1;
      used[s] = 1;
      k.segments.push_back(s);
      k.points.push_back(end_point(far));
      const int n = node[far];
      if (n < 0 || degree[n] != 2) break;
      const int next = incident[offset[n]] == far ? incident[offset[n] + 1] : incident[offset[n]];
      if (used[next / 2]) {
        k.closed = next / 2 == k.segments.front();
        break;
      }
      e = next;
    }
    r.strokes.push_back(std::move(k));
  };
  for (int e = 0; e < 2 * ns; ++e)
    if (!used[e / 2] && (node[e] < 0 || degree[node[e]] != 2)) walk(e);
  for (int s = 0; s < ns; ++s)
    if (!used[s]) walk(2 * s);
}

void chain_curves(ShadowIntersections& r, double join) {
  const int ns = static_cast<int>(r.segments.size());
  std::vector<Vec3> ends;
  ends.reserve(2 * ns);
  for (const auto& s : r.segments) {
    ends.push_back(s.p0);
    ends.push_back(s.p1);
  }
  // Cluster the end points, then attach every end to its nearest cluster representative.
  const std::vector<Vec3> reps = merge_points<3>(ends, join);
  Bvh<3> bvh;
  std::vector<Box<3>> boxes(reps.size());
  for (std::size_t i = 0; i < reps.size(); ++i) boxes[i].add(reps[i]);
  bvh.build(boxes);
  std::vector<int> node(ends.size(), -1);
  for (std::size_t e = 0; e < ends.size(); ++e) {
    Box<3> b;
    b.add(ends[e]);
    double best = std::numeric_limits<double>::infinity();
    bvh.query(b, join, [&](int i) {
      const double d = (reps[i] - ends[e]).norm();
      if (d < best) best = d, node[e] = i;
    });
  }
  // Union segments that share a node; count node degrees for "closed".
  std::vector<int> parent(ns);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<int> first_seg(reps.size(), -1), degree(reps.size(), 0);
  for (int s = 0; s < ns; ++s)
    for (int k = 0; k < 2; ++k) {
      const int n = node[2 * s + k];
      if (n < 0) continue;
      ++degree[n];
      if (first_seg[n] < 0)
        first_seg[n] = s;
      else
        parent[find(s)] = find(first_seg[n]);
    }
  std::vector<int> curve_of(ns, -1);
  for (int s = 0; s < ns; ++s) {
    const int root = find(s);
    if (curve_of[root] < 0) {
      curve_of[root] = static_cast<int>(r.curves.size());
      r.curves.push_back({});
      r.curves.back().closed = true;
    }
    ShadowCurve& c = r.curves[curve_of[root]];
    c.segments.push_back(s);
    c.length += r.segments[s].length();
    if (r.segments[s].true_intersection) ++c.true_points;
    for (int k = 0; k < 2; ++k) {
      const int n = node[2 * s + k];
      if (n < 0 || degree[n] != 2) c.closed = false;
    }
  }
  walk_strokes(r, node, degree, reps);
  for (const auto& c : r.curves) {
    r.total_length += c.length;
    if (c.true_intersection())
      ++r.true_curves;
    else
      ++r.shadow_only_curves;
  }
}

double join_distance(const ShadowMesh& a, const ShadowMesh* b, const ShadowIntersectionOptions& o) {
  if (o.join_distance >= 0) return o.join_distance;
  Box<3> box;
  for (const auto& p : a.x)
    if (p.allFinite()) box.add(p);
  if (b)
    for (const auto& p : b->x)
      if (p.allFinite()) box.add(p);
  const double d = (box.hi - box.lo).norm();
  return 1e-9 * (std::isfinite(d) && d > 0 ? d : 1.0);
}

}  // namespace

void ShadowCurveCounts::add(const ShadowIntersections& r) {
  curves += static_cast<int>(r.curves.size());
  shadow_only_curves += r.shadow_only_curves;
  true_curves += r.true_curves;
  coplanar_pairs += r.coplanar_pairs;
  length += r.total_length;
  for (const ShadowCurve& c : r.curves) true_points += c.true_points;
}

std::string counts_text(const ShadowCurveCounts& c) {
  std::ostringstream o;
  o << c.curves << " curve(s), total length " << std::setprecision(6) << c.length << ": "
    << c.shadow_only_curves << " shadow-only, " << c.true_curves << " true (" << c.true_points
    << " true point(s))";
  if (c.coplanar_pairs > 0) o << "; the view is not generic (sheets overlap in area): turn it";
  return o.str();
}

ShadowIntersections shadow_intersections(const Surface<4>& s, const Frame<4>& frame,
                                         const ShadowIntersectionOptions& opt) {
  const ShadowMesh m = project(s, frame);
  ShadowIntersections r;
  Bvh<3> bvh;
  bvh.build(m.boxes);
  bvh.self_pairs(0.0, [&](int i, int j) {
    const Triangle& a = s.triangles[i];
    const Triangle& b = s.triangles[j];
    for (int u : a)
      for (int v : b)
        if (u == v) return;
    intersect_pair(m, std::min(i, j), m, std::max(i, j), r);
  });
  std::sort(r.segments.begin(), r.segments.end(), [](const ShadowSegment& x, const ShadowSegment& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  chain_curves(r, join_distance(m, nullptr, opt));
  return r;
}

ShadowIntersections shadow_intersections(const Surface<4>& a, const Surface<4>& b,
                                         const Frame<4>& frame,
                                         const ShadowIntersectionOptions& opt) {
  const ShadowMesh ma = project(a, frame);
  const ShadowMesh mb = project(b, frame);
  ShadowIntersections r;
  Bvh<3> ba, bb;
  ba.build(ma.boxes);
  bb.build(mb.boxes);
  ba.pairs_with(bb, 0.0, [&](int i, int j) { intersect_pair(ma, i, mb, j, r); });
  std::sort(r.segments.begin(), r.segments.end(), [](const ShadowSegment& x, const ShadowSegment& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  chain_curves(r, join_distance(ma, &mb, opt));
  return r;
}

}  // namespace s4d
