// Artin spin and the spun trefoil: a closed, embedded 2-sphere in R^4.
#include "shape/spun_knot.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "shape/mesh_checks.hpp"
#include "shape/knotted_arc.hpp"
#include "shape/topology.hpp"

namespace s4d {
namespace {

TEST(SpinArc, SpinningASemicircleGivesARoundSphere) {
  std::vector<Vec3> arc;
  const int n = 30;
  for (int i = 0; i < n; ++i) {
    const double t = M_PI * i / (n - 1);
    arc.emplace_back(std::cos(t), 0.5, i == 0 || i == n - 1 ? 0.0 : std::sin(t));
  }
  const Surface<4> s = spin_arc(arc, 24);
  EXPECT_EQ(s.vertex_count(), 2u + (n - 2) * 24);
  for (const Vec4& v : s.vertices) {
    EXPECT_NEAR((v - Vec4(0, 0.5, 0, 0)).norm(), 1.0, 1e-12);
    EXPECT_NEAR(v.y(), 0.5, 1e-12);
  }
  const auto t = summarize_topology(s);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
}

TEST(SpinArc, RejectsArcsOffTheFloor) {
  EXPECT_THROW(spin_arc({Vec3(0, 0, 0.1), Vec3(0, 0, 1), Vec3(1, 0, 0)}, 8), Error);
  EXPECT_THROW(spin_arc({Vec3(0, 0, 0), Vec3(0, 0, -1), Vec3(1, 0, 0)}, 8), Error);
  EXPECT_THROW(spin_arc({Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0)}, 2), Error);
}

TEST(SpunTrefoil, ClosedManifoldSphere) {
  const Surface<4> s = spun_trefoil(160, 32);
  const auto t = summarize_topology(s);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.singular_edges, 0);
}

TEST(SpunTrefoil, SpinPreservesDistanceToTheAxisPlane) {
  // Each ring vertex sits at distance z(arc point) from the plane z = w = 0.
  const auto arc = trefoil_arc(100, false);
  const Surface<4> s = spun_trefoil(100, 12);
  for (int i = 1; i < 99; ++i)
    for (int j = 0; j < 12; ++j) {
      const Vec4& v = s.vertices[1 + (i - 1) * 12 + j];
      EXPECT_NEAR(v.tail<2>().norm(), arc[i].z(), 1e-12);
      EXPECT_EQ(v.x(), arc[i].x());
    }
}

class SpunTrefoilEmbedded : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(SpunTrefoilEmbedded, NoSelfIntersectionInR4) {
  const auto [n, m] = GetParam();
  const Surface<4> s = spun_trefoil(n, m);
  const auto rep = test::self_intersections(s);
  EXPECT_GT(rep.checked_pairs, 0);
  EXPECT_EQ(rep.intersecting_pairs, 0) << "n=" << n << " m=" << m;
}

INSTANTIATE_TEST_SUITE_P(Resolutions, SpunTrefoilEmbedded,
                         ::testing::Values(std::pair{160, 32}, std::pair{64, 8},
                                           std::pair{100, 17}, std::pair{300, 48}));

}  // namespace
}  // namespace s4d
