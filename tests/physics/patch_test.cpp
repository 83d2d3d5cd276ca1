// Patches a hand carries: the rings of the mesh graph around a vertex, checked against a
// brute-force breadth-first reference on several meshes, with the falloff's properties; other
// bodies (and other sheets near in space) are never taken along.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <set>
#include <utility>

#include "physics/patch.hpp"
#include "physics/test_worlds.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

// The mesh's edges from its triangles (and a curve's segments), as plain pairs: the reference
// does not read the Model's adjacency it checks.
std::set<std::pair<int, int>> edges_of(const std::vector<Triangle>& triangles, int first = 0) {
  std::set<std::pair<int, int>> e;
  for (const auto& t : triangles)
    for (int c = 0; c < 3; ++c) {
      const int a = first + t[c], b = first + t[(c + 1) % 3];
      e.insert({std::min(a, b), std::max(a, b)});
    }
  return e;
}

// Rounds of relaxation over every edge until nothing changes: each vertex's ring (-1 unreached).
std::vector<int> reference_rings(int nv, const std::set<std::pair<int, int>>& edges, int from) {
  constexpr int kFar = std::numeric_limits<int>::max() / 2;
  std::vector<int> d(static_cast<std::size_t>(nv), kFar);
  d[static_cast<std::size_t>(from)] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [a, b] : edges) {
      const int na = std::min(d[a], d[b] + 1), nb = std::min(d[b], d[a] + 1);
      changed = changed || na != d[a] || nb != d[b];
      d[a] = na;
      d[b] = nb;
    }
  }
  for (int& k : d)
    if (k == kFar) k = -1;
  return d;
}

template <int D>
void expect_patches_match_reference(const Model<D>& m, const std::set<std::pair<int, int>>& edges,
                                    std::initializer_list<int> centres) {
  Patch patch;
  PatchScratch scratch;
  scratch.reserve(m.nv);
  for (int centre : centres) {
    const std::vector<int> ref = reference_rings(m.nv, edges, centre);
    for (int rings : {0, 1, 2, 3, 5, 11, 1000}) {
      SCOPED_TRACE("centre " + std::to_string(centre) + ", rings " + std::to_string(rings));
      const int c[] = {centre};
      grow_patch<D>(m, c, rings, patch, scratch);
      std::vector<int> expected;
      for (int v = 0; v < m.nv; ++v)
        if (ref[v] >= 0 && ref[v] <= rings) expected.push_back(v);
      std::vector<int> got = patch.vertices;
      std::sort(got.begin(), got.end());
      EXPECT_EQ(got, expected);
      ASSERT_EQ(patch.weights.size(), patch.vertices.size());
      ASSERT_EQ(patch.rings.size(), patch.vertices.size());
      EXPECT_EQ(patch.vertices.front(), centre);
      EXPECT_DOUBLE_EQ(patch.weights.front(), 1.0);
      for (std::size_t i = 0; i < patch.vertices.size(); ++i) {
        EXPECT_EQ(patch.rings[i], ref[patch.vertices[i]]);
        EXPECT_DOUBLE_EQ(patch.weights[i], patch_weight(patch.rings[i], rings));
        EXPECT_GT(patch.weights[i], 0) << "the rim still moves";
        EXPECT_LE(patch.weights[i], 1);
        if (i > 0) {
          EXPECT_GE(patch.rings[i], patch.rings[i - 1]) << "ring by ring";
          EXPECT_LE(patch.weights[i], patch.weights[i - 1]) << "nearest first";
        }
      }
    }
  }
}

TEST(Patch, IsTheRingsOfTheMeshGraphOnACloth) {
  ModelBuilder<4> b(test::quiet_params<4>());
  Surface<4> cloth = test::flat_cloth<4>(9, 1.0);
  for (auto& p : cloth.vertices) p.w() = 0.3 * p.x() * p.x();  // bent in w: the rings do not care
  b.add_body(cloth);
  expect_patches_match_reference<4>(b.build(), edges_of(cloth.triangles), {0, 40, 44, 80});
}

TEST(Patch, IsTheRingsOfTheMeshGraphOnTheCliffordTorusAndASphere) {
  const Surface<4> torus = std::get<Surface<4>>(generate("clifford-torus", {{"n", 24}, {"m", 24}}));
  const Surface<4> sphere = std::get<Surface<4>>(generate("sphere", {{"n", 10}}));
  ModelBuilder<4> b(test::quiet_params<4>());
  b.add_body(torus);
  b.add_body(sphere);
  const Model<4> m = b.build();
  auto edges = edges_of(torus.triangles);
  const int first = static_cast<int>(torus.vertices.size());
  edges.merge(edges_of(sphere.triangles, first));
  expect_patches_match_reference<4>(m, edges, {0, 156, 575, first, first + 17});
}

TEST(Patch, IsTheRingsAlongACurve) {
  const Curve<3> knot = std::get<Curve<3>>(generate("torus-knot", {{"p", 2}, {"q", 4}, {"n", 64}}));
  ModelBuilder<3> b(test::quiet_params<3>());
  b.add_body(knot);
  const Model<3> m = b.build();
  std::set<std::pair<int, int>> edges;
  int first = 0;
  for (const auto& c : knot.components) {
    const int n = static_cast<int>(c.points.size());
    for (int i = 0; i + 1 < n + (c.closed ? 1 : 0); ++i)
      edges.insert({std::min(first + i, first + (i + 1) % n), std::max(first + i, first + (i + 1) % n)});
    first += n;
  }
  expect_patches_match_reference<3>(m, edges, {0, 7, 70});  // two components: a link
}

// Issue 34: three rings on the 24 x 24 torus are a small disc around the press, not the half of
// the torus a radius of 3 scene units took (322 of 576 vertices).
TEST(Patch, ThreeRingsOnTheTorusAreASmallDisc) {
  const Surface<4> torus = std::get<Surface<4>>(generate("clifford-torus", {{"n", 24}, {"m", 24}}));
  ModelBuilder<4> b(test::quiet_params<4>());
  b.add_body(torus);
  const Model<4> m = b.build();
  Patch patch;
  PatchScratch scratch;
  for (int centre : {0, 19, 543}) {
    const int c[] = {centre};
    grow_patch<4>(m, c, 3, patch, scratch);
    EXPECT_EQ(patch.vertices.size(), 37u) << "1 + 6 + 12 + 18: the hexagonal rings of a triangulated grid";
    for (int v : patch.vertices) {
      const int du = std::abs(v / 24 - centre / 24), dv = std::abs(v % 24 - centre % 24);
      EXPECT_LE(std::min(du, 24 - du), 3);
      EXPECT_LE(std::min(dv, 24 - dv), 3);
    }
  }
}

TEST(Patch, StaysOnItsBodyWhateverIsNearInSpace) {
  ModelBuilder<4> b(test::quiet_params<4>());
  const Surface<4> lower = test::flat_cloth<4>(6, 1.0), upper = test::flat_cloth<4>(6, 1.0, Vec4(0, 0, 0, 0.2));
  b.add_body(lower);
  b.add_body(upper);
  const Model<4> m = b.build();
  Patch patch;
  PatchScratch scratch;
  const int c[] = {14};
  grow_patch<4>(m, c, 1000, patch, scratch);
  EXPECT_EQ(patch.vertices.size(), 36u) << "all of its own sheet, none of the other 0.2 away in w";
  for (int v : patch.vertices) EXPECT_LT(v, 36);
}

TEST(Patch, BadRingsAndCentresAreHarmless) {
  ModelBuilder<3> b(test::quiet_params<3>());
  const Surface<3> cloth = test::flat_cloth<3>(4, 1.0);
  b.add_body(cloth);
  const Model<3> m = b.build();
  Patch patch;
  PatchScratch scratch;
  const int c[] = {-1, 99, 5, 5};
  for (int rings : {-1, 0, std::numeric_limits<int>::min()}) {
    grow_patch<3>(m, c, rings, patch, scratch);
    EXPECT_EQ(patch.vertices, std::vector<int>{5}) << "a centre taken once, alone";
  }
  // A broken adjacency (offsets past its end) is read only within its bounds.
  const std::vector<int> offset = {0, 5, 9}, adjacency = {1, 0};
  grow_patch(offset, adjacency, c, 3, patch, scratch);
  EXPECT_TRUE(patch.vertices.empty());
  const int zero[] = {0};
  grow_patch(offset, adjacency, zero, 3, patch, scratch);
  EXPECT_EQ(patch.vertices, (std::vector<int>{0, 1}));
}

TEST(Patch, MeshAdjacencyIsTheModels) {
  const Surface<4> torus = std::get<Surface<4>>(generate("clifford-torus", {{"n", 12}, {"m", 8}}));
  ModelBuilder<4> b(test::quiet_params<4>());
  b.add_body(torus);
  const Model<4> m = b.build();
  std::vector<int> offset, adjacency;
  mesh_adjacency(torus.triangles, static_cast<int>(torus.vertices.size()), offset, adjacency);
  EXPECT_EQ(offset, m.adjacency_offset);
  EXPECT_EQ(adjacency, m.adjacency);
}

}  // namespace
}  // namespace s4d
