// Cheap conservative lower bounds on the distance of two simplices in R^D (separating axes), so
// that the broad phase's candidates reach the exact kernels of closest_points.hpp only when needed.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "proximity/closest_points.hpp"
#include "proximity/continuous_collision.hpp"

namespace s4d {

namespace prox_detail {

// Orthogonal projection onto a line never increases distances, so the gap between the projected
// point sets (either order), divided by |n|, bounds the distance of their convex hulls from below.
// The dot products carry an error of a few ulps of |p||n|: that much is taken off the gap. Returns
// a lower bound (<= 0 when the projections overlap; 0 for a zero or NaN axis or NaN points).
template <int D, int NA, int NB>
inline double axis_gap(const std::array<Vec<D>, NA>& a, const std::array<Vec<D>, NB>& b,
                       const Vec<D>& n) {
  const double len = n.norm();
  if (!(len > 0)) return 0;  // zero or NaN axis: no information
  double lo_a = a[0].dot(n), hi_a = lo_a, lo_b = b[0].dot(n), hi_b = lo_b;
  double sum = lo_a + lo_b;  // NaN if any projection is: min/max alone would skip it
  for (int i = 1; i < NA; ++i) {
    const double s = a[i].dot(n);
    lo_a = std::min(lo_a, s);
    hi_a = std::max(hi_a, s);
    sum += s;
  }
  for (int j = 1; j < NB; ++j) {
    const double s = b[j].dot(n);
    lo_b = std::min(lo_b, s);
    hi_b = std::max(hi_b, s);
    sum += s;
  }
  if (sum != sum) return 0;
  const double gap = std::max(lo_b - hi_a, lo_a - hi_b);
  const double scale = std::max(std::max(std::abs(lo_a), std::abs(hi_a)),
                                std::max(std::abs(lo_b), std::abs(hi_b)));
  return (gap - 1e-12 * scale) / len;
}

template <int D, int NA, int NB>
inline bool axis_separates(const std::array<Vec<D>, NA>& a, const std::array<Vec<D>, NB>& b,
                           const Vec<D>& n, double delta) {
  return axis_gap<D, NA, NB>(a, b, n) > delta;
}

// The best of several axes: its gap and, when asked (axis != nullptr), the axis that gave it.
template <int D>
struct BestAxis {
  double gap = 0;
  Vec<D>* axis = nullptr;
  template <class A, class B>
  void offer(const A& a, const B& b, const Vec<D>& n) {
    constexpr int NA = static_cast<int>(std::tuple_size_v<A>), NB = static_cast<int>(std::tuple_size_v<B>);
    const double g = axis_gap<D, NA, NB>(a, b, n);
    if (g > gap) {
      gap = g;
      if (axis) *axis = n;
    }
  }
};

// Axes intrinsic to simplex s (K vertices, the first K of `pts` when pts also holds the same
// vertices at a later time): inside its affine hull, the inward normal of each facet; outside it,
// the component of (towards - s[0]) orthogonal to the hull (for stacked, parallel layers this is
// the layer normal). Raises `best` with the gaps between pts and `other`, stopping as soon as one
// exceeds `enough`.
template <int D, int K, int NA, int NB>
inline void simplex_axes(const Simplex<D, K>& s, const std::array<Vec<D>, NA>& pts,
                         const std::array<Vec<D>, NB>& other, const Vec<D>& towards, double enough,
                         BestAxis<D>& best) {
  if constexpr (K == 1) {
    best.offer(pts, other, Vec<D>(towards - s[0]));
  } else if constexpr (K == 2) {
    const Vec<D> d = s[1] - s[0];
    best.offer(pts, other, d);  // the two end caps
    if (best.gap > enough) return;
    const double dd = d.squaredNorm();
    if (!(dd > 0)) return;
    const Vec<D> w = towards - s[0];
    best.offer(pts, other, Vec<D>(w - (w.dot(d) / dd) * d));
  } else {
    static_assert(K == 3, "simplices have 1, 2 or 3 vertices");
    for (int e = 0; e < 3; ++e) {
      const Vec<D>& p = s[e];
      const Vec<D> d = s[(e + 1) % 3] - p;
      const Vec<D> r = s[(e + 2) % 3] - p;
      const double dd = d.squaredNorm();
      if (!(dd > 0)) continue;
      best.offer(pts, other, Vec<D>(r - (r.dot(d) / dd) * d));
      if (best.gap > enough) return;
    }
    if constexpr (D > 2) {
      // Orthonormal basis of the triangle's plane; skipped when the triangle is degenerate.
      const Vec<D> e1 = s[1] - s[0];
      const double l1 = e1.norm();
      if (!(l1 > 0)) return;
      const Vec<D> u1 = e1 / l1;
      Vec<D> u2 = (s[2] - s[0]) - (s[2] - s[0]).dot(u1) * u1;
      const double l2 = u2.norm();
      if (!(l2 > 1e-12 * l1)) return;
      u2 /= l2;
      Vec<D> w = towards - s[0];
      w -= w.dot(u1) * u1 + w.dot(u2) * u2;
      best.offer(pts, other, w);
    }
  }
}

template <int D, int K, int NA, int NB>
inline double simplex_axes_gap(const Simplex<D, K>& s, const std::array<Vec<D>, NA>& pts,
                               const std::array<Vec<D>, NB>& other, const Vec<D>& towards,
                               double enough) {
  BestAxis<D> best;
  simplex_axes<D, K, NA, NB>(s, pts, other, towards, enough, best);
  return best.gap;
}

template <int D, int K, int NA, int NB>
inline bool simplex_axes_separate(const Simplex<D, K>& s, const std::array<Vec<D>, NA>& pts,
                                  const std::array<Vec<D>, NB>& other, const Vec<D>& towards,
                                  double delta) {
  return simplex_axes_gap<D, K, NA, NB>(s, pts, other, towards, delta) > delta;
}

template <int D, int K>
inline Vec<D> centroid(const Simplex<D, K>& s) {
  Vec<D> c = s[0];
  for (int i = 1; i < K; ++i) c += s[i];
  return c / K;
}

}  // namespace prox_detail

// A cheap lower bound of dist(a, b): the Euclidean gap of the tight boxes, then the gaps along the
// line of centroids and along each simplex's facet normals and off-hull direction; it stops as
// soon as the bound exceeds `enough` (so a result > enough proves dist > enough, and a smaller one
// is the best of all the axes). Never more than the distance; 0 when nothing is known (or NaN).
// With `axis`, also the direction that gave the bound (left as it was when the bound is 0): a
// caller that asks again after a small motion can try that one direction first (axis_gap).
template <int D, int KA, int KB>
inline double distance_lower_bound(const Simplex<D, KA>& a, const Simplex<D, KB>& b,
                                   double enough, Vec<D>* axis = nullptr) {
  using namespace prox_detail;
  double sum = 0;  // NaN if any coordinate is (min/max alone would skip it)
  Vec<D> g = Vec<D>::Zero();
  for (int k = 0; k < D; ++k) {
    double lo_a = a[0][k], hi_a = lo_a, lo_b = b[0][k], hi_b = lo_b;
    for (int i = 1; i < KA; ++i)
      lo_a = std::min(lo_a, a[i][k]), hi_a = std::max(hi_a, a[i][k]), sum += a[i][k];
    for (int j = 1; j < KB; ++j)
      lo_b = std::min(lo_b, b[j][k]), hi_b = std::max(hi_b, b[j][k]), sum += b[j][k];
    sum += lo_a + lo_b;
    // The signed per-axis separation: its direction is an axis as good as the boxes' gap.
    if (lo_b - hi_a > 0) g[k] = lo_b - hi_a;
    if (lo_a - hi_b > 0) g[k] = -(lo_a - hi_b);
  }
  if (sum != sum) return 0;  // the exact kernel decides what NaN means
  BestAxis<D> best;
  best.axis = axis;
  best.gap = g.norm() * (1 - 1e-12);
  if (axis && best.gap > 0) *axis = g;
  if (best.gap > enough) return best.gap;
  const Vec<D> ca = centroid<D, KA>(a), cb = centroid<D, KB>(b);
  best.offer(a, b, Vec<D>(cb - ca));
  if (best.gap > enough) return best.gap;
  simplex_axes<D, KA, KA, KB>(a, a, b, cb, enough, best);
  if (best.gap > enough) return best.gap;
  simplex_axes<D, KB, KB, KA>(b, b, a, ca, enough, best);
  return best.gap;
}

// True when dist(a, b) > delta is proven cheaply (distance_lower_bound); false means "unknown"
// (the exact kernel decides), never "closer than delta".
template <int D, int KA, int KB>
inline bool provably_farther(const Simplex<D, KA>& a, const Simplex<D, KB>& b, double delta) {
  return distance_lower_bound<D, KA, KB>(a, b, delta) > delta;
}

// True when the two simplices, every vertex moving linearly from *0 to *1, provably stay farther
// apart than delta for all t in [0, t_max]. A moving point's projection on a fixed axis moves
// linearly, so the projections of the simplex at any such t lie within those of its vertices at
// t = 0 and t = t_max: a gap between these swept sets bounds the distance for the whole interval.
template <int D, int KA, int KB>
inline bool provably_apart_over_step(const Simplex<D, KA>& a0, const Simplex<D, KA>& a1,
                                     const Simplex<D, KB>& b0, const Simplex<D, KB>& b1,
                                     double t_max, double delta) {
  using namespace prox_detail;
  std::array<Vec<D>, 2 * KA> sa;
  std::array<Vec<D>, 2 * KB> sb;
  for (int i = 0; i < KA; ++i) sa[i] = a0[i], sa[KA + i] = a0[i] + t_max * (a1[i] - a0[i]);
  for (int j = 0; j < KB; ++j) sb[j] = b0[j], sb[KB + j] = b0[j] + t_max * (b1[j] - b0[j]);
  // Axes from the configuration at mid-interval: it stays closest to both ends.
  const Simplex<D, KA> am = lerp_simplex<D, KA>(a0, a1, 0.5 * t_max);
  const Simplex<D, KB> bm = lerp_simplex<D, KB>(b0, b1, 0.5 * t_max);
  const Vec<D> ca = centroid<D, KA>(am), cb = centroid<D, KB>(bm);
  if (axis_separates<D, 2 * KA, 2 * KB>(sa, sb, cb - ca, delta)) return true;
  if (simplex_axes_separate<D, KA, 2 * KA, 2 * KB>(am, sa, sb, cb, delta)) return true;
  return simplex_axes_separate<D, KB, 2 * KB, 2 * KA>(bm, sb, sa, ca, delta);
}

}  // namespace s4d
