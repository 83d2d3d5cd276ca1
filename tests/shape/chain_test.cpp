// The 4D chain: components, topology of each element, no contact between elements, linking.
#include "shape/chain.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "shape/mesh_checks.hpp"
#include "shape/topology.hpp"

namespace s4d {
namespace {

TEST(Chain, ComponentsAndEulerCharacteristic) {
  for (int links : {1, 2, 3, 5}) {
    const Surface<4> s = chain(links, 16);
    const auto t = summarize_topology(s);
    const int spheres = (links + 1) / 2, loops = links / 2;
    EXPECT_EQ(t.components, links);
    EXPECT_EQ(t.euler_characteristic, 2 * spheres + 0 * loops);
    EXPECT_EQ(t.boundary_edges, loops * 2 * (2 * 16));  // each loop: two circles of 2n edges
    EXPECT_TRUE(t.manifold && t.oriented);
  }
}

TEST(Chain, TopElementAtTheOriginHangingDown) {
  const Surface<4> s = chain(3, 16);
  double top = -1e9, bottom = 1e9;
  for (const Vec4& v : s.vertices) {
    top = std::max(top, v.y());
    bottom = std::min(bottom, v.y());
  }
  EXPECT_NEAR(top, kChainSphereRadius, 1e-12);  // the first sphere, centred at the origin
  EXPECT_NEAR(bottom, -2 * kChainSpacing - kChainSphereRadius, 1e-12);
}

TEST(Chain, NoIntersectionsAnywhere) {
  for (int links : {3, 4}) {
    const auto rep = test::self_intersections(chain(links, 24));
    EXPECT_EQ(rep.intersecting_pairs, 0) << links << " links";
  }
}

TEST(Chain, EachLoopPiercesTheBallsOfBothNeighbours) {
  // A loop links a sphere in w = 0 when it crosses w = 0 once inside the ball and once outside.
  // Count, for loop 1 of a 3-chain, where its core circle crosses w = 0.
  const Surface<4> s = chain(3, 32);
  // Loop vertices follow the first sphere's; its grid is 2n × 2 (core = mean of the 2 columns).
  const int sphere_vertices = 2 + 32 * 15;
  const int rows = 64;
  std::vector<Vec4> core;
  for (int i = 0; i < rows; ++i)
    core.push_back(0.5 * (s.vertices[sphere_vertices + 2 * i] + s.vertices[sphere_vertices + 2 * i + 1]));
  int inside_top = 0, inside_bottom = 0, outside = 0;
  for (int i = 0; i < rows; ++i) {
    const Vec4 a = core[i], b = core[(i + 1) % rows];
    // Half-open test, so a vertex exactly on w = 0 counts for one segment only.
    if (!((a.w() <= 0 && b.w() > 0) || (b.w() <= 0 && a.w() > 0))) continue;
    const double t = a.w() / (a.w() - b.w());
    const Vec4 x = a + t * (b - a);
    const double d_top = (x - Vec4(0, 0, 0, 0)).norm();
    const double d_bottom = (x - Vec4(0, -2 * kChainSpacing, 0, 0)).norm();
    if (d_top < kChainSphereRadius) ++inside_top;
    else if (d_bottom < kChainSphereRadius) ++inside_bottom;
    else ++outside;
  }
  EXPECT_EQ(inside_top, 1);
  EXPECT_EQ(inside_bottom, 1);
  EXPECT_EQ(outside, 0);
}

TEST(Chain, RejectsBadArguments) {
  EXPECT_THROW(chain(0, 16), Error);
  EXPECT_THROW(chain(3, 4), Error);
}

}  // namespace
}  // namespace s4d
