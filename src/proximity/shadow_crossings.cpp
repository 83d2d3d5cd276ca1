// Crossings of a curve's shadow with the depth of both strands (see shadow_crossings.hpp).
#include "proximity/shadow_crossings.hpp"

#include <algorithm>

#include "proximity/bvh.hpp"
#include "proximity/closest_points.hpp"

namespace s4d {

namespace {

struct SegInfo {
  SegmentRef ref;
  int v0 = 0, v1 = 0;    // global vertex ids (for the adjacency test)
  bool closed_end = false;  // the last segment of an open polyline includes its end point
};

inline double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

template <int D>
ShadowCrossingResult<D> shadow_crossings(const Curve<D>& curve, const Frame<D>& frame,
                                         const ShadowCrossingOptions& options) {
  constexpr int S = D - 1;  // shadow dimension
  ShadowCrossingResult<D> result;
  std::vector<SegInfo> segs;
  std::vector<Vec<S>> s0, s1;   // shadow end points of each segment
  std::vector<double> z0, z1;   // depths of the end points
  std::vector<Box<S>> boxes;
  int vertex_base = 0;
  for (int c = 0; c < static_cast<int>(curve.components.size()); ++c) {
    const Polyline<D>& pl = curve.components[c];
    const int n = static_cast<int>(pl.points.size());
    const int m = static_cast<int>(pl.segment_count());
    for (int k = 0; k < m; ++k) {
      const Vec<D>& a = pl.seg_a(k);
      const Vec<D>& b = pl.seg_b(k);
      if (!a.allFinite() || !b.allFinite()) {
        ++result.non_generic;
        continue;
      }
      SegInfo info{{c, k}, vertex_base + k, vertex_base + (k + 1) % n, !pl.closed && k == m - 1};
      const Vec<S> pa = frame.shadow(a), pb = frame.shadow(b);
      if (pa == pb) {  // seen end-on: its shadow is a point, the diagram is not regular here
        ++result.non_generic;
        continue;
      }
      segs.push_back(info);
      s0.push_back(pa);
      s1.push_back(pb);
      z0.push_back(frame.depth(a));
      z1.push_back(frame.depth(b));
      Box<S> box;
      box.add(pa);
      box.add(pb);
      boxes.push_back(box);
    }
    vertex_base += n;
  }
  Bvh<S> bvh;
  bvh.build(boxes);
  const double tol = std::max(0.0, options.tolerance);
  auto in_range = [](double s, bool closed_end) { return s >= 0 && (closed_end ? s <= 1 : s < 1); };
  bvh.self_pairs(tol, [&](int i, int j) {
    if (segs[j].ref < segs[i].ref) std::swap(i, j);
    const SegInfo& a = segs[i];
    const SegInfo& b = segs[j];
    if (a.v0 == b.v0 || a.v0 == b.v1 || a.v1 == b.v0 || a.v1 == b.v1) return;
    double s = 0, t = 0;
    Vec<S> point;
    if constexpr (S == 2) {
      const Vec2 da = s1[i] - s0[i], db = s1[j] - s0[j], w = s0[j] - s0[i];
      const double den = cross2(da, db);
      if (den == 0) {
        // Parallel shadows: collinear and overlapping is a non-generic projection.
        if (cross2(w, da) == 0) {
          const double l2 = da.squaredNorm();
          const double u0 = w.dot(da) / l2, u1 = (s1[j] - s0[i]).dot(da) / l2;
          if (std::max(u0, u1) >= 0 && std::min(u0, u1) <= 1) ++result.non_generic;
        }
        return;
      }
      s = cross2(w, db) / den;
      t = cross2(w, da) / den;
      if (!in_range(s, a.closed_end) || !in_range(t, b.closed_end)) return;
      point = s0[i] + s * da;
    } else {
      const ClosestPoints<S> cp = segment_segment<S>(s0[i], s1[i], s0[j], s1[j]);
      if (!(cp.distance <= tol)) return;
      s = cp.wa[1];
      t = cp.wb[1];
      if (!in_range(s, a.closed_end) || !in_range(t, b.closed_end)) return;
      point = 0.5 * (cp.p + cp.q);
    }
    if (s == 0 || t == 0) ++result.non_generic;  // through a vertex's shadow
    ShadowCrossing<D> x;
    x.a = a.ref;
    x.b = b.ref;
    x.ta = s;
    x.tb = t;
    x.point = point;
    x.depth_a = frame.depth_at(std::array<double, 2>{1 - s, s}, std::array<double, 2>{z0[i], z1[i]});
    x.depth_b = frame.depth_at(std::array<double, 2>{1 - t, t}, std::array<double, 2>{z0[j], z1[j]});
    result.crossings.push_back(x);
  });
  std::sort(result.crossings.begin(), result.crossings.end(),
            [](const ShadowCrossing<D>& x, const ShadowCrossing<D>& y) {
              if (x.a != y.a) return x.a < y.a;
              if (x.ta != y.ta) return x.ta < y.ta;
              return x.b < y.b;
            });
  return result;
}

template ShadowCrossingResult<3> shadow_crossings<3>(const Curve<3>&, const Frame<3>&,
                                                     const ShadowCrossingOptions&);
template ShadowCrossingResult<4> shadow_crossings<4>(const Curve<4>&, const Frame<4>&,
                                                     const ShadowCrossingOptions&);

}  // namespace s4d
