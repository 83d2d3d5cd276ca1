// Breadth-first over the mesh's CSR adjacency, cut off at the ring count.
#include "physics/patch.hpp"

#include <algorithm>

namespace s4d {

void PatchScratch::reserve(int vertex_count) { ring.reserve(static_cast<std::size_t>(std::max(vertex_count, 0))); }

double patch_weight(int k, int rings) {
  if (rings <= 0 || k <= 0) return 1;
  const double u = static_cast<double>(k) / (rings + 1);
  return (1 - u * u) * (1 - u * u);
}

void grow_patch(std::span<const int> offset, std::span<const int> adjacency, std::span<const int> centres, int rings,
                Patch& out, PatchScratch& scratch) {
  out.vertices.clear();
  out.rings.clear();
  out.weights.clear();
  const int nv = offset.empty() ? 0 : static_cast<int>(offset.size()) - 1;
  auto& ring = scratch.ring;
  ring.assign(static_cast<std::size_t>(nv), -1);
  for (int c : centres)
    if (c >= 0 && c < nv && ring[static_cast<std::size_t>(c)] < 0) {
      ring[static_cast<std::size_t>(c)] = 0;
      out.vertices.push_back(c);
    }
  // out.vertices is the queue: the front part is done, the rest waits, ring by ring.
  for (std::size_t head = 0; head < out.vertices.size(); ++head) {
    const int v = out.vertices[head];
    const int k = ring[static_cast<std::size_t>(v)];
    if (k >= rings) continue;
    const int lo = std::max(offset[static_cast<std::size_t>(v)], 0);
    const int hi = std::min(offset[static_cast<std::size_t>(v) + 1], static_cast<int>(adjacency.size()));
    for (int e = lo; e < hi; ++e) {
      const int n = adjacency[static_cast<std::size_t>(e)];
      if (n < 0 || n >= nv || ring[static_cast<std::size_t>(n)] >= 0) continue;
      ring[static_cast<std::size_t>(n)] = k + 1;
      out.vertices.push_back(n);
    }
  }
  for (int v : out.vertices) {
    out.rings.push_back(ring[static_cast<std::size_t>(v)]);
    out.weights.push_back(patch_weight(out.rings.back(), rings));
  }
}

void mesh_adjacency(std::span<const std::array<int, 3>> triangles, int vertex_count, std::vector<int>& offset,
                    std::vector<int>& adjacency) {
  const std::size_t nv = static_cast<std::size_t>(std::max(vertex_count, 0));
  std::vector<std::vector<int>> adj(nv);
  for (const auto& t : triangles) {
    if (std::any_of(t.begin(), t.end(), [&](int c) { return c < 0 || c >= vertex_count; })) continue;
    for (int c = 0; c < 3; ++c) {
      adj[static_cast<std::size_t>(t[c])].push_back(t[(c + 1) % 3]);
      adj[static_cast<std::size_t>(t[(c + 1) % 3])].push_back(t[c]);
    }
  }
  offset.assign(1, 0);
  adjacency.clear();
  for (auto& a : adj) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    adjacency.insert(adjacency.end(), a.begin(), a.end());
    offset.push_back(static_cast<int>(adjacency.size()));
  }
}

}  // namespace s4d
