// Patches a hand carries: the geodesic ball along mesh edges, checked against a brute-force
// shortest-path reference, with the falloff's properties; other bodies are never taken along.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "physics/patch.hpp"
#include "physics/test_worlds.hpp"

namespace s4d {
namespace {

// Bellman–Ford over every mesh edge: the reference distances along the surface.
template <int D>
std::vector<double> reference_distances(const Model<D>& m, std::span<const Vec<D>> x, int from) {
  std::vector<double> d(static_cast<std::size_t>(m.nv), std::numeric_limits<double>::infinity());
  d[static_cast<std::size_t>(from)] = 0;
  for (int round = 0; round < m.nv; ++round)
    for (int v = 0; v < m.nv; ++v)
      for (int k = m.adjacency_offset[v]; k < m.adjacency_offset[v + 1]; ++k) {
        const int n = m.adjacency[k];
        d[n] = std::min(d[n], d[v] + (x[n] - x[v]).norm());
      }
  return d;
}

TEST(Patch, IsTheGeodesicBallWithAFalloffFromOneToZero) {
  ModelBuilder<4> b(test::quiet_params<4>());
  Surface<4> cloth = test::flat_cloth<4>(9, 1.0);
  for (auto& p : cloth.vertices) p.w() = 0.3 * p.x() * p.x();  // bent in w: lengths are not planar
  b.add_body(cloth);
  const Model<4> m = b.build();
  const std::span<const Vec4> x(cloth.vertices);
  Patch patch;
  PatchScratch scratch;
  scratch.reserve(m.nv, m.adjacency.size());
  for (int centre : {0, 40, 44, 80})
    for (double r : {0.0, 0.1, 0.3, 0.7, 5.0}) {
      SCOPED_TRACE("centre " + std::to_string(centre) + ", radius " + std::to_string(r));
      const int c[] = {centre};
      grow_patch<4>(m, x, c, r, patch, scratch);
      const std::vector<double> d = reference_distances<4>(m, x, centre);
      std::vector<int> expected;
      for (int v = 0; v < m.nv; ++v)
        if (v == centre || d[v] < r) expected.push_back(v);
      std::vector<int> got = patch.vertices;
      std::sort(got.begin(), got.end());
      EXPECT_EQ(got, expected);
      ASSERT_EQ(patch.weights.size(), patch.vertices.size());
      EXPECT_EQ(patch.vertices.front(), centre);
      EXPECT_DOUBLE_EQ(patch.weights.front(), 1.0);
      for (std::size_t i = 0; i < patch.vertices.size(); ++i) {
        const double u = r > 0 ? d[patch.vertices[i]] / r : 0;
        EXPECT_NEAR(patch.weights[i], (1 - u * u) * (1 - u * u), 1e-12);
        EXPECT_GE(patch.weights[i], 0);
        if (i > 0) {
          EXPECT_LE(patch.weights[i], patch.weights[i - 1] + 1e-12) << "nearest first";
        }
      }
    }
}

TEST(Patch, StaysOnItsBodyWhateverIsNearInSpace) {
  ModelBuilder<4> b(test::quiet_params<4>());
  const Surface<4> lower = test::flat_cloth<4>(6, 1.0), upper = test::flat_cloth<4>(6, 1.0, Vec4(0, 0, 0, 0.2));
  b.add_body(lower);
  b.add_body(upper);
  const Model<4> m = b.build();
  std::vector<Vec4> x = lower.vertices;
  x.insert(x.end(), upper.vertices.begin(), upper.vertices.end());
  Patch patch;
  PatchScratch scratch;
  const int c[] = {14};
  grow_patch<4>(m, std::span<const Vec4>(x), c, 10.0, patch, scratch);
  EXPECT_EQ(patch.vertices.size(), 36u) << "all of its own sheet, none of the other 0.2 away in w";
  for (int v : patch.vertices) EXPECT_LT(v, 36);
}

TEST(Patch, BadRadiiAndCentresAreHarmless) {
  ModelBuilder<3> b(test::quiet_params<3>());
  const Surface<3> cloth = test::flat_cloth<3>(4, 1.0);
  b.add_body(cloth);
  const Model<3> m = b.build();
  Patch patch;
  PatchScratch scratch;
  const int c[] = {-1, 99, 5, 5};
  for (double r : {std::numeric_limits<double>::quiet_NaN(), -1.0, std::numeric_limits<double>::infinity()}) {
    grow_patch<3>(m, std::span<const Vec3>(cloth.vertices), c, r, patch, scratch);
    EXPECT_EQ(patch.vertices, std::vector<int>{5}) << "a centre taken once, alone";
  }
}

}  // namespace
}  // namespace s4d
