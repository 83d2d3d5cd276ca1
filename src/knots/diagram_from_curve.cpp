// diagram_from_curve: crossings of the shadow (the proximity layer finds them) become a KnotDiagram;
// a non-generic view is turned a tiny bit, touching strands are rejected with a clear message.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "core/error.hpp"
#include "knots/knot_diagram.hpp"
#include "proximity/shadow_crossings.hpp"

namespace s4d {

double curve_scale(const Curve<3>& curve) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const auto& c : curve.components)
    for (const auto& p : c.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  const double s = (hi - lo).norm();
  return std::isfinite(s) && s > 0 ? s : 1.0;
}

void validate_knot_curve(const Curve<3>& curve) {
  if (curve.components.empty()) throw Error("the curve has no components");
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    const auto& pl = curve.components[c];
    const std::string who = "component " + std::to_string(c);
    if (pl.points.size() < 3)
      throw Error(who + " has " + std::to_string(pl.points.size()) +
                  " points; a closed knot curve needs at least 3");
    if (!pl.closed) throw Error(who + " is open; knots and links are closed curves");
    for (std::size_t k = 0; k < pl.points.size(); ++k)
      if (!pl.points[k].allFinite())
        throw Error(who + ", point " + std::to_string(k) + " is not finite (NaN or infinity)");
  }
  const double tol = 1e-12 * curve_scale(curve);
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    const auto& pl = curve.components[c];
    for (std::size_t k = 0; k < pl.segment_count(); ++k)
      if ((pl.seg_b(k) - pl.seg_a(k)).norm() <= tol)
        throw Error("component " + std::to_string(c) + ": points " + std::to_string(k) + " and " +
                    std::to_string((k + 1) % pl.points.size()) + " are repeated (the same point)");
  }
}

namespace {

Vec2 segment_direction(const Curve<3>& curve, const Frame<3>& frame, const SegmentRef& s) {
  const auto& pl = curve.components[s.component];
  return frame.shadow(pl.seg_b(s.segment)) - frame.shadow(pl.seg_a(s.segment));
}

std::string where(const Vec3& p) {
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

bool adjacent(const Curve<3>& curve, const SegmentRef& x, const SegmentRef& y) {
  if (x.component != y.component) return false;
  const int n = static_cast<int>(curve.components[x.component].points.size());
  const int d = std::abs(x.segment - y.segment);
  return d == 1 || d == n - 1;
}

// Two crossings of one strand with the two segments on either side of a vertex of another strand:
// a crossing just beside a vertex, which is regular (a triple point needs three strands).
bool near_vertex_pair(const Curve<3>& curve, const ShadowCrossing<3>& p, const ShadowCrossing<3>& q) {
  const SegmentRef ps[2] = {p.a, p.b}, qs[2] = {q.a, q.b};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      if (ps[i] == qs[j] && adjacent(curve, ps[1 - i], qs[1 - j])) return true;
  return false;
}

// Tries one frame. Returns false when the view is not generic (the caller turns it a little).
bool try_frame(const Curve<3>& curve, const Frame<3>& frame, double scale, const DiagramOptions& o,
               KnotDiagram& out) {
  const auto found = shadow_crossings<3>(curve, frame);
  if (found.non_generic > 0) return false;
  const double tol = o.touch_tolerance * scale;
  const auto& xs = found.crossings;
  // A crossing within rounding of a vertex's shadow is one too: shadow_crossings only sees exact
  // hits, and a rounded one can be counted on both segments at that vertex or on neither
  // (symmetric samplings, such as T(3,7) on 336 points seen down its axis, do this).
  constexpr double kNearVertex = 1e-9;
  for (const auto& x : xs)
    if (std::min({x.ta, 1 - x.ta, x.tb, 1 - x.tb}) < kNearVertex) return false;
  // Triple points: two crossings at the same spot of the shadow.
  {
    std::vector<int> order(xs.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int i, int j) { return xs[i].point.x() < xs[j].point.x(); });
    for (std::size_t i = 0; i < order.size(); ++i)
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        if (xs[order[j]].point.x() - xs[order[i]].point.x() > tol) break;
        if ((xs[order[j]].point - xs[order[i]].point).norm() <= tol &&
            !near_vertex_pair(curve, xs[order[i]], xs[order[j]]))
          return false;
      }
  }
  KnotDiagram d;
  d.components.resize(curve.components.size());
  for (const auto& x : xs) {
    if (std::abs(x.depth_a - x.depth_b) <= tol) {
      const auto& pl = curve.components[x.a.component];
      const Vec3 p = pl.seg_a(x.a.segment) + x.ta * (pl.seg_b(x.a.segment) - pl.seg_a(x.a.segment));
      throw Error("the curve intersects itself near " + where(p) + " (component " +
                  std::to_string(x.a.component) + ", segment " + std::to_string(x.a.segment) +
                  " meets component " + std::to_string(x.b.component) + ", segment " +
                  std::to_string(x.b.segment) + ")");
    }
    const bool a_over = x.a_over();
    const SegmentRef& so = a_over ? x.a : x.b;
    const SegmentRef& su = a_over ? x.b : x.a;
    const Vec2 dir_o = segment_direction(curve, frame, so), dir_u = segment_direction(curve, frame, su);
    const double cr = dir_o.x() * dir_u.y() - dir_o.y() * dir_u.x();
    DiagramCrossing c;
    c.sign = cr > 0 ? 1 : -1;
    c.point = x.point;
    c.depth_over = a_over ? x.depth_a : x.depth_b;
    c.depth_under = a_over ? x.depth_b : x.depth_a;
    const int ci = static_cast<int>(d.crossings.size());
    c.over = static_cast<int>(d.passages.size());
    d.passages.push_back({ci, true, so.component, so.segment + (a_over ? x.ta : x.tb)});
    c.under = static_cast<int>(d.passages.size());
    d.passages.push_back({ci, false, su.component, su.segment + (a_over ? x.tb : x.ta)});
    d.crossings.push_back(c);
  }
  for (int p = 0; p < static_cast<int>(d.passages.size()); ++p)
    d.components[d.passages[p].component].push_back(p);
  for (auto& comp : d.components)
    std::sort(comp.begin(), comp.end(),
              [&](int i, int j) { return d.passages[i].position < d.passages[j].position; });
  d.normalise();
  out = std::move(d);
  return true;
}

}  // namespace

KnotDiagram diagram_from_curve(const Curve<3>& curve, const Frame<3>& frame,
                               const DiagramOptions& options, Frame<3>* used_frame) {
  validate_knot_curve(curve);
  const double scale = curve_scale(curve);
  Frame<3> f = frame;
  KnotDiagram d;
  for (int attempt = 0; attempt <= options.max_perturbations; ++attempt) {
    if (try_frame(curve, f, scale, options, d)) {
      if (used_frame) *used_frame = f;
      return d;
    }
    // A tiny turn, growing with each attempt, in planes that move the shadow (xz, yz) and spin
    // it (xy). Deterministic, so the same input always gives the same codes.
    const double angle = 1e-7 * std::pow(3.0, attempt);
    f.rotate(Plane{0, 2}, angle * 0.7548776662);
    f.rotate(Plane{1, 2}, angle * 0.5698402910);
    f.rotate(Plane{0, 1}, angle * 0.3141592654);
  }
  throw Error("no generic projection found near the given view: the curve may overlap itself");
}

}  // namespace s4d
