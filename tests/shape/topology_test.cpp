// Topology of triangle meshes: counts, Euler characteristic, boundary, manifold checks.
#include "shape/topology.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "shape/grid_mesh.hpp"

namespace s4d {
namespace {

template <int D>
Surface<D> grid_surface(int rows, int cols, bool wi, bool wj) {
  Surface<D> s;
  s.grid = Grid{rows, cols, wi, wj};
  s.vertices.assign(static_cast<std::size_t>(rows) * cols, Vec<D>::Zero());
  s.triangles = grid_triangles(*s.grid);
  return s;
}

TEST(MeshEdges, SortedUniqueWithCounts) {
  const std::vector<Triangle> tris{{0, 1, 2}, {2, 1, 3}};
  const auto e = mesh_edges(tris);
  ASSERT_EQ(e.size(), 5u);
  EXPECT_EQ(e[0].a, 0); EXPECT_EQ(e[0].b, 1); EXPECT_EQ(e[0].triangles, 1);
  EXPECT_EQ(e[2].a, 1); EXPECT_EQ(e[2].b, 2); EXPECT_EQ(e[2].triangles, 2);
  for (std::size_t i = 0; i + 1 < e.size(); ++i)
    EXPECT_TRUE(e[i].a < e[i + 1].a || (e[i].a == e[i + 1].a && e[i].b < e[i + 1].b));
}

TEST(Topology, SingleTriangleIsADisk) {
  const auto t = summarize_topology(3, {{0, 1, 2}});
  EXPECT_EQ(t.vertices, 3); EXPECT_EQ(t.edges, 3); EXPECT_EQ(t.faces, 1);
  EXPECT_EQ(t.boundary_edges, 3);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_FALSE(t.closed);
  EXPECT_TRUE(t.manifold);
  EXPECT_TRUE(t.oriented);
  EXPECT_EQ(t.components, 1);
}

TEST(Topology, TetrahedronIsASphere) {
  const std::vector<Triangle> tris{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const auto t = summarize_topology(4, tris);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.manifold);
  EXPECT_TRUE(t.oriented);
  // Flip one face: still a manifold sphere, no longer consistently oriented.
  auto flipped = tris;
  std::swap(flipped[0][1], flipped[0][2]);
  const auto f = summarize_topology(4, flipped);
  EXPECT_TRUE(f.manifold);
  EXPECT_FALSE(f.oriented);
}

TEST(Topology, GridsAtEveryDimension) {
  // Same combinatorics whatever the ambient dimension (the template only forwards).
  const auto disk2 = summarize_topology(grid_surface<2>(5, 7, false, false));
  const auto annulus3 = summarize_topology(grid_surface<3>(6, 4, true, false));
  const auto torus4 = summarize_topology(grid_surface<4>(6, 5, true, true));
  EXPECT_EQ(disk2.euler_characteristic, 1);
  EXPECT_EQ(disk2.faces, 2 * 4 * 6);
  EXPECT_EQ(disk2.boundary_edges, 2 * (4 + 6));
  EXPECT_TRUE(disk2.manifold && disk2.oriented && !disk2.closed);
  EXPECT_EQ(annulus3.euler_characteristic, 0);
  EXPECT_EQ(annulus3.boundary_edges, 2 * 6);
  EXPECT_TRUE(annulus3.manifold && annulus3.oriented);
  EXPECT_EQ(torus4.euler_characteristic, 0);
  EXPECT_EQ(torus4.edges, 3 * 30);
  EXPECT_TRUE(torus4.closed && torus4.manifold && torus4.oriented);
  EXPECT_EQ(torus4.components, 1);
}

TEST(Topology, ThreeTrianglesOnOneEdgeAreSingular) {
  const auto t = summarize_topology(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  EXPECT_EQ(t.singular_edges, 1);
  EXPECT_FALSE(t.manifold);
}

TEST(Topology, BowtieVertexIsNotManifold) {
  // Two triangles touching at vertex 0 only: every edge is fine, the vertex link is two pieces.
  const auto t = summarize_topology(5, {{0, 1, 2}, {0, 3, 4}});
  EXPECT_EQ(t.singular_edges, 0);
  EXPECT_FALSE(t.manifold);
  EXPECT_EQ(t.components, 1);
}

TEST(Topology, TwoConesGluedAtTheirApexAreNotManifold) {
  // Two closed fans (octahedron halves closed off) sharing one apex: edges all manifold.
  std::vector<Triangle> tris;
  for (int j = 0; j < 4; ++j) tris.push_back({0, 1 + j, 1 + (j + 1) % 4});
  for (int j = 0; j < 4; ++j) tris.push_back({0, 5 + (j + 1) % 4, 5 + j});
  const auto t = summarize_topology(9, tris);
  EXPECT_EQ(t.singular_edges, 0);
  EXPECT_FALSE(t.manifold);
}

TEST(Topology, ComponentsAndUnusedVertices) {
  const auto t = summarize_topology(10, {{0, 1, 2}, {3, 4, 5}});
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.vertices, 6);  // 4 unused vertices do not count
  EXPECT_EQ(t.euler_characteristic, 2);
}

TEST(Topology, DegenerateTriangleIsReported) {
  const auto t = summarize_topology(3, {{0, 1, 1}});
  EXPECT_EQ(t.degenerate_triangles, 1);
  EXPECT_FALSE(t.manifold);
}

TEST(Topology, BadIndicesThrowInsteadOfCrashing) {
  EXPECT_THROW(summarize_topology(3, {{0, 1, 3}}), Error);
  EXPECT_THROW(summarize_topology(3, {{0, -1, 2}}), Error);
}

TEST(Topology, EmptyMesh) {
  const auto t = summarize_topology(0, {});
  EXPECT_EQ(t.faces, 0);
  EXPECT_FALSE(t.closed);
  EXPECT_FALSE(t.manifold);
}

TEST(GridTriangles, TooSmallGridsAreRejected) {
  EXPECT_THROW(grid_triangles(Grid{1, 5, false, false}), Error);
  EXPECT_THROW(grid_triangles(Grid{2, 5, true, false}), Error);
  EXPECT_NO_THROW(grid_triangles(Grid{3, 2, true, false}));
}

}  // namespace
}  // namespace s4d

#include "shape/describe.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

TEST(DescribeShape, SaysKindSizeAndTopology) {
  const std::string torus = describe_shape(generate("clifford-torus", {{"n", 8}, {"m", 8}}));
  EXPECT_EQ(torus, "surface in R^4, 64 vertices, 128 triangles, 1 component(s), Euler characteristic 0, "
                   "closed, manifold");
  const std::string knot = describe_shape(generate("torus-knot", {{"n", 60}}));
  EXPECT_EQ(knot.rfind("curve in R^3, 1 component(s), 60 points, length ", 0), 0u) << knot;
}

}  // namespace
}  // namespace s4d
