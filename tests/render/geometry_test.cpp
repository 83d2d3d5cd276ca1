// Pure-geometry tests of the renderer: projection, normals, tubes, beads, bounding spheres (no GL).
#include "core/camera.hpp"
#include "render/geometry.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "core/error.hpp"
#include "render/test_shapes.hpp"
#include "shape/topology.hpp"

namespace s4d {
namespace {

using test::kPi;

TEST(ProjectSurface, IdentityFrameKeepsXyzAndUsesWAsDepth) {
  const Surface<4> s = test::clifford_torus(12);
  const ProjectedSurface p = project_surface(s, Frame<4>());
  ASSERT_EQ(p.positions.size(), s.vertices.size());
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    EXPECT_NEAR((p.positions[i] - s.vertices[i].head<3>()).norm(), 0, 1e-15);
    EXPECT_DOUBLE_EQ(p.depth[i], s.vertices[i][3]);
  }
}

TEST(ProjectSurface, QuarterTurnInXwSwapsXAndW) {
  Surface<4> s;
  s.vertices = {Vec4(1, 0, 0, 0), Vec4(0, 0, 0, 1), Vec4(0.3, 0.2, 0.1, -0.4)};
  Frame<4> f;
  f.rotate(Plane{0, 3}, kPi / 2);
  const ProjectedSurface p = project_surface(s, f);
  // Whatever the sign convention, x and w trade places and y, z stay.
  EXPECT_NEAR(std::abs(p.depth[0]), 1, 1e-12);
  EXPECT_NEAR(p.positions[0].norm(), 0, 1e-12);
  EXPECT_NEAR(std::abs(p.positions[1].x()), 1, 1e-12);
  EXPECT_NEAR(p.depth[1], 0, 1e-12);
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    const Vec4 q = f.to_view(s.vertices[i]);
    EXPECT_NEAR((p.positions[i] - q.head<3>()).norm(), 0, 1e-15);
    EXPECT_DOUBLE_EQ(p.depth[i], q[3]);
  }
}

TEST(VertexNormals, SphereNormalsAreUnitAndOutward) {
  const Surface<3> s = test::uv_sphere();
  const auto n = vertex_normals(s.vertices, s.triangles);
  ASSERT_EQ(n.size(), s.vertices.size());
  for (std::size_t i = 0; i < n.size(); ++i) {
    EXPECT_NEAR(n[i].norm(), 1, 1e-12);
    // Poles are fans of slivers; elsewhere the area-weighted normal is the radius to ~1%.
    EXPECT_GT(n[i].dot(s.vertices[i]), 0.98) << "vertex " << i;
  }
}

TEST(VertexNormals, ReversedWindingFlipsNormals) {
  Surface<3> s = test::uv_sphere(10, 12);
  for (auto& t : s.triangles) std::swap(t[1], t[2]);
  const auto n = vertex_normals(s.vertices, s.triangles);
  for (std::size_t i = 0; i < n.size(); ++i) EXPECT_LT(n[i].dot(s.vertices[i]), -0.9);
}

TEST(VertexNormals, DegenerateVertexBorrowsANeighbourAndBadIndexThrows) {
  // Vertex 3 only belongs to a zero-area triangle; it borrows from vertex 0's normal.
  std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 0)};
  const auto n = vertex_normals(p, {{0, 1, 2}, {0, 3, 0}});
  EXPECT_NEAR((n[0] - Vec3::UnitZ()).norm(), 0, 1e-12);
  EXPECT_NEAR(n[3].norm(), 1, 1e-12);
  EXPECT_THROW(vertex_normals(p, {{0, 1, 7}}), Error);
  EXPECT_THROW(vertex_normals(p, {{-1, 1, 2}}), Error);
}

TEST(Tube, ClosedTubeCountsAndIsAWatertightTorus) {
  const Curve<3> c = test::trefoil(60);
  TubeOptions o;
  o.radius = 0.05;
  o.sides = 8;
  const RenderMesh m = tube_mesh(c.components[0].points, true, o);
  EXPECT_EQ(m.vertex_count(), 60u * 8u);
  EXPECT_EQ(m.triangle_count(), 2u * 60u * 8u);
  std::vector<Triangle> tris;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    tris.push_back({int(m.indices[3 * t]), int(m.indices[3 * t + 1]), int(m.indices[3 * t + 2])});
  const TopologySummary top = summarize_topology(int(m.vertex_count()), tris);
  EXPECT_TRUE(top.closed);
  EXPECT_TRUE(top.manifold);
  EXPECT_EQ(top.euler_characteristic, 0);
}

TEST(Tube, OpenTubeHasCapsAndIsAWatertightSphere) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 10; ++i) pts.emplace_back(std::cos(0.2 * i), std::sin(0.2 * i), 0.1 * i);
  TubeOptions o;
  o.radius = 0.1;
  o.sides = 6;
  const RenderMesh m = tube_mesh(pts, false, o, 100);
  EXPECT_EQ(m.vertex_count(), 10u * 6u + 2u * 7u);
  EXPECT_EQ(m.triangle_count(), 2u * 9u * 6u + 2u * 6u);
  for (int s : m.source) {
    EXPECT_GE(s, 100);
    EXPECT_LT(s, 110);
  }
  // Caps carry their own vertices, so the mesh is watertight only up to welding by position.
  std::vector<int> weld(m.vertex_count());
  for (std::size_t i = 0; i < m.vertex_count(); ++i) {
    weld[i] = int(i);
    for (std::size_t j = 0; j < i; ++j)
      if ((m.positions[i] - m.positions[j]).norm() < 1e-12) {
        weld[i] = weld[j];
        break;
      }
  }
  std::vector<Triangle> tris;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    tris.push_back({weld[m.indices[3 * t]], weld[m.indices[3 * t + 1]], weld[m.indices[3 * t + 2]]});
  const TopologySummary top = summarize_topology(int(m.vertex_count()), tris);
  EXPECT_TRUE(top.closed);
  EXPECT_EQ(top.euler_characteristic, 2);
}

// Every normal is unit length and points away from the curve; the triangles' own winding agrees.
TEST(Tube, NormalsAreUnitOutwardAndMatchTheWinding) {
  const Curve<3> c = test::trefoil(120);
  const auto& pts = c.components[0].points;
  for (bool closed : {true, false}) {
    TubeOptions o;
    o.radius = 0.04;
    const RenderMesh m = tube_mesh(pts, closed, o);
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      EXPECT_NEAR(m.normals[v].norm(), 1, 1e-12);
      const Vec3 radial = m.positions[v] - pts[m.source[v]];
      if (radial.norm() > 1e-9) {  // side vertices sit on the tube at exactly the radius
        if (std::abs(m.normals[v].dot(radial) / radial.norm()) > 0.5) {
          EXPECT_NEAR(radial.norm(), o.radius, 1e-12);
          EXPECT_NEAR((radial / o.radius - m.normals[v]).norm(), 0, 1e-12);
        }
      }
    }
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
      const Vec3& a = m.positions[m.indices[3 * t]];
      const Vec3& b = m.positions[m.indices[3 * t + 1]];
      const Vec3& cc = m.positions[m.indices[3 * t + 2]];
      const Vec3 face = (b - a).cross(cc - a);
      const Vec3 mean = m.normals[m.indices[3 * t]] + m.normals[m.indices[3 * t + 1]] +
                        m.normals[m.indices[3 * t + 2]];
      EXPECT_GT(face.dot(mean), 0) << "triangle " << t << (closed ? " closed" : " open");
    }
  }
}

// Rotation-minimising frames: the side-0 direction turns around the tangent only by the evenly
// spread holonomy correction, including across the seam where the loop closes.
TEST(Tube, FramesDoNotTwistAcrossTheSeam) {
  const int n = 400;
  const Curve<3> c = test::trefoil(n);
  TubeOptions o;
  o.sides = 8;
  const RenderMesh m = tube_mesh(c.components[0].points, true, o);
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const Vec3 t = (c.components[0].points[j] - c.components[0].points[i]).normalized();
    const Vec3 ri = m.normals[i * 8], rj = m.normals[j * 8];
    // Twist = rotation of the frame about the tangent between consecutive rings.
    const double twist = std::abs(std::asin(std::clamp(t.dot(ri.cross(rj)), -1.0, 1.0)));
    worst = std::max(worst, twist);
  }
  // The whole holonomy is below pi, so spread over 400 rings it is below 0.008 rad per ring.
  EXPECT_LT(worst, 0.01);
}

TEST(Tube, StraightLineKeepsOneFrame) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 5; ++i) pts.emplace_back(0.3 * i, 0.1 * i, -0.2 * i);
  TubeOptions o;
  o.sides = 5;
  const RenderMesh m = tube_mesh(pts, false, o);
  for (int i = 1; i < 5; ++i)
    for (int k = 0; k < 5; ++k) EXPECT_NEAR((m.normals[i * 5 + k] - m.normals[k]).norm(), 0, 1e-12);
}

TEST(Tube, DegenerateInput) {
  TubeOptions o;
  EXPECT_EQ(tube_mesh({}, true, o).vertex_count(), 0u);
  EXPECT_EQ(tube_mesh({Vec3(1, 2, 3), Vec3(1, 2, 3)}, true, o).vertex_count(), 0u);
  // Repeated points are skipped; a closed two-point "loop" is a capped segment.
  const RenderMesh seg = tube_mesh({Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)}, true, o);
  EXPECT_EQ(seg.vertex_count(), 2u * o.sides + 2u * (o.sides + 1));
  // A curve that doubles back still gets finite unit normals.
  const RenderMesh back = tube_mesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0)}, false, o);
  for (const Vec3& nrm : back.normals) EXPECT_NEAR(nrm.norm(), 1, 1e-12);
  o.sides = 2;
  EXPECT_THROW(tube_mesh({Vec3(0, 0, 0), Vec3(1, 0, 0)}, false, o), Error);
  o.sides = 8;
  o.radius = -1;
  EXPECT_THROW(tube_mesh({Vec3(0, 0, 0), Vec3(1, 0, 0)}, false, o), Error);
  o.radius = 0.1;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(tube_mesh({Vec3(0, 0, 0), Vec3(nan, 0, 0)}, false, o), Error);
}

// The beads: every vertex on the sphere with its outward unit normal, every triangle with area
// wound counter-clockwise seen from outside, and the whole closed (each edge in two triangles).
TEST(Sphere, VerticesOnItNormalsOutwardWindingOutward) {
  const Vec3 c(1, -2, 0.5);
  const RenderMesh m = sphere_mesh(c, 0.3, 6, 10);
  EXPECT_EQ(m.vertex_count(), 7u * 10u);
  ASSERT_EQ(m.normals.size(), m.vertex_count());
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    EXPECT_NEAR((m.positions[v] - c).norm(), 0.3, 1e-12);
    EXPECT_NEAR(m.normals[v].norm(), 1, 1e-12);
    EXPECT_LT((m.normals[v] - (m.positions[v] - c) / 0.3).norm(), 1e-12);
  }
  int with_area = 0;
  std::map<std::pair<Vec3, Vec3>, int, bool (*)(const std::pair<Vec3, Vec3>&, const std::pair<Vec3, Vec3>&)> edges(
      [](const std::pair<Vec3, Vec3>& x, const std::pair<Vec3, Vec3>& y) {
        auto key = [](const std::pair<Vec3, Vec3>& e) {
          return std::array{e.first.x(), e.first.y(), e.first.z(), e.second.x(), e.second.y(), e.second.z()};
        };
        return key(x) < key(y);
      });
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const Vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
               d = m.positions[m.indices[3 * t + 2]];
    const Vec3 n = (b - a).cross(d - a);
    if (n.norm() < 1e-12) continue;  // at a pole
    ++with_area;
    EXPECT_GT(n.dot((a + b + d) / 3 - c), 0);
    // Each directed edge once, and its reverse once, where the triangles have area.
    for (const auto& [p, q] : {std::pair{a, b}, {b, d}, {d, a}}) ++edges[{p, q}];
  }
  EXPECT_EQ(with_area, 2 * 10 * (6 - 1)) << "the pole rows' triangles have no area";
  for (const auto& [e, n] : edges) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(edges.count({e.second, e.first}), 1u) << "closed: every edge has a neighbour";
  }
  EXPECT_THROW(sphere_mesh(c, 0, 6, 10), Error);
  EXPECT_THROW(sphere_mesh(c, 0.3, 2, 10), Error);
  EXPECT_THROW(sphere_mesh(Vec3(std::nan(""), 0, 0), 0.3), Error);
}

TEST(BoundingSphere, ContainsEveryPointAndIgnoresNonFinite) {
  const Surface<3> s = test::uv_sphere(9, 8);  // even longitudes: a symmetric box
  std::vector<Vec3> pts;
  for (const Vec3& p : s.vertices) pts.push_back(2 * p + Vec3(5, -1, 0.5));
  pts.push_back(Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0));
  const BoundingSphere b = bounding_sphere(pts);
  EXPECT_NEAR((b.centre - Vec3(5, -1, 0.5)).norm(), 0, 1e-9);
  EXPECT_NEAR(b.radius, 2, 1e-9);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) EXPECT_LE((pts[i] - b.centre).norm(), b.radius + 1e-12);
  EXPECT_EQ(bounding_sphere({}).radius, 0);
}

}  // namespace
}  // namespace s4d
