// The vertex pass of a substep (see vertex_pass.hpp): portable for every D, and for R^4 a path
// with one point a 256-bit register when the CPU has AVX.
#include "physics/vertex_pass.hpp"

#include <algorithm>
#include <cmath>

#include "core/avx4.hpp"

namespace s4d {

namespace {

template <int D>
inline void start_force(const VertexArrays<D>& a, int i, const Vec<D>& gravity, double damping) {
  a.force[i] = a.mass[i] * gravity + a.f_ext[i] - damping * a.v[i];
}

// The paper clamps any motion between two frames: it keeps contacts from being skipped between
// proximity queries (the fail-safe would catch them, at the price of a freeze).
template <int D>
inline void clamp(const VertexArrays<D>& a, int i, bool pinned, double limit, int& clamps) {
  const Vec<D> d = a.x[i] - a.x0[i];
  if (!(d.squaredNorm() > limit * limit)) return;  // the common case, without a square root
  const double len = d.norm();
  if (len > limit) {
    a.x[i] = a.x0[i] + d * (limit / len);
    if (!pinned) a.v[i] *= limit / len;
    ++clamps;
  }
}

template <int D>
inline void update(const VertexArrays<D>& a, const VertexPassParams<D>& p, int i,
                   VertexPassResult<D>& r) {
  Vec<D>& x = a.x[i];
  Vec<D>& v = a.v[i];
  const bool pinned = a.pinned[i] != 0;
  if (pinned) {
    x = a.x0[i] + p.along * (a.target[i] - a.x0[i]);
    v = (a.target[i] - a.x0[i]) / p.dt;
  } else {
    // Paper Eq. 4: a = F/m, v += h a, x += h v (the new velocity moves the position).
    v += (p.h * a.inv_mass[i]) * a.force[i];
    x += p.h * v;
  }
  if (!p.last) return start_force(a, i, p.gravity, p.damping);
  // Pinned vertices follow their targets at any speed.
  if (!pinned) r.fastest2 = std::max(r.fastest2, v.squaredNorm());
  r.nonfinite += 0.0 * x + 0.0 * v;
  clamp(a, i, pinned, p.limit, r.clamps);
}

template <int D>
void pass(const VertexArrays<D>& a, const VertexPassParams<D>& p, VertexPassResult<D>& r) {
  const int n = static_cast<int>(a.x.size());
  for (int i = 0; i < n; ++i) update(a, p, i, r);
}

#if S4D_X86
using avx4::load;

S4D_AVX_INLINE void store(Vec<4>& p, __m256d v) { _mm256_storeu_pd(p.data(), v); }

// Eigen's order for the squared norm of a point of R^4 in SSE2 pairs: (p0 + p2) + (p1 + p3).
S4D_AVX_INLINE double squared_norm(__m256d d) {
  const __m256d q = _mm256_mul_pd(d, d);
  const __m128d s = _mm_add_pd(_mm256_castpd256_pd128(q), _mm256_extractf128_pd(q, 1));
  return _mm_cvtsd_f64(_mm_add_sd(s, _mm_unpackhi_pd(s, s)));
}

// start_force's operations on one register: (m g + f_ext) - c v.
S4D_AVX_INLINE void start_force_avx(const VertexArrays<4>& a, int i, __m256d g, __m256d damping,
                                    __m256d v) {
  const __m256d weight = _mm256_mul_pd(_mm256_set1_pd(a.mass[i]), g);
  store(a.force[i], _mm256_sub_pd(_mm256_add_pd(weight, load(a.f_ext[i])), _mm256_mul_pd(damping, v)));
}

S4D_AVX_TARGET void pass_avx_kernel(const VertexArrays<4>& a, const VertexPassParams<4>& p,
                                    VertexPassResult<4>& r) {
  const int n = static_cast<int>(a.x.size());
  const __m256d h = _mm256_set1_pd(p.h), along = _mm256_set1_pd(p.along);
  const __m256d dt = _mm256_set1_pd(p.dt), damping = _mm256_set1_pd(p.damping);
  const __m256d g = load(p.gravity), zero = _mm256_setzero_pd();
  const double limit2 = p.limit * p.limit;
  __m256d nonfinite = load(r.nonfinite);
  double fastest2 = r.fastest2;
  for (int i = 0; i < n; ++i) {
    const bool pinned = a.pinned[i] != 0;
    __m256d x, v;
    if (pinned) {
      const __m256d x0 = load(a.x0[i]);
      const __m256d to = _mm256_sub_pd(load(a.target[i]), x0);
      x = _mm256_add_pd(x0, _mm256_mul_pd(along, to));
      v = _mm256_div_pd(to, dt);
    } else {
      const __m256d c = _mm256_set1_pd(p.h * a.inv_mass[i]);
      v = _mm256_add_pd(load(a.v[i]), _mm256_mul_pd(c, load(a.force[i])));
      x = _mm256_add_pd(load(a.x[i]), _mm256_mul_pd(h, v));
    }
    store(a.x[i], x);
    store(a.v[i], v);
    if (!p.last) {
      start_force_avx(a, i, g, damping, v);
      continue;
    }
    // std::max drops a NaN squared norm here as in the portable pass; the sum below keeps it.
    if (!pinned) fastest2 = std::max(fastest2, squared_norm(v));
    nonfinite =
        _mm256_add_pd(nonfinite, _mm256_add_pd(_mm256_mul_pd(zero, x), _mm256_mul_pd(zero, v)));
    if (squared_norm(_mm256_sub_pd(x, load(a.x0[i]))) > limit2)
      clamp(a, i, pinned, p.limit, r.clamps);
  }
  store(r.nonfinite, nonfinite);
  r.fastest2 = fastest2;
}

S4D_AVX_TARGET void start_step_avx(const VertexArrays<4>& a, Vec<4>* x0, const Vec<4>& gravity,
                                   double damping) {
  const int n = static_cast<int>(a.x.size());
  const __m256d g = load(gravity), c = _mm256_set1_pd(damping);
  for (int i = 0; i < n; ++i) {
    store(x0[i], load(a.x[i]));
    start_force_avx(a, i, g, c, load(a.v[i]));
  }
}
#endif  // S4D_X86

}  // namespace

namespace vertex_detail {

void pass_portable(const VertexArrays<4>& a, const VertexPassParams<4>& p, VertexPassResult<4>& r) {
  pass<4>(a, p, r);
}

bool pass_avx(const VertexArrays<4>& a, const VertexPassParams<4>& p, VertexPassResult<4>& r) {
#if S4D_X86
  if (!cpu::kHasAvx) return false;
  pass_avx_kernel(a, p, r);
  return true;
#else
  return false;
#endif
}

}  // namespace vertex_detail

template <int D>
void start_step(const VertexArrays<D>& a, std::span<Vec<D>> x0, const Vec<D>& gravity, double damping) {
#if S4D_X86
  if constexpr (D == 4)
    if (cpu::kHasAvx) return start_step_avx(a, x0.data(), gravity, damping);
#endif
  const int n = static_cast<int>(a.x.size());
  for (int i = 0; i < n; ++i) {
    x0[i] = a.x[i];
    start_force(a, i, gravity, damping);
  }
}

template <int D>
void vertex_pass(const VertexArrays<D>& a, const VertexPassParams<D>& p, VertexPassResult<D>& r) {
  if constexpr (D == 4)
    if (vertex_detail::pass_avx(a, p, r)) return;
  pass<D>(a, p, r);
}

#define S4D_INSTANTIATE(D)                                                                       \
  template void start_step<D>(const VertexArrays<D>&, std::span<Vec<D>>, const Vec<D>&, double); \
  template void vertex_pass<D>(const VertexArrays<D>&, const VertexPassParams<D>&, VertexPassResult<D>&);
S4D_INSTANTIATE(2)
S4D_INSTANTIATE(3)
S4D_INSTANTIATE(4)
#undef S4D_INSTANTIATE

}  // namespace s4d
