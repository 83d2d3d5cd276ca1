// The spring loop: a portable kernel for every D and exponent, and for linear springs in R^4 (the
// cloth of every 4D scene) one that does four springs at a time when the CPU has AVX. Measured on
// the 64² cloth's 24k springs: 300 µs → 165 µs a pass.
#include "physics/spring_forces.hpp"

#include <cmath>

#include "core/avx4.hpp"

namespace s4d {

namespace {

// One reciprocal square root a spring, no vector division, and the exponent's branch taken once
// outside the loop.
template <int D, bool Linear>
void spring_forces(std::span<const Spring> springs, double beta, double kd,
                   std::span<const Vec<D>> x, std::span<const Vec<D>> v, std::span<Vec<D>> force) {
  for (const Spring& s : springs) {
    const Vec<D> d = x[s.b] - x[s.a];
    const double len2 = d.squaredNorm();
    if (!(len2 > 1e-24)) continue;  // coincident ends: no direction to pull along
    const double inv = 1 / std::sqrt(len2);
    const double e = len2 * inv - s.rest;
    // Paper Eq. 1: |F| = k |e|^(1+β), along the spring, towards rest length.
    double mag;
    if constexpr (Linear)
      mag = s.k * e;
    else
      mag = std::copysign(s.k * std::pow(std::abs(e), 1 + beta), e);
    const double damp = kd * (v[s.b] - v[s.a]).dot(d) * inv;
    const Vec<D> f = ((mag + damp) * inv) * d;
    force[s.a] += f;
    force[s.b] -= f;
  }
}

#if S4D_X86
using avx4::load;

S4D_AVX_INLINE void add_force(Vec<4>& fa, Vec<4>& fb, __m256d f) {
  _mm256_storeu_pd(fa.data(), _mm256_add_pd(load(fa), f));
  _mm256_storeu_pd(fb.data(), _mm256_sub_pd(load(fb), f));
}

// No fused multiply-add (FMA is not part of "avx"): every product is rounded as in the portable
// kernel.
S4D_AVX_TARGET void linear_springs_avx_kernel(std::span<const Spring> springs, double kd,
                                              std::span<const Vec<4>> x, std::span<const Vec<4>> v,
                                              std::span<Vec<4>> force) {
  const std::size_t n = springs.size();
  const __m256d tiny = _mm256_set1_pd(1e-24), one = _mm256_set1_pd(1.0), kdv = _mm256_set1_pd(kd);
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    const Spring* s = springs.data() + i;
    __m256d d[4], p[4], q[4];
    for (int j = 0; j < 4; ++j) {
      d[j] = _mm256_sub_pd(load(x[s[j].b]), load(x[s[j].a]));
      p[j] = _mm256_mul_pd(d[j], d[j]);
      q[j] = _mm256_mul_pd(_mm256_sub_pd(load(v[s[j].b]), load(v[s[j].a])), d[j]);
    }
    const __m256d len2 = avx4::sums4(p[0], p[1], p[2], p[3]);
    if (_mm256_movemask_pd(_mm256_cmp_pd(len2, tiny, _CMP_GT_OQ)) != 0xF) {
      // Coincident (or non-finite) ends in this group: the portable kernel skips them.
      spring_forces<4, true>(springs.subspan(i, 4), 0, kd, x, v, force);
      continue;
    }
    const __m256d inv = _mm256_div_pd(one, _mm256_sqrt_pd(len2));
    // Lanes in the order of sums4: springs 0, 2, 1, 3.
    const __m256d rest = _mm256_set_pd(s[3].rest, s[1].rest, s[2].rest, s[0].rest);
    const __m256d k = _mm256_set_pd(s[3].k, s[1].k, s[2].k, s[0].k);
    const __m256d mag = _mm256_mul_pd(k, _mm256_sub_pd(_mm256_mul_pd(len2, inv), rest));
    const __m256d damp = _mm256_mul_pd(_mm256_mul_pd(kdv, avx4::sums4(q[0], q[1], q[2], q[3])), inv);
    alignas(32) double c[4];
    _mm256_store_pd(c, _mm256_mul_pd(_mm256_add_pd(mag, damp), inv));
    constexpr int kLane[4] = {0, 2, 1, 3};
    for (int j = 0; j < 4; ++j)
      add_force(force[s[j].a], force[s[j].b], _mm256_mul_pd(_mm256_set1_pd(c[kLane[j]]), d[j]));
  }
  spring_forces<4, true>(springs.subspan(i), 0, kd, x, v, force);
}
#endif  // S4D_X86

}  // namespace

namespace spring_detail {

void linear_springs_portable(std::span<const Spring> springs, double kd, std::span<const Vec<4>> x,
                             std::span<const Vec<4>> v, std::span<Vec<4>> force) {
  spring_forces<4, true>(springs, 0, kd, x, v, force);
}

bool linear_springs_avx(std::span<const Spring> springs, double kd, std::span<const Vec<4>> x,
                        std::span<const Vec<4>> v, std::span<Vec<4>> force) {
#if S4D_X86
  if (!cpu::kHasAvx) return false;
  linear_springs_avx_kernel(springs, kd, x, v, force);
  return true;
#else
  return false;
#endif
}

}  // namespace spring_detail

template <int D>
void add_spring_forces(const Model<D>& model, std::span<const Vec<D>> x, std::span<const Vec<D>> v,
                       std::span<Vec<D>> force) {
  const double beta = model.params.beta;
  const double kd = model.params.spring_damping;
  if (beta != 0) return spring_forces<D, false>(model.springs, beta, kd, x, v, force);
  if constexpr (D == 4)
    if (spring_detail::linear_springs_avx(model.springs, kd, x, v, force)) return;
  spring_forces<D, true>(model.springs, beta, kd, x, v, force);
}

template void add_spring_forces<2>(const Model<2>&, std::span<const Vec<2>>, std::span<const Vec<2>>,
                                   std::span<Vec<2>>);
template void add_spring_forces<3>(const Model<3>&, std::span<const Vec<3>>, std::span<const Vec<3>>,
                                   std::span<Vec<3>>);
template void add_spring_forces<4>(const Model<4>&, std::span<const Vec<4>>, std::span<const Vec<4>>,
                                   std::span<Vec<4>>);

}  // namespace s4d
