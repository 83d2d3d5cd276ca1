// The motion kernels of the coherent self queries (see motion_kernels.hpp), portable and AVX.
// Sections: [SECTION] Displacement fields, [SECTION] Gaps along a stored axis,
// [SECTION] Motion since a snapshot, [SECTION] Edge changes of the ring bounds
#include "proximity/motion_kernels.hpp"

#include <algorithm>
#include <limits>

#include "proximity/narrow_phase.hpp"
#include "proximity/separating_axes.hpp"

namespace s4d::prox_detail {

// [SECTION] Displacement fields

template <int D>
double centred_difference_portable(std::span<const Vec<D>> a, std::span<const Vec<D>> b,
                                   std::vector<Vec<D>>& out) {
  out.resize(a.size());
  if (a.empty()) return 0;
  Vec<D> lo = a[0] - b[0], hi = lo;
  Vec<D> zero = Vec<D>::Zero();  // stays zero while every coordinate is finite
  for (std::size_t v = 0; v < a.size(); ++v) {
    const Vec<D> u = a[v] - b[v];
    out[v] = u;
    lo = lo.cwiseMin(u);
    hi = hi.cwiseMax(u);
    zero += 0.0 * u;
  }
  if (!(zero.array() == 0.0).all()) return std::numeric_limits<double>::infinity();
  const Vec<D> c = 0.5 * (lo + hi);
  double r2 = 0;
  for (Vec<D>& u : out) {
    u -= c;
    r2 = std::max(r2, u.squaredNorm());
  }
  return std::sqrt(r2);
}

namespace {
#if S4D_X86
// The portable loop's operations on one register a point, its squared norms summed in the same
// order (avx4::sums4): the same bits.
S4D_AVX_TARGET double centred_difference_avx(const Vec<4>* a, const Vec<4>* b, Vec<4>* out, std::size_t n) {
  using avx4::load;
  const __m256d zero = _mm256_setzero_pd();
  __m256d lo = _mm256_sub_pd(load(a[0]), load(b[0])), hi = lo, finite = zero;
  for (std::size_t v = 0; v < n; ++v) {
    const __m256d u = _mm256_sub_pd(load(a[v]), load(b[v]));
    _mm256_storeu_pd(out[v].data(), u);
    lo = _mm256_min_pd(lo, u);
    hi = _mm256_max_pd(hi, u);
    finite = _mm256_add_pd(finite, _mm256_mul_pd(zero, u));
  }
  if (_mm256_movemask_pd(_mm256_cmp_pd(finite, zero, _CMP_EQ_OQ)) != 0xF)
    return std::numeric_limits<double>::infinity();
  const __m256d c = _mm256_mul_pd(_mm256_set1_pd(0.5), _mm256_add_pd(lo, hi));
  __m256d r2 = zero;
  std::size_t v = 0;
  for (; v + 4 <= n; v += 4) {
    __m256d sq[4];
    for (int j = 0; j < 4; ++j) {
      const __m256d u = _mm256_sub_pd(load(out[v + j]), c);
      _mm256_storeu_pd(out[v + j].data(), u);
      sq[j] = _mm256_mul_pd(u, u);
    }
    r2 = _mm256_max_pd(r2, avx4::sums4(sq[0], sq[1], sq[2], sq[3]));
  }
  for (; v < n; ++v) {
    const __m256d u = _mm256_sub_pd(load(out[v]), c);
    _mm256_storeu_pd(out[v].data(), u);
    const __m256d sq = _mm256_mul_pd(u, u);
    r2 = _mm256_max_pd(r2, avx4::sums4(sq, sq, sq, sq));
  }
  return std::sqrt(avx4::max_lane(r2));
}
#endif
}  // namespace

template <int D>
double centred_difference(std::span<const Vec<D>> a, std::span<const Vec<D>> b,
                          std::vector<Vec<D>>& out) {
#if S4D_X86
  if constexpr (D == 4)
    if (cpu::kHasAvx) {
      out.resize(a.size());
      if (a.empty()) return 0;
      return centred_difference_avx(a.data(), b.data(), out.data(), a.size());
    }
#endif
  return centred_difference_portable<D>(a, b, out);
}


// [SECTION] Gaps along a stored axis

#if S4D_X86
// axis_gap's bits for two triangles in R^4 and a stored axis: its dot products in Eigen's order
// (avx4::sums4); the extremes are exact whatever the order, and a NaN projection gives 0 as there.
S4D_AVX_TARGET double stored_axis_gap_avx(const Vec<4>* x, const Cell<3>& a, const Cell<3>& b,
                                          const float* axis) {
  using avx4::load;
  const __m256d n = _mm256_cvtps_pd(_mm_loadu_ps(axis));
  const __m256d nn = _mm256_mul_pd(n, n);
  const double len2 = _mm256_cvtsd_f64(avx4::sums4(nn, nn, nn, nn));
  if (!(len2 > 0)) return -std::numeric_limits<double>::infinity();
  const double len = std::sqrt(len2);
  const __m256d pa[3] = {_mm256_mul_pd(load(x[a[0]]), n), _mm256_mul_pd(load(x[a[1]]), n),
                         _mm256_mul_pd(load(x[a[2]]), n)};
  const __m256d pb[3] = {_mm256_mul_pd(load(x[b[0]]), n), _mm256_mul_pd(load(x[b[1]]), n),
                         _mm256_mul_pd(load(x[b[2]]), n)};
  const __m256d s1 = avx4::sums4(pa[0], pa[1], pa[2], pb[0]);  // a0, a2, a1, b0
  const __m256d s2 = avx4::sums4(pb[1], pb[2], pb[1], pb[2]);  // b1, b1, b2, b2
  const __m256d nan = _mm256_or_pd(_mm256_cmp_pd(s1, s1, _CMP_UNORD_Q), _mm256_cmp_pd(s2, s2, _CMP_UNORD_Q));
  if (_mm256_movemask_pd(nan) != 0) return 0;
  alignas(32) double d1[4], d2[4];
  _mm256_store_pd(d1, s1);
  _mm256_store_pd(d2, s2);
  const double lo_a = std::min(std::min(d1[0], d1[2]), d1[1]);  // the portable order: a0, a1, a2
  const double hi_a = std::max(std::max(d1[0], d1[2]), d1[1]);
  const double lo_b = std::min(std::min(d1[3], d2[0]), d2[2]);
  const double hi_b = std::max(std::max(d1[3], d2[0]), d2[2]);
  const double gap = std::max(lo_b - hi_a, lo_a - hi_b);
  const double scale = std::max(std::max(std::abs(lo_a), std::abs(hi_a)),
                                std::max(std::abs(lo_b), std::abs(hi_b)));
  return (gap - 1e-12 * scale) / len;
}
#endif

template <int D, int K>
double stored_axis_gap_portable(std::span<const Vec<D>> x, const Cell<K>& a, const Cell<K>& b,
                                const std::array<float, D>& axis) {
  Vec<D> n;
  for (int k = 0; k < D; ++k) n[k] = axis[k];
  if (!(n.squaredNorm() > 0)) return -std::numeric_limits<double>::infinity();
  return axis_gap<D, K, K>(gather<D, K>(x, a), gather<D, K>(x, b), n);
}

// [SECTION] Motion since a snapshot

namespace {
#if S4D_X86
// The portable snapshot motion's bits (see max_pair_distance2_3x3).
S4D_AVX_TARGET double snapshot_motion_avx(const Vec<4>* x, const Cell<3>& a, const Cell<3>& b,
                                          const Vec<4>* x0) {
  using avx4::load;
  __m256d p[3], q[3];
  for (int i = 0; i < 3; ++i) {
    p[i] = _mm256_sub_pd(load(x[a[i]]), load(x0[i]));
    q[i] = _mm256_sub_pd(load(x[b[i]]), load(x0[3 + i]));
  }
  return std::sqrt(max_pair_distance2_3x3(p, q));
}
#endif

}  // namespace

template <int D, int K>
double motion_since_snapshot(std::span<const Vec<D>> x, const Cell<K>& a, const Cell<K>& b,
                             const std::array<Vec<D>, 2 * K>& x0) {
#if S4D_X86
  if constexpr (D == 4 && K == 3)
    if (cpu::kHasAvx) return snapshot_motion_avx(x.data(), a, b, x0.data());
#endif
  std::array<Vec<D>, 2 * K> d;
  for (int i = 0; i < K; ++i) {
    d[i] = x[a[i]] - x0[i];
    d[K + i] = x[b[i]] - x0[K + i];
  }
  double m2 = 0;
  for (int i = 0; i < K; ++i)
    for (int j = K; j < 2 * K; ++j) m2 = std::max(m2, (d[i] - d[j]).squaredNorm());
  return m2 == m2 ? std::sqrt(m2) : std::numeric_limits<double>::infinity();
}

// [SECTION] Edge changes of the ring bounds

namespace {
// a[p] = max(a[p], to_p) and a[q] = max(a[q], to_q) for an edge (p, q): the maxima's scalar step,
// a NaN value dropped (std::max keeps a).
inline void raise_ends(double* a, const std::array<int, 2>& e, double to_p, double to_q) {
  a[e[0]] = std::max(a[e[0]], to_p);
  a[e[1]] = std::max(a[e[1]], to_q);
}

#if S4D_X86
// a[first .. first + 3] = max(a[...], m) lane by lane; a NaN in m leaves a (as std::max(a, m)).
S4D_AVX_INLINE void raise4(double* a, int first, __m256d m) {
  _mm256_storeu_pd(a + first, _mm256_max_pd(m, _mm256_loadu_pd(a + first)));
}

// The first pass of the ring bounds for whole groups of four edges: their squared changes in
// registers (the portable bits, see avx4::sums4), then the maxima, four vertices at once for a
// strided group (max is exact: any order gives the same bits). Returns how many edges it did
// (the portable loop does the rest).
S4D_AVX_TARGET std::size_t edge_maxima_avx(const Vec<4>* u, const std::array<int, 2>* edges, std::size_t ne,
                                           const std::uint8_t* strided, std::size_t groups, double* own) {
  using avx4::load;
  std::size_t i = 0;
  for (; i + 4 <= ne; i += 4) {
    const std::array<int, 2>* e = edges + i;
    __m256d sq[4];
    if (i / 4 < groups && strided[i / 4]) {
      const Vec<4>* ua = u + e[0][0];
      const Vec<4>* ub = u + e[0][1];
      for (int j = 0; j < 4; ++j) {
        const __m256d d = _mm256_sub_pd(load(ua[j]), load(ub[j]));
        sq[j] = _mm256_mul_pd(d, d);
      }
      const __m256d d2 = avx4::sums4(sq[0], sq[1], sq[2], sq[3]);  // edges 0, 2, 1, 3
      const __m128d lo = _mm256_castpd256_pd128(d2), hi = _mm256_extractf128_pd(d2, 1);
      const __m256d in_order = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_unpacklo_pd(lo, hi)),
                                                    _mm_unpackhi_pd(lo, hi), 1);
      raise4(own, e[0][0], in_order);
      raise4(own, e[0][1], in_order);  // after the first: the two may overlap
      continue;
    }
    for (int j = 0; j < 4; ++j) {
      const __m256d d = _mm256_sub_pd(load(u[e[j][0]]), load(u[e[j][1]]));
      sq[j] = _mm256_mul_pd(d, d);
    }
    const __m256d d2 = avx4::sums4(sq[0], sq[1], sq[2], sq[3]);  // edges 0, 2, 1, 3
    alignas(32) double d2s[4];
    _mm256_store_pd(d2s, d2);
    constexpr int kLane[4] = {0, 2, 1, 3};
    for (int j = 0; j < 4; ++j) {
      const double d = d2s[kLane[j]];
      raise_ends(own, e[j], d, d);
    }
  }
  return i;
}

// around[v] = max(around[v], own[w]) for both ends of whole groups of four edges, four vertices
// at once for a strided group. Returns how many edges it did.
S4D_AVX_TARGET std::size_t neighbour_maxima_avx(const double* own, const std::array<int, 2>* edges,
                                                std::size_t ne, const std::uint8_t* strided,
                                                std::size_t groups, double* around) {
  std::size_t i = 0;
  for (; i + 4 <= ne; i += 4) {
    const std::array<int, 2>* e = edges + i;
    if (i / 4 < groups && strided[i / 4]) {
      const int a = e[0][0], b = e[0][1];
      raise4(around, a, _mm256_loadu_pd(own + b));
      raise4(around, b, _mm256_loadu_pd(own + a));
      continue;
    }
    for (int j = 0; j < 4; ++j) {
      raise_ends(around, e[j], own[e[j][1]], own[e[j][0]]);
    }
  }
  return i;
}

// ring[k] = 2 B + C for the strided groups of eight triangles (CellTopology::strided_cell_groups):
// each parity's four cells from three loads of four consecutive vertices, then interleaved.
S4D_AVX_TARGET void strided_cell_bounds_avx(const Cell<3>* c, const std::uint8_t* strided,
                                            std::size_t groups, const double* own,
                                            const double* around, double* ring) {
  const __m256d two = _mm256_set1_pd(2.0);
  for (std::size_t g = 0; g < groups; ++g) {
    if (!strided[g]) continue;
    __m256d r[2];
    for (int p = 0; p < 2; ++p) {
      const Cell<3>& first = c[8 * g + p];
      __m256d b = _mm256_loadu_pd(own + first[0]), cc = _mm256_loadu_pd(around + first[0]);
      for (int i = 1; i < 3; ++i) {
        b = _mm256_max_pd(b, _mm256_loadu_pd(own + first[i]));
        cc = _mm256_max_pd(cc, _mm256_loadu_pd(around + first[i]));
      }
      r[p] = _mm256_add_pd(_mm256_mul_pd(two, b), cc);  // cells 8g + p + 2m in lane m
    }
    const __m256d lo = _mm256_unpacklo_pd(r[0], r[1]), hi = _mm256_unpackhi_pd(r[0], r[1]);
    _mm256_storeu_pd(ring + 8 * g, _mm256_permute2f128_pd(lo, hi, 0x20));
    _mm256_storeu_pd(ring + 8 * g + 4, _mm256_permute2f128_pd(lo, hi, 0x31));
  }
}

// sqrt(a[v]) in place for whole groups of four (sqrt rounds correctly either way: the same
// bits); returns how many it did.
S4D_AVX_TARGET int square_roots_avx(double* a, int n) {
  int v = 0;
  for (; v + 4 <= n; v += 4) _mm256_storeu_pd(a + v, _mm256_sqrt_pd(_mm256_loadu_pd(a + v)));
  return v;
}
#endif

}  // namespace

template <int D>
void raise_to_edge_changes(const Vec<D>* u, std::span<const std::array<int, 2>> edges,
                           std::span<const std::uint8_t> strided, double* own) {
  std::size_t done = 0;
#if S4D_X86
  if constexpr (D == 4)
    if (cpu::kHasAvx)
      done = edge_maxima_avx(u, edges.data(), edges.size(), strided.data(), strided.size(), own);
#endif
  for (std::size_t i = done; i < edges.size(); ++i) {
    const auto& e = edges[i];
    const double d = (u[e[0]] - u[e[1]]).squaredNorm();
    raise_ends(own, e, d, d);
  }
}

void square_roots(double* a, int n) {
  int done = 0;
#if S4D_X86
  if (cpu::kHasAvx) done = square_roots_avx(a, n);
#endif
  for (int v = done; v < n; ++v) a[v] = std::sqrt(a[v]);
}

template <int D, int K>
void ring_motion_bounds(const Vec<D>* u, const CellTopology<K>& topo, std::span<const Cell<K>> cells,
                        std::vector<double>& own_v, std::vector<double>& around_v,
                        std::vector<double>& ring_v) {
  // Raw pointers: through the vectors, every store would make the compiler reload their data.
  const int nv = topo.vertex_count, nc = static_cast<int>(cells.size());
  own_v.assign(nv, 0.0);
  double* own = own_v.data();  // per vertex: the largest |u_p - u_q|² of its edges
  raise_to_edge_changes<D>(u, topo.edges, topo.strided_edge_groups, own);
  around_v.assign(own_v.begin(), own_v.end());
  double* around = around_v.data();  // the same over the vertex and its neighbours
  std::size_t done = 0;
#if S4D_X86
  if (cpu::kHasAvx)
    done = neighbour_maxima_avx(own, topo.edges.data(), topo.edges.size(),
                                topo.strided_edge_groups.data(), topo.strided_edge_groups.size(), around);
#endif
  for (std::size_t i = done; i < topo.edges.size(); ++i) {
    const auto& e = topo.edges[i];
    raise_ends(around, e, own[e[1]], own[e[0]]);
  }
  // Roots once a vertex (monotone: the same as once a cell).
  square_roots(own, nv);
  square_roots(around, nv);
  ring_v.resize(nc);
  double* ring = ring_v.data();
  const Cell<K>* c = cells.data();
  const std::vector<std::uint8_t>& strided = topo.strided_cell_groups;
  bool vector_groups = false;
#if S4D_X86
  if constexpr (K == 3)
    if (cpu::kHasAvx && strided.size() == static_cast<std::size_t>(nc) / 8) {
      strided_cell_bounds_avx(c, strided.data(), strided.size(), own, around, ring);
      vector_groups = true;
    }
#endif
  for (int k = 0; k < nc; ++k) {
    if (vector_groups && static_cast<std::size_t>(k / 8) < strided.size() && strided[k / 8]) {
      k += 7;  // done above
      continue;
    }
    double b = own[c[k][0]], cc = around[c[k][0]];
    for (int i = 1; i < K; ++i) {
      b = std::max(b, own[c[k][i]]);
      cc = std::max(cc, around[c[k][i]]);
    }
    ring[k] = 2 * b + cc;
  }
}

#define S4D_INSTANTIATE_CELLS(D, K)                                                                \
  template void ring_motion_bounds<D, K>(const Vec<D>*, const CellTopology<K>&,                    \
                                         std::span<const Cell<K>>, std::vector<double>&,           \
                                         std::vector<double>&, std::vector<double>&);              \
  template double stored_axis_gap_portable<D, K>(std::span<const Vec<D>>, const Cell<K>&,          \
                                                 const Cell<K>&, const std::array<float, D>&);     \
  template double motion_since_snapshot<D, K>(std::span<const Vec<D>>, const Cell<K>&,             \
                                              const Cell<K>&, const std::array<Vec<D>, 2 * K>&);
#define S4D_INSTANTIATE(D)                                                                         \
  template double centred_difference<D>(std::span<const Vec<D>>, std::span<const Vec<D>>,          \
                                        std::vector<Vec<D>>&);                                     \
  template double centred_difference_portable<D>(std::span<const Vec<D>>, std::span<const Vec<D>>, \
                                                 std::vector<Vec<D>>&);                            \
  template void raise_to_edge_changes<D>(const Vec<D>*, std::span<const std::array<int, 2>>,       \
                                         std::span<const std::uint8_t>, double*);                  \
  S4D_INSTANTIATE_CELLS(D, 2)                                                                      \
  S4D_INSTANTIATE_CELLS(D, 3)
S4D_INSTANTIATE(2)
S4D_INSTANTIATE(3)
S4D_INSTANTIATE(4)
#undef S4D_INSTANTIATE
#undef S4D_INSTANTIATE_CELLS

}  // namespace s4d::prox_detail
