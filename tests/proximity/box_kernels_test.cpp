// Cell boxes and the BVH's outward float boxes: the AVX paths give the portable bits, and the
// boxes hold what they bound.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "core/cpu.hpp"
#include "proximity/cell_boxes.hpp"

namespace s4d {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Random points in R^4, with a NaN, an infinity and a huge finite coordinate here and there.
std::vector<Vec4> points(std::mt19937& rng, int n, int round) {
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<Vec4> x(n);
  for (Vec4& p : x)
    for (int k = 0; k < 4; ++k) p[k] = std::ldexp(u(rng), round % 9 - 4);
  if (round % 5 == 1) x[round % n][round % 4] = std::numeric_limits<double>::quiet_NaN();
  if (round % 7 == 2) x[(round + 3) % n][(round + 1) % 4] = -kInf;
  if (round % 11 == 3) x[(round + 5) % n][(round + 2) % 4] = 1e308;  // finite: an exact box
  return x;
}

std::vector<Cell<3>> triangles(std::mt19937& rng, int n, int count) {
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::vector<Cell<3>> cells(count);
  for (Cell<3>& c : cells) c = {pick(rng), pick(rng), pick(rng)};
  return cells;
}

template <int T>
void expect_boxes_hold_their_points(const std::array<std::span<const Vec4>, T>& x,
                                    const std::vector<Cell<3>>& cells,
                                    const std::vector<Box<4>>& boxes) {
  for (std::size_t c = 0; c < cells.size(); ++c) {
    bool finite = true;
    for (int t = 0; t < T; ++t)
      for (int v : cells[c]) finite = finite && x[t][v].allFinite();
    if (!finite) {  // the whole space
      EXPECT_TRUE((boxes[c].lo.array() == -kInf).all() && (boxes[c].hi.array() == kInf).all());
      continue;
    }
    for (int k = 0; k < 4; ++k) {
      double lo = kInf, hi = -kInf;
      for (int t = 0; t < T; ++t)
        for (int v : cells[c]) lo = std::min(lo, x[t][v][k]), hi = std::max(hi, x[t][v][k]);
      EXPECT_EQ(boxes[c].lo[k], lo);
      EXPECT_EQ(boxes[c].hi[k], hi);
    }
  }
}

TEST(BoxKernels, CellBoxesAreTheTightBoxesOrAllSpace) {
  std::mt19937 rng(21);
  for (int round = 0; round < 60; ++round) {
    const auto x0 = points(rng, 40, round), x1 = points(rng, 40, round + 1);
    const auto cells = triangles(rng, 40, 50);
    std::vector<Box<4>> boxes;
    prox_detail::static_boxes<4, 3>(x0, cells, boxes);
    expect_boxes_hold_their_points<1>({x0}, cells, boxes);
    prox_detail::swept_boxes<4, 3>(x0, x1, cells, boxes);
    expect_boxes_hold_their_points<2>({x0, x1}, cells, boxes);
  }
}

TEST(BoxKernels, AvxCellBoxesEqualThePortableOnes) {
  if (!cpu::kHasAvx) GTEST_SKIP() << "this CPU has no AVX";
  std::mt19937 rng(22);
  for (int round = 0; round < 200; ++round) {
    const auto x0 = points(rng, 30, round), x1 = points(rng, 30, round + 2);
    const auto cells = triangles(rng, 30, 1 + round % 37);
    std::vector<Box<4>> fast, ref;
    prox_detail::cell_boxes_avx<1>({x0}, cells, fast);
    prox_detail::cell_boxes_portable<4, 3, 1>({x0}, cells, ref);
    ASSERT_EQ(fast.size(), ref.size());
    EXPECT_EQ(std::memcmp(fast.data(), ref.data(), ref.size() * sizeof(Box<4>)), 0);
    prox_detail::cell_boxes_avx<2>({x0, x1}, cells, fast);
    prox_detail::cell_boxes_portable<4, 3, 2>({x0, x1}, cells, ref);
    EXPECT_EQ(std::memcmp(fast.data(), ref.data(), ref.size() * sizeof(Box<4>)), 0);
  }
}

// What a refit copies: the boxes in slot order and their outward float boxes, which must hold
// the double boxes (a float test never drops what the double one keeps).
TEST(BoxKernels, OutwardFloatBoxesHoldTheirBoxesAndAvxGivesThePortableBits) {
  std::mt19937 rng(23);
  for (int round = 0; round < 100; ++round) {
    const auto x = points(rng, 30, round);
    const auto cells = triangles(rng, 30, 64);
    std::vector<Box<4>> boxes;
    prox_detail::cell_boxes_portable<4, 3, 1>({x}, cells, boxes);
    boxes[round % boxes.size()].hi[round % 4] = std::numeric_limits<double>::quiet_NaN();
    std::vector<int> order(boxes.size());
    for (std::size_t k = 0; k < order.size(); ++k)
      order[k] = static_cast<int>((k * 37 + round) % order.size());
    std::vector<Box<4>> prim(order.size()), prim_fast(order.size());
    std::vector<FloatBox> pf(order.size()), pf_fast(order.size());
    gather_outward_portable<4>(boxes, order, prim.data(), pf.data());
    for (std::size_t k = 0; k < order.size(); ++k) {
      EXPECT_EQ(std::memcmp(&prim[k], &boxes[order[k]], sizeof(Box<4>)), 0);
      for (int a = 0; a < 4; ++a) {
        EXPECT_LE(static_cast<double>(pf[k].lo[a]), prim[k].lo[a]);
        if (std::isnan(prim[k].hi[a]))  // a NaN side stays open
          EXPECT_EQ(pf[k].hi[a], std::numeric_limits<float>::infinity());
        else
          EXPECT_GE(static_cast<double>(pf[k].hi[a]), prim[k].hi[a]);
      }
    }
#if S4D_X86
    if (!cpu::kHasAvx) continue;
    gather_outward_avx(boxes, order, prim_fast.data(), pf_fast.data());
    EXPECT_EQ(std::memcmp(prim_fast.data(), prim.data(), prim.size() * sizeof(Box<4>)), 0);
    EXPECT_EQ(std::memcmp(pf_fast.data(), pf.data(), pf.size() * sizeof(FloatBox)), 0);
#endif
  }
}

}  // namespace
}  // namespace s4d
