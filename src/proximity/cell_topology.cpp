// Building the cell topology: CSR arrays by counting, ring pairs deduplicated with a stamp array
// (linear in the mesh, no per-cell sort of candidate lists).
#include "proximity/cell_topology.hpp"

#include <algorithm>

namespace s4d {

namespace {

// CSR of `pairs` (key, value) with keys in [0, n).
void to_csr(const std::vector<std::array<int, 2>>& pairs, int n, std::vector<int>& offset,
            std::vector<int>& values) {
  offset.assign(n + 1, 0);
  for (const auto& p : pairs) ++offset[p[0] + 1];
  for (int i = 0; i < n; ++i) offset[i + 1] += offset[i];
  values.resize(pairs.size());
  std::vector<int> fill(offset.begin(), offset.end() - 1);
  for (const auto& p : pairs) values[fill[p[0]]++] = p[1];
}

}  // namespace

template <int K>
CellTopology<K>::CellTopology(const std::vector<Cell<K>>& cells, int nv) : vertex_count(nv) {
  const int nc = static_cast<int>(cells.size());
  std::vector<std::array<int, 2>> pairs;
  pairs.reserve(static_cast<std::size_t>(nc) * K);
  for (int c = 0; c < nc; ++c)
    for (int v : cells[c]) pairs.push_back({v, c});
  to_csr(pairs, nv, around_offset, around);

  pairs.clear();
  for (const Cell<K>& c : cells)
    for (int i = 0; i < K; ++i)
      for (int j = i + 1; j < K; ++j)
        if (c[i] != c[j]) pairs.push_back({std::min(c[i], c[j]), std::max(c[i], c[j])});
  // By (v - u, u): a grid's edges then come in long runs of one offset between consecutive
  // vertices, which the motion kernels read four at a time (see motion_kernels.cpp).
  std::sort(pairs.begin(), pairs.end(), [](const std::array<int, 2>& p, const std::array<int, 2>& q) {
    return p[1] - p[0] != q[1] - q[0] ? p[1] - p[0] < q[1] - q[0] : p[0] < q[0];
  });
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  edges = pairs;
  strided_edge_groups.assign(edges.size() / 4, 1);
  for (std::size_t g = 0; g < strided_edge_groups.size(); ++g)
    for (int j = 1; j < 4; ++j) {
      const auto& e0 = edges[4 * g];
      const auto& e = edges[4 * g + j];
      if (e[0] != e0[0] + j || e[1] != e0[1] + j) strided_edge_groups[g] = 0;
    }
  strided_cell_groups.assign(cells.size() / 8, 1);
  for (std::size_t g = 0; g < strided_cell_groups.size(); ++g)
    for (int k = 2; k < 8; ++k)
      for (int i = 0; i < K; ++i)
        if (cells[8 * g + k][i] != cells[8 * g + k % 2][i] + k / 2) strided_cell_groups[g] = 0;
  pairs.clear();
  for (const auto& e : edges) {
    pairs.push_back({e[0], e[1]});
    pairs.push_back({e[1], e[0]});
  }
  to_csr(pairs, nv, neighbour_offset, neighbours);

  // Ring partners: cells around the neighbours of a's vertices, later than a, sharing no vertex.
  std::vector<int> stamp(nc, -1), found;
  ring_offset.assign(1, 0);
  for (int a = 0; a < nc; ++a) {
    found.clear();
    for (int v : cells[a])
      for (int e = around_offset[v]; e < around_offset[v + 1]; ++e) stamp[around[e]] = a;
    for (int v : cells[a])
      for (int n = neighbour_offset[v]; n < neighbour_offset[v + 1]; ++n) {
        const int w = neighbours[n];
        for (int e = around_offset[w]; e < around_offset[w + 1]; ++e) {
          const int b = around[e];
          if (b <= a || stamp[b] == a) continue;
          stamp[b] = a;
          found.push_back(b);
        }
      }
    std::sort(found.begin(), found.end());
    ring.insert(ring.end(), found.begin(), found.end());
    ring_offset.push_back(static_cast<int>(ring.size()));
  }
}

template struct CellTopology<2>;
template struct CellTopology<3>;

}  // namespace s4d
