// Helpers for AVX kernels on R^4 points (one point = one 256-bit register), shared by the kernels
// that pick an AVX path at run time (see cpu.hpp). Include only where S4D_X86 holds, and call
// only from functions marked S4D_AVX_TARGET (or S4D_AVX_INLINE). No FMA: products round as in SSE2.
#pragma once
#include "core/cpu.hpp"

#if S4D_X86
#include <immintrin.h>

#include "core/vec.hpp"

#define S4D_AVX_INLINE S4D_AVX_TARGET __attribute__((always_inline)) inline

namespace s4d::avx4 {

S4D_AVX_INLINE __m256d load(const Vec<4>& p) { return _mm256_loadu_pd(p.data()); }

// The sums of the coordinates of four R^4 vectors, each in Eigen's order for SSE2 pairs,
// (p0 + p2) + (p1 + p3), so that a dot product or squared norm built on it equals the portable
// one bit for bit. Lanes come out as vectors 0, 2, 1, 3.
S4D_AVX_INLINE __m256d sums4(__m256d p0, __m256d p1, __m256d p2, __m256d p3) {
  const __m256d s01 = _mm256_add_pd(_mm256_permute2f128_pd(p0, p1, 0x20),
                                    _mm256_permute2f128_pd(p0, p1, 0x31));
  const __m256d s23 = _mm256_add_pd(_mm256_permute2f128_pd(p2, p3, 0x20),
                                    _mm256_permute2f128_pd(p2, p3, 0x31));
  return _mm256_hadd_pd(s01, s23);
}

// The largest lane.
S4D_AVX_INLINE double max_lane(__m256d v) {
  const __m128d m = _mm_max_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
  return _mm_cvtsd_f64(_mm_max_sd(m, _mm_unpackhi_pd(m, m)));
}

}  // namespace s4d::avx4

#endif  // S4D_X86
