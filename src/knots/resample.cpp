// Resampling by Delta moves checked with the proximity kernel (segment-triangle distances).
#include "knots/resample.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "knots/knot_diagram.hpp"
#include "proximity/closest_points.hpp"

namespace s4d {

namespace {

struct Box {
  Vec3 lo, hi;
  bool overlaps(const Box& o, double eps) const {
    return (lo.array() - eps <= o.hi.array()).all() && (o.lo.array() - eps <= hi.array()).all();
  }
};
Box box_of(std::initializer_list<Vec3> ps) {
  Box b{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
  for (const auto& p : ps) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

// The strands of the curve at one moment of the sequence of moves, as segments with an owner tag
// so that a move can ignore its own old path and its two neighbours.
struct Seg {
  Vec3 a, b;
  Box box;
};

// True if no segment in `others` comes within eps of triangle (p, q, r).
bool triangle_clear(const Vec3& p, const Vec3& q, const Vec3& r, const std::vector<const Seg*>& others,
                    double eps) {
  const Box tb = box_of({p, q, r});
  for (const Seg* s : others) {
    if (!tb.overlaps(s->box, eps)) continue;
    if (segment_triangle<3>(s->a, s->b, p, q, r).distance <= eps) return false;
  }
  return true;
}

// Point at arc length s along a closed polyline with cumulative lengths cum (cum[0] = 0).
Vec3 point_at(const Polyline<3>& pl, const std::vector<double>& cum, double s, std::size_t& seg) {
  const std::size_t n = pl.points.size();
  while (seg + 1 < n && cum[seg + 1] <= s) ++seg;
  const double len = cum[seg + 1] - cum[seg];
  const double t = len > 0 ? (s - cum[seg]) / len : 0;
  return pl.seg_a(seg) + t * (pl.seg_b(seg) - pl.seg_a(seg));
}

}  // namespace

Curve<3> resample_curve(const Curve<3>& curve, double spacing, ResampleStats* stats) {
  validate_knot_curve(curve);
  if (!(spacing > 0) || !std::isfinite(spacing)) throw Error("resampling needs a spacing > 0");
  const double eps = 1e-10 * curve_scale(curve);
  ResampleStats st;

  // Current strands: the new polylines of processed components and the old ones of the others.
  Curve<3> out = curve;
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    const Polyline<3>& old = curve.components[c];
    const std::size_t n = old.points.size();
    std::vector<double> cum(n + 1, 0);
    for (std::size_t k = 0; k < n; ++k) cum[k + 1] = cum[k] + (old.seg_b(k) - old.seg_a(k)).norm();
    const double L = cum[n];
    const int m = std::max(4, static_cast<int>(std::lround(L / spacing)));

    // Targets q_j at equal arc length, each tagged with the old segment it lies on.
    std::vector<Vec3> q(m);
    std::vector<std::size_t> q_seg(m);
    std::vector<double> q_s(m);
    std::size_t seg = 0;
    for (int j = 0; j < m; ++j) {
      q_s[j] = L * j / m;
      q[j] = point_at(old, cum, q_s[j], seg);
      q_seg[j] = seg;
    }

    // Segments of the other components, fixed during this component's moves.
    std::vector<Seg> fixed;
    for (std::size_t o = 0; o < out.components.size(); ++o) {
      if (o == c) continue;
      const auto& pl = out.components[o];
      for (std::size_t k = 0; k < pl.segment_count(); ++k)
        fixed.push_back({pl.seg_a(k), pl.seg_b(k), box_of({pl.seg_a(k), pl.seg_b(k)})});
    }

    Polyline<3> fresh;
    fresh.closed = true;
    std::vector<Seg> accepted;  // new segments so far (the last one ends at the current q_j)
    for (int j = 0; j < m; ++j) {
      const int jn = (j + 1) % m;
      // The old path from q_j to q_{j+1}: q_j, old vertices strictly after it, q_{j+1}.
      std::vector<Vec3> path{q[j]};
      std::size_t k = q_seg[j];
      const double s_end = jn == 0 ? L : q_s[jn];
      while (cum[k + 1] < s_end && k + 1 < n + (jn == 0 ? 1 : 0)) {
        path.push_back(old.points[(k + 1) % n]);
        ++k;
      }
      path.push_back(q[jn]);

      // Everything that exists while this move happens, except the path itself and its
      // neighbours: earlier new segments but the last, the old curve beyond q_{j+1}.
      std::vector<const Seg*> others;
      for (const auto& s : fixed) others.push_back(&s);
      for (std::size_t i = 0; i + 1 < accepted.size(); ++i)
        if (!(j == m - 1 && i == 0)) others.push_back(&accepted[i]);  // the first meets q_0
      std::vector<Seg> rest;
      {
        const std::size_t k_end = jn == 0 ? n : q_seg[jn];  // old segment holding q_{j+1}
        const std::size_t k_stop = q_seg[0] + n;           // back around to q_0
        // Old segments after the one holding q_{j+1}, up to (not including) the one holding q_0.
        for (std::size_t kk = k_end + 1; jn != 0 && kk < k_stop; ++kk) {
          const Vec3& a = old.points[kk % n];
          const Vec3& b = old.points[(kk + 1) % n];
          rest.push_back({a, b, box_of({a, b})});
        }
      }
      for (const auto& s : rest) others.push_back(&s);
      // The rest of the old segment holding q_{j+1} touches the last triangle at q_{j+1} by
      // construction; it must still miss the earlier ones.
      std::vector<const Seg*> with_tail = others;
      Seg tail;
      if (jn != 0) {
        const std::size_t k_end = q_seg[jn];
        tail = {q[jn], old.points[(k_end + 1) % n], box_of({q[jn], old.points[(k_end + 1) % n]})};
        with_tail.push_back(&tail);
      }

      bool clear = true;
      for (std::size_t i = 1; clear && i + 1 < path.size(); ++i)
        clear = triangle_clear(path.front(), path[i], path[i + 1],
                               i + 2 < path.size() ? with_tail : others, eps);
      if (path.size() <= 2 || clear) {
        fresh.points.push_back(q[j]);
        accepted.push_back({q[j], q[jn], box_of({q[j], q[jn]})});
        ++st.moves;
      } else {
        // Keep the old shape here: q_j and the old vertices of the path.
        for (std::size_t i = 0; i + 1 < path.size(); ++i) {
          fresh.points.push_back(path[i]);
          accepted.push_back({path[i], path[i + 1], box_of({path[i], path[i + 1]})});
        }
        ++st.refused;
      }
    }
    // Drop points that coincide with their successor (a target landing on an old vertex).
    Polyline<3> clean;
    clean.closed = true;
    for (std::size_t i = 0; i < fresh.points.size(); ++i) {
      const Vec3& p = fresh.points[i];
      const Vec3& nx = fresh.points[(i + 1) % fresh.points.size()];
      if ((nx - p).norm() > eps) clean.points.push_back(p);
    }
    out.components[c] = std::move(clean);
  }
  if (stats) *stats = st;
  return out;
}

Curve<3> resample_curve_to_count(const Curve<3>& curve, int points, ResampleStats* stats) {
  validate_knot_curve(curve);
  if (points < 3 * static_cast<int>(curve.components.size()))
    throw Error("resampling needs at least 3 points per component");
  return resample_curve(curve, curve.length() / points, stats);
}

}  // namespace s4d
