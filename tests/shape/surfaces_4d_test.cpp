// Cloth, Clifford torus and spheres: counts, topology, points on the expected sets.
#include "shape/surfaces_4d.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "shape/mesh_checks.hpp"
#include "shape/topology.hpp"

namespace s4d {
namespace {

TEST(Cloth, FlatSquareDisk) {
  const Surface<4> s = cloth(9, 2.0);
  EXPECT_EQ(s.vertex_count(), 81u);
  EXPECT_EQ(s.triangle_count(), 2u * 8 * 8);
  ASSERT_TRUE(s.grid.has_value());
  EXPECT_EQ(*s.grid, (Grid{9, 9, false, false}));
  for (const Vec4& v : s.vertices) {
    EXPECT_EQ(v.z(), 0.0);
    EXPECT_EQ(v.w(), 0.0);
    EXPECT_LE(std::abs(v.x()), 1.0);
    EXPECT_LE(std::abs(v.y()), 1.0);
  }
  EXPECT_TRUE(s.vertices[s.grid->index(8, 8)].isApprox(Vec4(1, 1, 0, 0)));
  const auto t = summarize_topology(s);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_edges, 4 * 8);
  EXPECT_TRUE(t.manifold && t.oriented);
  EXPECT_THROW(cloth(1, 1.0), Error);
  EXPECT_THROW(cloth(4, 0.0), Error);
}

TEST(CliffordTorus, OnTheSphereOfRadiusSqrt2AndATorus) {
  const Surface<4> s = clifford_torus(24, 16);
  EXPECT_EQ(s.vertex_count(), 24u * 16);
  ASSERT_TRUE(s.grid.has_value());
  EXPECT_TRUE(s.grid->wrap_i && s.grid->wrap_j);
  for (const Vec4& v : s.vertices) {
    EXPECT_NEAR(v.norm(), std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(v.head<2>().norm(), 1.0, 1e-12);  // and on the product of two unit circles
  }
  const auto t = summarize_topology(s);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(test::self_intersections(s).intersecting_pairs, 0);
}

TEST(Sphere, ClosedSphereOnTheRightRadiusAtD3AndD4) {
  const Surface<4> s4 = uv_sphere<4>(20, 1.5, Vec4(0, 1, 0, 0.25));
  const Surface<3> s3 = uv_sphere<3>(7, 2.0, Vec3::Zero());
  for (const Vec4& v : s4.vertices) {
    EXPECT_NEAR((v - Vec4(0, 1, 0, 0.25)).norm(), 1.5, 1e-12);
    EXPECT_EQ(v.w(), 0.25);
  }
  for (const Vec3& v : s3.vertices) EXPECT_NEAR(v.norm(), 2.0, 1e-12);
  for (const auto& t : {summarize_topology(s4), summarize_topology(s3)}) {
    EXPECT_EQ(t.euler_characteristic, 2);
    EXPECT_TRUE(t.closed && t.manifold && t.oriented);
  }
  EXPECT_EQ(s4.vertex_count(), 2u + 20 * 9);
  EXPECT_FALSE(s4.grid.has_value());
  EXPECT_EQ(test::self_intersections(s4).intersecting_pairs, 0);
}

TEST(Sphere, TrianglesFaceOutwards) {
  const Surface<3> s = uv_sphere<3>(16, 1.0, Vec3::Zero());
  for (const Triangle& t : s.triangles) {
    const Vec3 a = s.vertices[t[0]], b = s.vertices[t[1]], c = s.vertices[t[2]];
    EXPECT_GT((b - a).cross(c - a).dot(a + b + c), 0.0);
  }
}

TEST(Sphere, RejectsBadArguments) {
  EXPECT_THROW(uv_sphere<4>(2, 1.0, Vec4::Zero()), Error);
  EXPECT_THROW(uv_sphere<4>(8, -1.0, Vec4::Zero()), Error);
}

}  // namespace
}  // namespace s4d
