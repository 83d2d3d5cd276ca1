// Exact closest points between simplices (point, segment, triangle) in R^D, any D >= 2: the
// distance kernel under every force, contact and "no pass-through" check of the engine.
// Sections: [SECTION] Implementation details, [SECTION] Public closest-point functions,
// [SECTION] Active set
#pragma once
#include <array>
#include <cmath>
#include <limits>

#include "core/vec.hpp"

namespace s4d {

// K vertices of a simplex: K = 1 point, 2 segment, 3 triangle.
template <int D, int K>
using Simplex = std::array<Vec<D>, K>;

template <int D>
struct ClosestPoints {
  double distance = std::numeric_limits<double>::infinity();
  Vec<D> p = Vec<D>::Zero();      // closest point on the first primitive
  Vec<D> q = Vec<D>::Zero();      // closest point on the second primitive
  std::array<double, 3> wa{};     // barycentric weights of p on the first primitive's vertices
  std::array<double, 3> wb{};     // ... of q on the second's (a segment's t is wb[1], etc.)
};

// [SECTION] Implementation details (the public functions follow)
//
// The minimiser of |p - q|^2 over a pair of simplices lies in the relative interior of some pair
// of faces (F of A, G of B). We enumerate the face pairs, solve the small unconstrained least
// squares on the affine hulls, and keep solutions strictly inside both faces. Every candidate is
// a feasible pair of points, so a badly conditioned solve can only lose the minimum, never give a
// wrong one; rank-deficient face pairs (parallel, coplanar, degenerate) always have a minimiser
// on a lower face, which the enumeration also visits. This is what makes it robust.
namespace prox_detail {

template <int D>
struct Best {
  double d2 = std::numeric_limits<double>::infinity();
  Vec<D> p = Vec<D>::Zero(), q = Vec<D>::Zero();
  std::array<double, 3> wa{}, wb{};
  void offer(const Vec<D>& pp, const Vec<D>& qq, const std::array<double, 3>& a,
             const std::array<double, 3>& b) {
    const double d = (pp - qq).squaredNorm();
    if (d < d2) {
      d2 = d;
      p = pp;
      q = qq;
      wa = a;
      wb = b;
    }
  }
};

inline double clamp01(double t) { return t < 0 ? 0.0 : (t > 1 ? 1.0 : t); }

// Least squares min |M x - r| for the D × N matrix M of a face pair's edge vectors; false when M
// is rank deficient to working precision (the caller then relies on the lower faces). Square
// systems are solved directly (LU); others by the normal equations plus one step of iterative
// refinement, which recovers the accuracy the normal equations lose on thin configurations.
//
// `plausible(x)` sees the solution before refinement: when it says the solution is clearly
// outside the faces (the caller's test with a margin far above what refinement moves it), the
// solve stops there. Most face pairs end so, which halves the kernel's cost.
template <int D, int N, class Plausible>
inline bool solve_least_squares(const Eigen::Matrix<double, D, N>& m, const Vec<D>& r,
                                Eigen::Matrix<double, N, 1>& x, Plausible&& plausible) {
  using MatN = Eigen::Matrix<double, N, N>;
  if constexpr (D == N) {
    const double det = m.determinant();
    double scale = 1;
    for (int i = 0; i < N; ++i) scale *= m.col(i).norm();
    if (!(std::abs(det) > 1e-10 * scale)) return false;
    const auto lu = m.partialPivLu();
    x = lu.solve(r);
    if (!plausible(x)) return false;
    x += lu.solve(r - m * x);
  } else {
    const MatN g = m.transpose() * m;
    const double det = g.determinant();
    double scale = 1;
    for (int i = 0; i < N; ++i) scale *= g(i, i);
    if (!(det > 1e-20 * scale) || !(scale > 0)) return false;
    const MatN inv = g.inverse();
    x = inv * (m.transpose() * r);
    if (!plausible(x)) return false;
    x += inv * (m.transpose() * (r - m * x));
  }
  return x.allFinite();
}

// Slack of the plausibility tests above, in face parameters: refinement moves a solution by about
// the condition number (at most 1e10 after the rank test) times the rounding, far below this.
constexpr double kPlausible = 1e-4;
inline bool in_unit(double t) { return t > -kPlausible && t < 1 + kPlausible; }
inline bool in_triangle(double u, double v) {
  return u > -kPlausible && v > -kPlausible && u + v < 1 + kPlausible;
}

template <int D, int K>
inline bool all_finite(const std::array<const Vec<D>*, K>& v) {
  double s = 0;
  for (const Vec<D>* p : v) s += p->sum();
  return std::isfinite(s);
}

template <int D>
inline ClosestPoints<D> non_finite() {
  ClosestPoints<D> r;
  r.distance = std::numeric_limits<double>::quiet_NaN();
  return r;
}

// Point x against segment [a, b], both endpoints included (vertex cases come out by clamping).
template <int D>
inline void point_segment(const Vec<D>& x, const Vec<D>& a, const Vec<D>& b, double& t, Vec<D>& y) {
  const Vec<D> d = b - a;
  const double dd = d.squaredNorm();
  t = dd > 0 ? clamp01((x - a).dot(d) / dd) : 0.0;
  y = a + t * d;
}

// Interior of segment a0a1 against interior of segment b0b1.
template <int D>
inline void edge_edge_interior(const Vec<D>& a0, const Vec<D>& a1, const Vec<D>& b0,
                               const Vec<D>& b1, Best<D>& best, bool swap) {
  const Vec<D> d1 = a1 - a0, d2 = b1 - b0;
  Eigen::Matrix<double, D, 2> m;
  m.col(0) = d1;
  m.col(1) = -d2;
  Eigen::Vector2d x;
  if (!solve_least_squares<D, 2>(m, Vec<D>(b0 - a0), x,
                                 [](const Eigen::Vector2d& y) { return in_unit(y[0]) && in_unit(y[1]); }))
    return;
  const double s = x[0], t = x[1];
  if (!(s > 0 && s < 1 && t > 0 && t < 1)) return;
  const Vec<D> p = a0 + s * d1, q = b0 + t * d2;
  if (swap)
    best.offer(q, p, {1 - t, t, 0}, {1 - s, s, 0});
  else
    best.offer(p, q, {1 - s, s, 0}, {1 - t, t, 0});
}

// Point x against the interior of triangle abc.
template <int D>
inline void vertex_triangle_interior(const Vec<D>& x, const Vec<D>& a, const Vec<D>& b,
                                     const Vec<D>& c, Best<D>& best, bool swap) {
  const Vec<D> e1 = b - a, e2 = c - a;
  Eigen::Matrix<double, D, 2> m;
  m.col(0) = e1;
  m.col(1) = e2;
  Eigen::Vector2d uv;
  if (!solve_least_squares<D, 2>(m, Vec<D>(x - a), uv,
                                 [](const Eigen::Vector2d& y) { return in_triangle(y[0], y[1]); }))
    return;
  const double u = uv[0], v = uv[1];
  if (!(u > 0 && v > 0 && u + v < 1)) return;
  const Vec<D> y = a + u * e1 + v * e2;
  if (swap)
    best.offer(y, x, {1 - u - v, u, v}, {1, 0, 0});
  else
    best.offer(x, y, {1, 0, 0}, {1 - u - v, u, v});
}

// Interior of segment p0p1 against the interior of triangle abc (only possible off-boundary in
// D >= 3: in the plane the minimiser of a segment against a triangle is on a lower face).
template <int D>
inline void edge_triangle_interior(const Vec<D>& p0, const Vec<D>& p1, const Vec<D>& a,
                                   const Vec<D>& b, const Vec<D>& c, Best<D>& best, bool swap) {
  if constexpr (D >= 3) {
    Eigen::Matrix<double, D, 3> m;
    m.col(0) = p1 - p0;
    m.col(1) = a - b;
    m.col(2) = a - c;
    Eigen::Vector3d x;
    if (!solve_least_squares<D, 3>(m, Vec<D>(a - p0), x, [](const Eigen::Vector3d& y) {
          return in_unit(y[0]) && in_triangle(y[1], y[2]);
        }))
      return;
    const double s = x[0], u = x[1], v = x[2];
    if (!(s > 0 && s < 1 && u > 0 && v > 0 && u + v < 1)) return;
    const Vec<D> p = p0 + s * (p1 - p0);
    const Vec<D> q = a + u * (b - a) + v * (c - a);
    if (swap)
      best.offer(q, p, {1 - u - v, u, v}, {1 - s, s, 0});
    else
      best.offer(p, q, {1 - s, s, 0}, {1 - u - v, u, v});
  }
}

// Interior against interior of two triangles: possible with positive distance only for D >= 5,
// and as an isolated crossing point for D = 4 (two 2-planes of R^4 meet in a point).
template <int D>
inline void triangle_triangle_interior(const Simplex<D, 3>& A, const Simplex<D, 3>& B,
                                       Best<D>& best) {
  if constexpr (D >= 4) {
    Eigen::Matrix<double, D, 4> m;
    m.col(0) = A[1] - A[0];
    m.col(1) = A[2] - A[0];
    m.col(2) = B[0] - B[1];
    m.col(3) = B[0] - B[2];
    Eigen::Vector4d x;
    if (!solve_least_squares<D, 4>(m, Vec<D>(B[0] - A[0]), x, [](const Eigen::Vector4d& y) {
          return in_triangle(y[0], y[1]) && in_triangle(y[2], y[3]);
        }))
      return;
    const double u = x[0], v = x[1], s = x[2], t = x[3];
    if (!(u > 0 && v > 0 && u + v < 1 && s > 0 && t > 0 && s + t < 1)) return;
    const Vec<D> p = A[0] + u * (A[1] - A[0]) + v * (A[2] - A[0]);
    const Vec<D> q = B[0] + s * (B[1] - B[0]) + t * (B[2] - B[0]);
    best.offer(p, q, {1 - u - v, u, v}, {1 - s - t, s, t});
  }
}

// Vertex x (index i of its primitive, weights one-hot) against the closed segment ab.
template <int D>
inline void vertex_edge(const Vec<D>& x, int i, const Vec<D>& a, int ia, const Vec<D>& b, int ib,
                        Best<D>& best, bool swap) {
  double t;
  Vec<D> y;
  point_segment<D>(x, a, b, t, y);
  std::array<double, 3> wx{}, wy{};
  wx[i] = 1;
  wy[ia] += 1 - t;
  wy[ib] += t;
  if (swap)
    best.offer(y, x, wy, wx);
  else
    best.offer(x, y, wx, wy);
}

template <int D>
inline ClosestPoints<D> finish(const Best<D>& b) {
  ClosestPoints<D> r;
  r.distance = std::sqrt(b.d2);
  r.p = b.p;
  r.q = b.q;
  r.wa = b.wa;
  r.wb = b.wb;
  return r;
}

}  // namespace prox_detail

// [SECTION] Public closest-point functions. Barycentric weights: a point has {1}, a segment
// {1 - t, t}, a triangle {w0, w1, w2}. Degenerate input (zero-length segments, collinear
// triangles, parallel or coplanar pairs, touching or crossing pairs) is handled; non-finite input
// gives a non-finite distance.

template <int D>
ClosestPoints<D> point_point(const Vec<D>& x, const Vec<D>& y) {
  prox_detail::Best<D> b;
  b.d2 = (x - y).squaredNorm();
  b.p = x;
  b.q = y;
  b.wa = {1, 0, 0};
  b.wb = {1, 0, 0};
  return prox_detail::finish(b);
}

template <int D>
ClosestPoints<D> point_segment(const Vec<D>& x, const Vec<D>& a, const Vec<D>& b) {
  if (!prox_detail::all_finite<D, 3>({&x, &a, &b})) return prox_detail::non_finite<D>();
  prox_detail::Best<D> best;
  prox_detail::vertex_edge<D>(x, 0, a, 0, b, 1, best, false);
  if (!std::isfinite(best.d2)) best.d2 = std::numeric_limits<double>::quiet_NaN();
  return prox_detail::finish(best);
}

template <int D>
ClosestPoints<D> segment_segment(const Vec<D>& a0, const Vec<D>& a1, const Vec<D>& b0,
                                 const Vec<D>& b1) {
  using namespace prox_detail;
  if (!all_finite<D, 4>({&a0, &a1, &b0, &b1})) return non_finite<D>();
  Best<D> best;
  vertex_edge<D>(a0, 0, b0, 0, b1, 1, best, false);
  vertex_edge<D>(a1, 1, b0, 0, b1, 1, best, false);
  vertex_edge<D>(b0, 0, a0, 0, a1, 1, best, true);
  vertex_edge<D>(b1, 1, a0, 0, a1, 1, best, true);
  edge_edge_interior<D>(a0, a1, b0, b1, best, false);
  if (!std::isfinite(best.d2)) best.d2 = std::numeric_limits<double>::quiet_NaN();
  return finish(best);
}

template <int D>
ClosestPoints<D> point_triangle(const Vec<D>& x, const Vec<D>& a, const Vec<D>& b,
                                const Vec<D>& c) {
  using namespace prox_detail;
  if (!all_finite<D, 4>({&x, &a, &b, &c})) return non_finite<D>();
  Best<D> best;
  vertex_edge<D>(x, 0, a, 0, b, 1, best, false);
  vertex_edge<D>(x, 0, b, 1, c, 2, best, false);
  vertex_edge<D>(x, 0, c, 2, a, 0, best, false);
  vertex_triangle_interior<D>(x, a, b, c, best, false);
  if (!std::isfinite(best.d2)) best.d2 = std::numeric_limits<double>::quiet_NaN();
  return finish(best);
}

template <int D>
ClosestPoints<D> segment_triangle(const Vec<D>& p0, const Vec<D>& p1, const Vec<D>& a,
                                  const Vec<D>& b, const Vec<D>& c) {
  using namespace prox_detail;
  if (!all_finite<D, 5>({&p0, &p1, &a, &b, &c})) return non_finite<D>();
  Best<D> best;
  const std::array<const Vec<D>*, 3> t{&a, &b, &c};
  const std::array<const Vec<D>*, 2> s{&p0, &p1};
  for (int i = 0; i < 2; ++i)
    for (int e = 0; e < 3; ++e)
      vertex_edge<D>(*s[i], i, *t[e], e, *t[(e + 1) % 3], (e + 1) % 3, best, false);
  for (int j = 0; j < 3; ++j) {
    // Triangle vertex j against the segment: weights land on the second primitive.
    double tt;
    Vec<D> y;
    point_segment<D>(*t[j], p0, p1, tt, y);
    std::array<double, 3> wt{};
    wt[j] = 1;
    best.offer(y, *t[j], {1 - tt, tt, 0}, wt);
  }
  for (int e = 0; e < 3; ++e) {
    // Interior of the segment against the interior of edge e of the triangle.
    Best<D> local;
    edge_edge_interior<D>(p0, p1, *t[e], *t[(e + 1) % 3], local, false);
    if (local.d2 < best.d2) {
      std::array<double, 3> wt{};
      wt[e] = local.wb[0];
      wt[(e + 1) % 3] = local.wb[1];
      best.offer(local.p, local.q, local.wa, wt);
    }
  }
  vertex_triangle_interior<D>(p0, a, b, c, best, false);
  {
    Best<D> local;
    vertex_triangle_interior<D>(p1, a, b, c, local, false);
    if (local.d2 < best.d2) best.offer(local.p, local.q, {0, 1, 0}, local.wb);
  }
  edge_triangle_interior<D>(p0, p1, a, b, c, best, false);
  if (!std::isfinite(best.d2)) best.d2 = std::numeric_limits<double>::quiet_NaN();
  return finish(best);
}

template <int D>
ClosestPoints<D> triangle_triangle(const Simplex<D, 3>& A, const Simplex<D, 3>& B) {
  using namespace prox_detail;
  if (!all_finite<D, 6>({&A[0], &A[1], &A[2], &B[0], &B[1], &B[2]})) return non_finite<D>();
  Best<D> best;
  // Vertex of one against an edge of the other (covers vertex-vertex by clamping).
  for (int i = 0; i < 3; ++i)
    for (int e = 0; e < 3; ++e) {
      const int f = (e + 1) % 3;
      vertex_edge<D>(A[i], i, B[e], e, B[f], f, best, false);
      vertex_edge<D>(B[i], i, A[e], e, A[f], f, best, true);
    }
  // Edge interior against edge interior.
  for (int e = 0; e < 3; ++e)
    for (int g = 0; g < 3; ++g) {
      Best<D> local;
      edge_edge_interior<D>(A[e], A[(e + 1) % 3], B[g], B[(g + 1) % 3], local, false);
      if (local.d2 < best.d2) {
        std::array<double, 3> wa{}, wb{};
        wa[e] = local.wa[0];
        wa[(e + 1) % 3] = local.wa[1];
        wb[g] = local.wb[0];
        wb[(g + 1) % 3] = local.wb[1];
        best.offer(local.p, local.q, wa, wb);
      }
    }
  // Vertex against triangle interior, and edge interior against triangle interior.
  for (int i = 0; i < 3; ++i) {
    Best<D> la, lb;
    vertex_triangle_interior<D>(A[i], B[0], B[1], B[2], la, false);
    if (la.d2 < best.d2) {
      std::array<double, 3> wa{};
      wa[i] = 1;
      best.offer(la.p, la.q, wa, la.wb);
    }
    vertex_triangle_interior<D>(B[i], A[0], A[1], A[2], lb, true);
    if (lb.d2 < best.d2) {
      std::array<double, 3> wb{};
      wb[i] = 1;
      best.offer(lb.p, lb.q, lb.wa, wb);
    }
  }
  if constexpr (D >= 3) {
    for (int e = 0; e < 3; ++e) {
      const int f = (e + 1) % 3;
      Best<D> la, lb;
      edge_triangle_interior<D>(A[e], A[f], B[0], B[1], B[2], la, false);
      if (la.d2 < best.d2) {
        std::array<double, 3> wa{};
        wa[e] = la.wa[0];
        wa[f] = la.wa[1];
        best.offer(la.p, la.q, wa, la.wb);
      }
      edge_triangle_interior<D>(B[e], B[f], A[0], A[1], A[2], lb, true);
      if (lb.d2 < best.d2) {
        std::array<double, 3> wb{};
        wb[e] = lb.wb[0];
        wb[f] = lb.wb[1];
        best.offer(lb.p, lb.q, lb.wa, wb);
      }
    }
  }
  triangle_triangle_interior<D>(A, B, best);
  if (!std::isfinite(best.d2)) best.d2 = std::numeric_limits<double>::quiet_NaN();
  return finish(best);
}

// Closest points of two simplices given by their vertices (K = 1, 2, 3), in argument order, by
// the enumeration of every face pair: the robust reference the fast path below falls back to.
template <int D, int KA, int KB>
ClosestPoints<D> closest_points_enumerated(const Simplex<D, KA>& a, const Simplex<D, KB>& b) {
  if constexpr (KA > KB) {
    ClosestPoints<D> r = closest_points_enumerated<D, KB, KA>(b, a);
    std::swap(r.p, r.q);
    std::swap(r.wa, r.wb);
    return r;
  } else if constexpr (KA == 1 && KB == 1) {
    return point_point<D>(a[0], b[0]);
  } else if constexpr (KA == 1 && KB == 2) {
    return point_segment<D>(a[0], b[0], b[1]);
  } else if constexpr (KA == 1 && KB == 3) {
    return point_triangle<D>(a[0], b[0], b[1], b[2]);
  } else if constexpr (KA == 2 && KB == 2) {
    return segment_segment<D>(a[0], a[1], b[0], b[1]);
  } else if constexpr (KA == 2 && KB == 3) {
    return segment_triangle<D>(a[0], a[1], b[0], b[1], b[2]);
  } else {
    static_assert(KA == 3 && KB == 3, "simplices have 1, 2 or 3 vertices");
    return triangle_triangle<D>(a, b);
  }
}

// [SECTION] Active set. The enumeration solves some 40 small systems for a triangle pair; the
// minimiser needs one. An active-set iteration walks to it: solve the face pair (the faces whose
// relative interiors hold the closest points), drop a vertex whose weight came out <= 0, add the
// vertex that most violates optimality, repeat. Its answer is accepted only with a certificate,
// the optimality condition of this convex problem with slack ε = 1e-12: with n = p - q and
// d = |n|, n·(a - p) >= -ε d |a - p| for every vertex a of A and n·(q - b) >= -ε d |q - b| for
// every vertex b of B. Then every a in A, b in B have |a - b| >= n̂·(a - b) >= d - ε (diam A +
// diam B): d is the distance to 1e-12 of the pair's size. Ties (parallel faces) pass, as they
// should. Anything else (rank-deficient faces, cycling, a noisy normal when d is tiny against
// the coordinates, non-finite input) falls back to the enumeration. Repeated queries on a slowly
// moving pair (resting contacts, conservative advancement) start from the last face pair and
// mostly finish in one solve.

// The face pair of an answer: bit i set when wa[i] > 0, bit 3 + i when wb[i] > 0.
inline unsigned face_pair_code(const std::array<double, 3>& wa, const std::array<double, 3>& wb) {
  unsigned code = 0;
  for (int i = 0; i < 3; ++i) code |= (wa[i] > 0 ? 1u : 0u) << i | (wb[i] > 0 ? 1u : 0u) << (3 + i);
  return code;
}

namespace prox_detail {

// Unconstrained least squares on the affine hulls of the face pair (fa[0..na) of A, fb[0..nb)
// of B): the weights of its minimiser (each face's summing to 1, possibly <= 0; 0 off the faces).
// False when the face pair is rank deficient.
template <int D, int N, int KA, int KB>
inline bool face_pair_weights(const Simplex<D, KA>& A, const Simplex<D, KB>& B, const int* fa,
                              int na, const int* fb, int nb, std::array<double, 3>& wa,
                              std::array<double, 3>& wb) {
  wa = {};
  wb = {};
  if constexpr (N == 0) {
    wa[fa[0]] = 1;
    wb[fb[0]] = 1;
    return true;
  } else {
    Eigen::Matrix<double, D, N> m;
    int col = 0;
    for (int k = 1; k < na; ++k) m.col(col++) = A[fa[k]] - A[fa[0]];
    for (int k = 1; k < nb; ++k) m.col(col++) = B[fb[0]] - B[fb[k]];
    Eigen::Matrix<double, N, 1> x;
    if (!solve_least_squares<D, N>(m, Vec<D>(B[fb[0]] - A[fa[0]]), x,
                                   [](const Eigen::Matrix<double, N, 1>&) { return true; }))
      return false;
    double sa = 0, sb = 0;
    col = 0;
    for (int k = 1; k < na; ++k) sa += (wa[fa[k]] = x[col++]);
    for (int k = 1; k < nb; ++k) sb += (wb[fb[k]] = x[col++]);
    wa[fa[0]] = 1 - sa;
    wb[fb[0]] = 1 - sb;
    return true;
  }
}

template <int D, int KA, int KB>
inline bool face_pair_weights(const Simplex<D, KA>& A, const Simplex<D, KB>& B, const int* fa,
                              int na, const int* fb, int nb, std::array<double, 3>& wa,
                              std::array<double, 3>& wb) {
  switch (na + nb - 2) {
    case 0: return face_pair_weights<D, 0, KA, KB>(A, B, fa, na, fb, nb, wa, wb);
    case 1: return face_pair_weights<D, 1, KA, KB>(A, B, fa, na, fb, nb, wa, wb);
    case 2: return face_pair_weights<D, 2, KA, KB>(A, B, fa, na, fb, nb, wa, wb);
    case 3:
      if constexpr (D >= 3) return face_pair_weights<D, 3, KA, KB>(A, B, fa, na, fb, nb, wa, wb);
      return false;
    case 4:
      if constexpr (D >= 4) return face_pair_weights<D, 4, KA, KB>(A, B, fa, na, fb, nb, wa, wb);
      return false;
    default: return false;  // more unknowns than dimensions: rank deficient
  }
}

// The face pair of the closest vertex pair: where a cold active-set run starts.
template <int D, int KA, int KB>
inline unsigned closest_vertex_code(const Simplex<D, KA>& A, const Simplex<D, KB>& B) {
  double best = std::numeric_limits<double>::infinity();
  unsigned code = 1u | 1u << 3;
  for (int i = 0; i < KA; ++i)
    for (int j = 0; j < KB; ++j) {
      const double d2 = (A[i] - B[j]).squaredNorm();
      if (d2 < best) best = d2, code = 1u << i | 1u << (3 + j);
    }
  return code;
}

// The active-set walk from face pair `code`; true with a certified answer in r (and its face pair
// in code), false when the caller must enumerate.
template <int D, int KA, int KB>
inline bool closest_points_active_set(const Simplex<D, KA>& A, const Simplex<D, KB>& B,
                                      unsigned& code, ClosestPoints<D>& r) {
  constexpr double kSlack = 1e-12;
  // The walk rarely needs more than 4 solves; past this it may be cycling. Sheets resting on each
  // other need more with their swaps (below): of 60 such walks that failed on the folded cloth, 0
  // finished within 8 solves, 55 within 12, and no more within 16 or 24.
  constexpr int kMaxSolves = 12;
  double sum = 0;  // non-finite input is the enumeration's to report (a NaN distance)
  for (const Vec<D>& v : A) sum += v.sum();
  for (const Vec<D>& v : B) sum += v.sum();
  if (!std::isfinite(sum)) return false;
  // A vertex added to a face pair can make it rank deficient: parallel faces (sheets resting on
  // each other), where the optimum lies on a face pair holding the new vertex but not one of the
  // old ones. Such a walk swaps: it drops the old vertices in turn (`swapped` marks those tried
  // since the add) until one leaves a face pair whose solution lies inside it, and the
  // optimality test below still certifies whatever it ends on.
  unsigned added = 0, swapped = 0, before_add = 0;
  auto next_swap = [&] {
    const unsigned left = before_add & ~swapped;  // old vertices not yet swapped out
    if (added == 0 || left == 0) return false;
    const unsigned out = left & (~left + 1);  // the lowest
    swapped |= out;
    code = (before_add | added) & ~out;
    return true;
  };
  for (int solve = 0; solve < kMaxSolves; ++solve) {
    int fa[3], fb[3], na = 0, nb = 0;
    for (int i = 0; i < KA; ++i)
      if (code >> i & 1u) fa[na++] = i;
    for (int j = 0; j < KB; ++j)
      if (code >> (3 + j) & 1u) fb[nb++] = j;
    std::array<double, 3> wa, wb;
    if (na == 0 || nb == 0 || !face_pair_weights<D, KA, KB>(A, B, fa, na, fb, nb, wa, wb)) {
      if (!next_swap()) return false;
      continue;
    }
    // Outside a face: drop the vertex with the smallest weight (<= 0) and solve again.
    unsigned drop = 0;
    double lowest = 0;
    for (int k = 0; k < na; ++k)
      if (!(wa[fa[k]] > lowest)) lowest = wa[fa[k]], drop = 1u << fa[k];
    for (int k = 0; k < nb; ++k)
      if (!(wb[fb[k]] > lowest)) lowest = wb[fb[k]], drop = 1u << (3 + fb[k]);
    if (drop != 0) {
      if (!(lowest == lowest)) return false;  // NaN
      if (swapped != 0) {  // a swap that does not hold the solution: the next one, if any
        if (!next_swap()) return false;
        continue;
      }
      code &= ~drop;
      continue;
    }
    added = 0;
    Vec<D> p = Vec<D>::Zero(), q = Vec<D>::Zero();
    for (int k = 0; k < na; ++k) p += wa[fa[k]] * A[fa[k]];
    for (int k = 0; k < nb; ++k) q += wb[fb[k]] * B[fb[k]];
    const Vec<D> n = p - q;
    const double d = n.norm();
    if (!(d > 0) || !std::isfinite(d)) return false;
    // Optimality: the most violated vertex joins its face (an active one violated means the solve
    // was too ill-conditioned to trust). An active vertex lies on the face through p, so its side
    // is zero but for rounding, which scales with the face, not with the vertex's distance to p:
    // near a vertex of the face (a tiny len) the first test alone would call rounding a violation
    // (seen on sheets resting on each other, whose nearly parallel triangles then went to the
    // enumeration). Worked out only then: the usual path is unchanged.
    auto face_extent = [&](const auto& S, const int* f, int nf, const Vec<D>& at) {
      double e = 0;
      for (int k = 0; k < nf; ++k) e = std::max(e, (S[f[k]] - at).norm());
      return e;
    };
    unsigned add = 0;
    double worst = -kSlack;
    for (int i = 0; i < KA; ++i) {
      const double len = (A[i] - p).norm(), side = (A[i] - p).dot(n);
      if (side >= -kSlack * d * len) continue;
      if (code >> i & 1u) {
        if (side >= -kSlack * d * face_extent(A, fa, na, p)) continue;
        return false;
      }
      const double v = side / (d * len);
      if (v < worst) worst = v, add = 1u << i;
    }
    for (int j = 0; j < KB; ++j) {
      const double len = (q - B[j]).norm(), side = (q - B[j]).dot(n);
      if (side >= -kSlack * d * len) continue;
      if (code >> (3 + j) & 1u) {
        if (side >= -kSlack * d * face_extent(B, fb, nb, q)) continue;
        return false;
      }
      const double v = side / (d * len);
      if (v < worst) worst = v, add = 1u << (3 + j);
    }
    if (add != 0) {
      before_add = code;
      added = add;
      swapped = 0;
      code |= add;
      continue;
    }
    r.distance = d;
    r.p = p;
    r.q = q;
    r.wa = wa;
    r.wb = wb;
    return true;
  }
  return false;
}

}  // namespace prox_detail

// Closest points of two simplices given by their vertices (K = 1, 2, 3), in argument order: exact
// (the certified active set of the section above, or the enumeration).
template <int D, int KA, int KB>
ClosestPoints<D> closest_points(const Simplex<D, KA>& a, const Simplex<D, KB>& b) {
  if constexpr ((KA == 1 && KB <= 2) || (KB == 1 && KA <= 2)) {
    return closest_points_enumerated<D, KA, KB>(a, b);  // closed forms: nothing to save
  } else {
    unsigned code = prox_detail::closest_vertex_code<D, KA, KB>(a, b);
    ClosestPoints<D> r;
    if (prox_detail::closest_points_active_set<D, KA, KB>(a, b, code, r)) return r;
    return closest_points_enumerated<D, KA, KB>(a, b);
  }
}

// The same, starting from the face pair `code` of an earlier answer (0: none) and updating it:
// a warm start for repeated queries on a slowly moving pair.
template <int D, int KA, int KB>
ClosestPoints<D> closest_points_warm(const Simplex<D, KA>& a, const Simplex<D, KB>& b,
                                     unsigned& code) {
  if (code == 0) code = prox_detail::closest_vertex_code<D, KA, KB>(a, b);
  ClosestPoints<D> r;
  if (prox_detail::closest_points_active_set<D, KA, KB>(a, b, code, r)) return r;
  r = closest_points_enumerated<D, KA, KB>(a, b);
  code = face_pair_code(r.wa, r.wb);
  return r;
}

}  // namespace s4d
