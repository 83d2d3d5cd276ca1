// The ring pairs' motion bound against brute force: for random displacement fields on grids and
// on a closed mesh, every ring pair's largest relative motion is within both of its cells' bounds.
#include "proximity/motion_kernels.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "proximity/reference.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

using test::grid_cells;

// Returns the largest ratio M_ab / bound seen (at most 1 when the bound holds).
double worst_ratio(const std::vector<Cell<3>>& cells, int nv, unsigned seed) {
  const CellTopology<3> topo(cells, nv);
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0, 1);
  std::vector<double> own, around, ring;
  double worst = 0;
  for (int trial = 0; trial < 60; ++trial) {
    // Uniform noise, or a few fast vertices in a slow field: the uneven motion where 2 B + C
    // is well below 3 C, and where a bound too tight would show.
    std::vector<Vec4> u(nv);
    for (int v = 0; v < nv; ++v) {
      const double scale = trial % 2 == 0 ? 1.0 : (rng() % 17 == 0 ? 5.0 : 0.05);
      u[v] = scale * Vec4(normal(rng), normal(rng), normal(rng), normal(rng));
    }
    prox_detail::ring_motion_bounds<4, 3>(u.data(), topo, cells, own, around, ring);
    for (int a = 0; a < static_cast<int>(cells.size()); ++a)
      for (int k = topo.ring_offset[a]; k < topo.ring_offset[a + 1]; ++k) {
        const int b = topo.ring[k];
        double m = 0;
        for (int i : cells[a])
          for (int j : cells[b]) m = std::max(m, (u[i] - u[j]).norm());
        worst = std::max(worst, m / std::min(ring[a], ring[b]));
      }
  }
  return worst;
}

TEST(MotionKernels, RingBoundHoldsForEveryRingPair) {
  for (int n : {5, 9, 16}) {
    const double r = worst_ratio(grid_cells(n), n * n, static_cast<unsigned>(n));
    EXPECT_LE(r, 1.0) << "grid " << n;
    EXPECT_GT(r, 0.5) << "grid " << n << ": the bound should be near tight somewhere";
  }
  const Surface<4> torus = std::get<Surface<4>>(generate("clifford-torus", {{"n", 12}, {"m", 9}}));
  std::vector<Cell<3>> cells(torus.triangles.begin(), torus.triangles.end());
  EXPECT_LE(worst_ratio(cells, static_cast<int>(torus.vertices.size()), 7), 1.0);
}

// Every cell's bound is its definition, 2 B + C, to the bit: B the largest |u_p - u_q| over the
// edges at its vertices, C the same at their neighbours too. On grids most groups of four edges
// and of eight triangles are runs read four vertices at once; a NaN displacement must not hide
// the others' maxima.
TEST(MotionKernels, RingBoundIsItsDefinitionBitForBit) {
  for (int n : {7, 16}) {
    const auto cells = grid_cells(n);
    const CellTopology<3> topo(cells, n * n);
    int strided = 0;
    for (std::uint8_t g : topo.strided_edge_groups) strided += g;
    EXPECT_GT(strided, static_cast<int>(topo.edges.size() / 8)) << "a grid's edges come in runs";
    int strided_cells = 0;
    for (std::uint8_t g : topo.strided_cell_groups) strided_cells += g;
    EXPECT_GT(strided_cells, static_cast<int>(cells.size() / 16)) << "and so do its triangles";
    std::mt19937 rng(static_cast<unsigned>(n));
    std::normal_distribution<double> normal(0, 1);
    for (int trial = 0; trial < 10; ++trial) {
      std::vector<Vec4> u(n * n);
      for (Vec4& p : u) p = Vec4(normal(rng), normal(rng), normal(rng), normal(rng));
      if (trial % 3 == 2) u[static_cast<std::size_t>(rng() % u.size())][1] = std::nan("");
      std::vector<double> own, around, ring;
      prox_detail::ring_motion_bounds<4, 3>(u.data(), topo, cells, own, around, ring);
      // The definition, edge by edge (std::max drops a NaN change, as the kernels do).
      std::vector<double> e(n * n, 0.0);
      for (const auto& [p, q] : topo.edges) {
        const double d = (u[p] - u[q]).squaredNorm();
        e[p] = std::max(e[p], d);
        e[q] = std::max(e[q], d);
      }
      std::vector<double> c = e;
      for (const auto& [p, q] : topo.edges) {
        c[p] = std::max(c[p], e[q]);
        c[q] = std::max(c[q], e[p]);
      }
      for (std::size_t k = 0; k < cells.size(); ++k) {
        double b2 = 0, c2 = 0;
        for (int v : cells[k]) {
          b2 = std::max(b2, e[v]);
          c2 = std::max(c2, c[v]);
        }
        EXPECT_EQ(ring[k], 2 * std::sqrt(b2) + std::sqrt(c2)) << "grid " << n << " cell " << k;
      }
    }
  }
}

// A field that only translates leaves every bound zero; one edge stretched raises its cells'.
TEST(MotionKernels, RingBoundIsZeroForATranslationAndSeesOneEdge) {
  const int n = 6;
  const auto cells = grid_cells(n);
  const CellTopology<3> topo(cells, n * n);
  std::vector<Vec4> u(n * n, Vec4(0.3, -1, 2, 0.5));
  std::vector<double> own, around, ring;
  prox_detail::ring_motion_bounds<4, 3>(u.data(), topo, cells, own, around, ring);
  for (double r : ring) EXPECT_EQ(r, 0.0);
  u[14] += Vec4(0, 0, 0, 1);  // every edge at vertex 14 changes by 1
  prox_detail::ring_motion_bounds<4, 3>(u.data(), topo, cells, own, around, ring);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const bool has = std::count(cells[c].begin(), cells[c].end(), 14) > 0;
    if (has) {
      EXPECT_DOUBLE_EQ(ring[c], 3.0) << c;  // B = C = 1
    }
    EXPECT_LE(ring[c], 3.0) << c;
  }
}

}  // namespace
}  // namespace s4d
