// Boxes of cells, static (at x) and swept (over x0 → x1): the input of every broad phase. For
// triangles in R^4 an AVX path (one register a point) is picked at run time and gives the
// portable path's boxes exactly; the *_portable forms are there for the tests to compare.
#pragma once
#include <array>
#include <limits>
#include <span>
#include <vector>

#include "core/cpu.hpp"
#include "proximity/bvh.hpp"
#include "proximity/cells.hpp"

namespace s4d::prox_detail {

// A cell with a non-finite vertex gets the whole space as its box: it stays a candidate with
// every other cell, and the exact kernels (NaN distance, contact at once) decide what it means.
// One finiteness test a box: the sum of 0·p over its points is NaN exactly when some coordinate
// is not finite (a sum of the coordinates themselves would also trip on huge finite ones).
template <int D, int K, int T>
Box<D> cell_box(const std::array<std::span<const Vec<D>>, T>& x, const Cell<K>& c) {
  Box<D> b;
  b.lo = b.hi = x[0][c[0]];
  Vec<D> zero = Vec<D>::Zero();
  for (int t = 0; t < T; ++t)
    for (int i = 0; i < K; ++i) {
      const Vec<D>& p = x[t][c[i]];
      b.lo = b.lo.cwiseMin(p);
      b.hi = b.hi.cwiseMax(p);
      zero += 0.0 * p;
    }
  if (!(zero.array() == 0.0).all()) {
    b.lo.setConstant(-std::numeric_limits<double>::infinity());
    b.hi.setConstant(std::numeric_limits<double>::infinity());
  }
  return b;
}

// boxes[i] = the box of cells[i] at x (T = 1) or over x0 and x1 (T = 2).
template <int D, int K, int T>
void cell_boxes_portable(const std::array<std::span<const Vec<D>>, T>& x,
                         const std::vector<Cell<K>>& cells, std::vector<Box<D>>& boxes) {
  boxes.resize(cells.size());
  for (std::size_t i = 0, n = cells.size(); i < n; ++i) boxes[i] = cell_box<D, K, T>(x, cells[i]);
}

#if S4D_X86
template <int T>
void cell_boxes_avx(const std::array<std::span<const Vec<4>>, T>& x,
                    const std::vector<Cell<3>>& cells, std::vector<Box<4>>& boxes);
#endif

template <int D, int K, int T>
void cell_boxes(const std::array<std::span<const Vec<D>>, T>& x, const std::vector<Cell<K>>& cells,
                std::vector<Box<D>>& boxes) {
#if S4D_X86
  if constexpr (D == 4 && K == 3)
    if (cpu::kHasAvx) return cell_boxes_avx<T>(x, cells, boxes);
#endif
  cell_boxes_portable<D, K, T>(x, cells, boxes);
}

template <int D, int K>
void static_boxes(std::span<const Vec<D>> x, const std::vector<Cell<K>>& cells,
                  std::vector<Box<D>>& boxes) {
  cell_boxes<D, K, 1>({x}, cells, boxes);
}

template <int D, int K>
void swept_boxes(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1,
                 const std::vector<Cell<K>>& cells, std::vector<Box<D>>& boxes) {
  cell_boxes<D, K, 2>({x0, x1}, cells, boxes);
}

}  // namespace s4d::prox_detail
