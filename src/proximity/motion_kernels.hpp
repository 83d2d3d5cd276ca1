// The motion kernels the coherent self queries rest on (self_proximity.hpp): displacement fields,
// the relative motion of two cells' vertices, the gap along a stored axis, and the edge changes
// behind the ring bounds. For triangles in R^4 each picks an AVX path at run time (core/cpu.hpp)
// that gives the portable path's bits; the *_portable forms are there for the tests to compare.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/avx4.hpp"
#include "core/vec.hpp"
#include "proximity/cell_topology.hpp"
#include "proximity/cells.hpp"

namespace s4d::prox_detail {

// out = a - b less the centre of its bounding box; returns the radius of the ball about that
// centre that holds every out[v] (+inf if one is not finite).
template <int D>
double centred_difference(std::span<const Vec<D>> a, std::span<const Vec<D>> b,
                          std::vector<Vec<D>>& out);
template <int D>
double centred_difference_portable(std::span<const Vec<D>> a, std::span<const Vec<D>> b,
                                   std::vector<Vec<D>>& out);

// The gap of cells a and b at x along a stored (float) axis: a lower bound of their distance,
// -inf when the axis is zero. The dispatch is inline (stored_axis_gap, below): the step query
// asks it of thousands of pairs.
template <int D, int K>
double stored_axis_gap_portable(std::span<const Vec<D>> x, const Cell<K>& a, const Cell<K>& b,
                                const std::array<float, D>& axis);
#if S4D_X86
double stored_axis_gap_avx(const Vec<4>* x, const Cell<3>& a, const Cell<3>& b, const float* axis);
#endif

// The relative motion of cells a and b since a snapshot x0 (a's vertices, then b's):
// max |(x_i - x0_i) - (x_j - x0_j)| over vertices i of a and j of b.
template <int D, int K>
double motion_since_snapshot(std::span<const Vec<D>> x, const Cell<K>& a, const Cell<K>& b,
                             const std::array<Vec<D>, 2 * K>& x0);

// own[v] = max(own[v], |u_p - u_q|²) over the edges (p, q) at each vertex v. `strided` marks the
// whole groups of four edges that are runs (CellTopology::strided_edge_groups; may be empty).
template <int D>
void raise_to_edge_changes(const Vec<D>* u, std::span<const std::array<int, 2>> edges,
                           std::span<const std::uint8_t> strided, double* own);
// a[v] = sqrt(a[v]) for v < n.
void square_roots(double* a, int n);

// ring[c], for every cell c, bounds M_cb = max |u_i - u_j| (i of c, j of b) over every ring
// partner b of c: 2 B + C, where B is the largest |u_p - u_q| over the edges at c's vertices and
// C the same over the edges at their neighbours. Any i of c joins any j of b through an edge of c
// (i to p, at p), the ring edge (p to q, at p) and an edge of b (q to j, at q, a neighbour of p).
// Never more than the 3 C of one maximum over all three, and less where the motion is uneven.
// own and around are scratch (nv each): per vertex, B's and C's terms.
template <int D, int K>
void ring_motion_bounds(const Vec<D>* u, const CellTopology<K>& topo, std::span<const Cell<K>> cells,
                        std::vector<double>& own, std::vector<double>& around,
                        std::vector<double>& ring);

#if S4D_X86
// max |p_i - q_j|² over three points p and three q in R^4, the portable loop's bits: each squared
// norm summed in its order (avx4::sums4), and a NaN one skipped as std::max(m2, NaN) skips it.
S4D_AVX_INLINE double max_pair_distance2_3x3(const __m256d p[3], const __m256d q[3]) {
  __m256d s[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const __m256d d = _mm256_sub_pd(p[i], q[j]);
      s[3 * i + j] = _mm256_mul_pd(d, d);
    }
  __m256d m = _mm256_setzero_pd();  // max_pd(new, m) keeps m where new is NaN
  m = _mm256_max_pd(avx4::sums4(s[0], s[1], s[2], s[3]), m);
  m = _mm256_max_pd(avx4::sums4(s[4], s[5], s[6], s[7]), m);
  m = _mm256_max_pd(avx4::sums4(s[8], s[8], s[8], s[8]), m);
  return avx4::max_lane(m);
}

S4D_AVX_TARGET inline double max_relative_avx(const Vec<4>* u, const Cell<3>& a, const Cell<3>& b) {
  const __m256d p[3] = {avx4::load(u[a[0]]), avx4::load(u[a[1]]), avx4::load(u[a[2]])};
  const __m256d q[3] = {avx4::load(u[b[0]]), avx4::load(u[b[1]]), avx4::load(u[b[2]])};
  return std::sqrt(max_pair_distance2_3x3(p, q));
}
#endif

// max |u_i - u_j| over vertices i of cell a and j of cell b. Inline: the step query asks it of
// thousands of pairs.
template <int D, int K>
inline double max_relative_portable(const std::vector<Vec<D>>& u, const Cell<K>& a,
                                    const Cell<K>& b) {
  double m2 = 0;
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < K; ++j) m2 = std::max(m2, (u[a[i]] - u[b[j]]).squaredNorm());
  return std::sqrt(m2);
}
// The same (the AVX path for triangles in R^4).
template <int D, int K>
inline double max_relative(const std::vector<Vec<D>>& u, const Cell<K>& a, const Cell<K>& b) {
#if S4D_X86
  if constexpr (D == 4 && K == 3)
    if (cpu::kHasAvx) return max_relative_avx(u.data(), a, b);
#endif
  return max_relative_portable<D, K>(u, a, b);
}

template <int D, int K>
inline double stored_axis_gap(std::span<const Vec<D>> x, const Cell<K>& a, const Cell<K>& b,
                              const std::array<float, D>& axis) {
#if S4D_X86
  if constexpr (D == 4 && K == 3)
    if (cpu::kHasAvx) return stored_axis_gap_avx(x.data(), a, b, axis.data());
#endif
  return stored_axis_gap_portable<D, K>(x, a, b, axis);
}

}  // namespace s4d::prox_detail
