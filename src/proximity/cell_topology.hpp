// The fixed neighbourhood structure of a mesh's cells that self-proximity leans on: its edges,
// vertex adjacency, the cells around each vertex, and its ring pairs.
#pragma once
#include <cstdint>
#include <vector>

#include "proximity/cells.hpp"

namespace s4d {

// A ring pair is two cells that share no vertex but are joined by a mesh edge (a vertex of one
// is a neighbour of a vertex of the other): the next-nearest neighbours on the surface. On a
// fine mesh they are most of the pairs any distance query near the mesh's own spacing finds,
// and their relative motion is the mesh's strain, far smaller than its motion.
template <int K>
struct CellTopology {
  CellTopology() = default;
  // Cells' vertex indices must lie in [0, nv).
  CellTopology(const std::vector<Cell<K>>& cells, int nv);

  int vertex_count = 0;
  std::vector<std::array<int, 2>> edges;     // unique, (u, v) with u < v, sorted by (v - u, u)
  // Per whole group of four edges (edges[4g .. 4g + 3]): 1 when they are (u0 + j, v0 + j), a run of
  // one offset between consecutive vertices (most of a grid's), which kernels read as such.
  std::vector<std::uint8_t> strided_edge_groups;
  // Per whole group of eight cells (cells[8g .. 8g + 7]): 1 when cells 8g + p + 2m are cell 8g + p
  // with every vertex index + m (p = 0, 1; m < 4): a grid's two triangles a quad, along a row.
  std::vector<std::uint8_t> strided_cell_groups;
  std::vector<int> neighbour_offset, neighbours;  // CSR: each vertex's neighbours along edges
  std::vector<int> around_offset, around;    // CSR: the cells holding each vertex
  std::vector<int> ring_offset, ring;        // CSR by cell a: its ring partners b > a, sorted

  // f(cell) for every cell sharing a vertex with `c` or forming a ring pair with it (c itself
  // included, some cells more than once).
  template <class F>
  void for_each_topological_neighbour(const Cell<K>& c, F&& f) const {
    for (int v : c) {
      for (int e = around_offset[v]; e < around_offset[v + 1]; ++e) f(around[e]);
      for (int n = neighbour_offset[v]; n < neighbour_offset[v + 1]; ++n) {
        const int w = neighbours[n];
        for (int e = around_offset[w]; e < around_offset[w + 1]; ++e) f(around[e]);
      }
    }
  }
};

}  // namespace s4d
