// The AVX path of the cell boxes (see cell_boxes.hpp).
#include "proximity/cell_boxes.hpp"

#include "core/avx4.hpp"

namespace s4d::prox_detail {

#if S4D_X86
namespace {
// The portable loop's operations, one register a point: min and max are exact, and the
// finiteness sum is NaN exactly when the portable one is.
template <int T>
S4D_AVX_TARGET void boxes_avx(const std::array<const Vec<4>*, T>& x, const Cell<3>* cells, std::size_t n,
                              Box<4>* out) {
  const __m256d zero = _mm256_setzero_pd();
  const __m256d inf = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  const __m256d minus_inf = _mm256_set1_pd(-std::numeric_limits<double>::infinity());
  for (std::size_t c = 0; c < n; ++c) {
    const Cell<3>& cell = cells[c];
    __m256d lo = avx4::load(x[0][cell[0]]), hi = lo, finite = zero;
    for (int t = 0; t < T; ++t)
      for (int i = 0; i < 3; ++i) {
        const __m256d p = avx4::load(x[t][cell[i]]);
        lo = _mm256_min_pd(lo, p);
        hi = _mm256_max_pd(hi, p);
        finite = _mm256_add_pd(finite, _mm256_mul_pd(zero, p));
      }
    if (_mm256_movemask_pd(_mm256_cmp_pd(finite, zero, _CMP_EQ_OQ)) != 0xF) {
      lo = minus_inf;
      hi = inf;
    }
    _mm256_storeu_pd(out[c].lo.data(), lo);
    _mm256_storeu_pd(out[c].hi.data(), hi);
  }
}
}  // namespace

template <int T>
void cell_boxes_avx(const std::array<std::span<const Vec<4>>, T>& x,
                    const std::vector<Cell<3>>& cells, std::vector<Box<4>>& boxes) {
  boxes.resize(cells.size());
  std::array<const Vec<4>*, T> at;
  for (int t = 0; t < T; ++t) at[t] = x[t].data();
  boxes_avx<T>(at, cells.data(), cells.size(), boxes.data());
}

template void cell_boxes_avx<1>(const std::array<std::span<const Vec<4>>, 1>&,
                                const std::vector<Cell<3>>&, std::vector<Box<4>>&);
template void cell_boxes_avx<2>(const std::array<std::span<const Vec<4>>, 2>&,
                                const std::vector<Cell<3>>&, std::vector<Box<4>>&);
#endif

}  // namespace s4d::prox_detail
