// The cell topology (edges, neighbours, cells around vertices, ring pairs) against definitions
// checked pair by pair.
#include "proximity/cell_topology.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace s4d {
namespace {

template <int K>
bool joined_by_edge(const Cell<K>& a, const Cell<K>& b, const std::set<std::pair<int, int>>& edges) {
  for (int u : a)
    for (int v : b)
      if (edges.count({std::min(u, v), std::max(u, v)})) return true;
  return false;
}

template <int K>
void check_topology(const std::vector<Cell<K>>& cells, int nv) {
  const CellTopology<K> t(cells, nv);
  std::set<std::pair<int, int>> edges;
  for (const auto& c : cells)
    for (int i = 0; i < K; ++i)
      for (int j = i + 1; j < K; ++j)
        if (c[i] != c[j]) edges.insert({std::min(c[i], c[j]), std::max(c[i], c[j])});
  ASSERT_EQ(t.edges.size(), edges.size());
  for (const auto& e : t.edges) EXPECT_TRUE(edges.count({e[0], e[1]}));
  for (int v = 0; v < nv; ++v) {
    std::set<int> want, got(t.neighbours.begin() + t.neighbour_offset[v],
                            t.neighbours.begin() + t.neighbour_offset[v + 1]);
    for (const auto& [a, b] : edges) {
      if (a == v) want.insert(b);
      if (b == v) want.insert(a);
    }
    EXPECT_EQ(got, want) << "vertex " << v;
    std::set<int> around(t.around.begin() + t.around_offset[v], t.around.begin() + t.around_offset[v + 1]);
    for (int c = 0; c < static_cast<int>(cells.size()); ++c)
      EXPECT_EQ(around.count(c) > 0, std::count(cells[c].begin(), cells[c].end(), v) > 0);
  }
  // Ring pairs: a < b, sharing no vertex, joined by an edge; every such pair, each once, sorted.
  std::vector<std::pair<int, int>> want, got;
  for (int a = 0; a < static_cast<int>(cells.size()); ++a) {
    for (int k = t.ring_offset[a]; k < t.ring_offset[a + 1]; ++k) got.push_back({a, t.ring[k]});
    for (int b = a + 1; b < static_cast<int>(cells.size()); ++b)
      if (!share_vertex<K, K>(cells[a], cells[b]) && joined_by_edge<K>(cells[a], cells[b], edges))
        want.push_back({a, b});
  }
  EXPECT_EQ(got, want);
  // Topological neighbours: every cell sharing a vertex or forming a ring pair, and no other.
  for (int a = 0; a < static_cast<int>(cells.size()); ++a) {
    std::set<int> seen;
    t.for_each_topological_neighbour(cells[a], [&](int c) { seen.insert(c); });
    for (int b = 0; b < static_cast<int>(cells.size()); ++b) {
      const bool near =
          share_vertex<K, K>(cells[a], cells[b]) || joined_by_edge<K>(cells[a], cells[b], edges);
      EXPECT_EQ(seen.count(b) > 0, near) << a << " " << b;
    }
  }
}

TEST(CellTopology, GridTrianglesAndRandomCellsMatchTheirDefinitions) {
  std::vector<Cell<3>> grid;
  const int n = 7;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j;
      grid.push_back({a, a + 1, a + n + 1});
      grid.push_back({a, a + n + 1, a + n});
    }
  check_topology<3>(grid, n * n);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> pick(0, 39);
  std::vector<Cell<3>> tris;
  std::vector<Cell<2>> segs;
  while (tris.size() < 60) {
    Cell<3> c{pick(rng), pick(rng), pick(rng)};
    if (c[0] != c[1] && c[1] != c[2] && c[0] != c[2]) tris.push_back(c);
  }
  while (segs.size() < 50) {
    Cell<2> c{pick(rng), pick(rng)};
    if (c[0] != c[1]) segs.push_back(c);
  }
  check_topology<3>(tris, 40);
  check_topology<2>(segs, 40);
  // A closed polygon: segment i's ring partners are i ± 2.
  std::vector<Cell<2>> loop;
  for (int i = 0; i < 12; ++i) loop.push_back({i, (i + 1) % 12});
  const CellTopology<2> t(loop, 12);
  EXPECT_EQ(t.ring.size(), 12u);
  check_topology<2>(loop, 12);
}

}  // namespace
}  // namespace s4d
