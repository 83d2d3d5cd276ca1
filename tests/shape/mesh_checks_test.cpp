// Tests of the test-only checkers themselves: they must find intersections where they exist.
#include "shape/mesh_checks.hpp"

#include <gtest/gtest.h>

#include <random>

namespace s4d::test {
namespace {

using V4 = Vec<4>;

TEST(TriangleDistance, PlanesMeetingAtOnePointInR4) {
  // The xy- and zw-planes meet only at the origin; both triangles contain it inside.
  const std::array<V4, 3> p{V4(-1, -1, 0, 0), V4(2, -1, 0, 0), V4(-1, 2, 0, 0)};
  const std::array<V4, 3> q{V4(0, 0, -1, -1), V4(0, 0, 2, -1), V4(0, 0, -1, 2)};
  EXPECT_NEAR(triangle_distance<4>(p, q), 0.0, 1e-12);
  // Shifting q along x (a direction of p's plane) keeps them meeting.
  std::array<V4, 3> qx = q, far = q;
  for (auto& v : qx) v.x() += 0.3;
  EXPECT_NEAR(triangle_distance<4>(p, qx), 0.0, 1e-12);
  const std::array<V4, 3> far_p{V4(5, 5, 0, 0), V4(6, 5, 0, 0), V4(5, 6, 0, 0)};
  // Nearest points: (5,5,0,0) on far_p and the origin, which q contains.
  EXPECT_NEAR(triangle_distance<4>(far_p, far), std::sqrt(50.0), 1e-12);
}

TEST(TriangleDistance, ParallelOffsetPlanes) {
  const std::array<V4, 3> p{V4(0, 0, 0, 0), V4(1, 0, 0, 0), V4(0, 1, 0, 0)};
  std::array<V4, 3> q = p;
  for (auto& v : q) v.w() += 0.25;  // same triangle, shifted along w
  EXPECT_NEAR(triangle_distance<4>(p, q), 0.25, 1e-12);
  for (auto& v : q) v.x() += 0.5;  // still overlapping in xy: distance stays 0.25
  EXPECT_NEAR(triangle_distance<4>(p, q), 0.25, 1e-12);
}

TEST(TriangleDistance, NeverAboveSampledDistanceAndCloseToIt) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 40; ++trial) {
    std::array<V4, 3> p, q;
    for (auto& v : p) v = V4(u(rng), u(rng), u(rng), u(rng));
    for (auto& v : q) v = V4(u(rng), u(rng), u(rng), u(rng)) + V4(0.5, 0, 0, 0);
    const double d = triangle_distance<4>(p, q);
    double sampled = 1e9;
    const int k = 24;
    for (int a = 0; a <= k; ++a)
      for (int b = 0; a + b <= k; ++b)
        for (int c = 0; c <= k; ++c)
          for (int e = 0; c + e <= k; ++e) {
            const V4 x = (a * p[0] + b * p[1] + (k - a - b) * p[2]) / k;
            const V4 y = (c * q[0] + e * q[1] + (k - c - e) * q[2]) / k;
            sampled = std::min(sampled, (x - y).norm());
          }
    EXPECT_LE(d, sampled + 1e-12);
    EXPECT_GE(d, sampled - 0.15);  // the sampling grid's spacing bounds the gap
  }
}

TEST(SelfIntersections, FindsAFoldedStrip) {
  // Two unit squares (4 triangles) crossing each other in R^3 at right angles.
  Surface<3> s;
  s.vertices = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0),
                Vec3(0, -0.5, -1), Vec3(0, 0.5, -1), Vec3(0, 0.5, 1), Vec3(0, -0.5, 1)};
  s.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  const auto rep = self_intersections(s);
  EXPECT_GT(rep.intersecting_pairs, 0);
  // Lift the second square clear of the first: no intersection, distance 0.2.
  for (int v = 4; v < 8; ++v) s.vertices[v].z() += 1.2;
  const auto rep2 = self_intersections(s, 1e-9, 1.0);
  EXPECT_EQ(rep2.intersecting_pairs, 0);
  EXPECT_NEAR(rep2.min_distance, 0.2, 1e-12);
}

TEST(DiagramCrossings, CountsAFigureEightDrawnByHand) {
  // A planar "∞" with one crossing, the over-strand lifted.
  Curve<3> c;
  Polyline<3> pl;
  for (int i = 0; i < 200; ++i) {
    const double t = 2 * M_PI * (i + 0.5) / 200;  // no sample on the crossing itself
    pl.points.emplace_back(std::sin(t), std::sin(t) * std::cos(t), 0.1 * std::cos(t));
  }
  c.components.push_back(pl);
  const auto x = diagram_crossings(c);
  ASSERT_EQ(x.size(), 1u);
}

}  // namespace
}  // namespace s4d::test
