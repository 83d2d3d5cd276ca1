// Edge table, Euler characteristic and manifold checks of an indexed triangle mesh.
#include "shape/topology.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

#include "core/error.hpp"

namespace s4d {

namespace {

// Union-find with path halving; small and allocation-free after construction.
class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(static_cast<std::size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(int a, int b) { parent_[find(a)] = find(b); }

 private:
  std::vector<int> parent_;
};

bool degenerate(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

void check_indices(int vertex_count, const std::vector<Triangle>& tris) {
  for (std::size_t k = 0; k < tris.size(); ++k)
    for (int v : tris[k])
      if (v < 0 || v >= vertex_count)
        throw Error("triangle " + std::to_string(k) + " uses vertex " + std::to_string(v) +
                    ", outside the " + std::to_string(vertex_count) + " vertices of the mesh");
}

// A vertex is a manifold vertex when the edges opposite it in its triangles (its link) form one
// path (boundary vertex) or one cycle (interior vertex). With every edge in at most two
// triangles, each link vertex has degree <= 2, so "connected" is the remaining condition.
bool link_is_one_fan(int v, const std::vector<int>& incident, const std::vector<Triangle>& tris) {
  std::vector<std::pair<int, int>> link;  // opposite edges, as vertex pairs
  std::vector<int> nodes;
  for (int k : incident) {
    const Triangle& t = tris[k];
    int o[2], n = 0;
    for (int x : t)
      if (x != v) o[n++] = x;
    link.emplace_back(o[0], o[1]);
    nodes.push_back(o[0]);
    nodes.push_back(o[1]);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  auto id = [&](int x) {
    return static_cast<int>(std::lower_bound(nodes.begin(), nodes.end(), x) - nodes.begin());
  };
  std::vector<int> degree(nodes.size(), 0);
  DisjointSets sets(static_cast<int>(nodes.size()));
  for (const auto& [a, b] : link) {
    const int ia = id(a), ib = id(b);
    if (++degree[ia] > 2 || ++degree[ib] > 2) return false;
    sets.unite(ia, ib);
  }
  const int root = sets.find(0);
  for (int i = 1; i < static_cast<int>(nodes.size()); ++i)
    if (sets.find(i) != root) return false;
  return true;
}

}  // namespace

std::vector<MeshEdge> mesh_edges(const std::vector<Triangle>& tris) {
  std::vector<std::pair<int, int>> all;
  all.reserve(tris.size() * 3);
  for (const Triangle& t : tris) {
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      if (a == b) continue;  // a degenerate triangle has no edge there
      all.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(all.begin(), all.end());
  std::vector<MeshEdge> edges;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i;
    while (j < all.size() && all[j] == all[i]) ++j;
    edges.push_back({all[i].first, all[i].second, static_cast<int>(j - i)});
    i = j;
  }
  return edges;
}

TopologySummary summarize_topology(int vertex_count, const std::vector<Triangle>& tris) {
  if (vertex_count < 0) throw Error("a mesh cannot have a negative vertex count");
  check_indices(vertex_count, tris);

  TopologySummary s;
  s.faces = static_cast<int>(tris.size());

  // Vertex -> incident triangles, in CSR form (offsets + flat list).
  std::vector<int> offset(static_cast<std::size_t>(vertex_count) + 1, 0);
  for (const Triangle& t : tris) {
    if (degenerate(t)) {
      ++s.degenerate_triangles;
      continue;
    }
    for (int v : t) ++offset[v + 1];
  }
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  std::vector<int> incident(static_cast<std::size_t>(offset.back()));
  {
    std::vector<int> fill(offset.begin(), offset.end() - 1);
    for (int k = 0; k < s.faces; ++k)
      if (!degenerate(tris[k]))
        for (int v : tris[k]) incident[fill[v]++] = k;
  }

  DisjointSets sets(vertex_count);
  std::vector<char> used(static_cast<std::size_t>(vertex_count), 0);
  for (const Triangle& t : tris) {
    for (int v : t) used[v] = 1;
    sets.unite(t[0], t[1]);
    sets.unite(t[1], t[2]);
  }
  for (int v = 0; v < vertex_count; ++v) {
    if (!used[v]) continue;
    ++s.vertices;
    if (sets.find(v) == v) ++s.components;
  }

  const std::vector<MeshEdge> edges = mesh_edges(tris);
  s.edges = static_cast<int>(edges.size());
  for (const MeshEdge& e : edges) {
    if (e.triangles == 1) ++s.boundary_edges;
    if (e.triangles >= 3) ++s.singular_edges;
  }
  s.euler_characteristic = s.vertices - s.edges + s.faces;
  s.closed = s.faces > 0 && s.boundary_edges == 0;

  s.manifold = s.faces > 0 && s.singular_edges == 0 && s.degenerate_triangles == 0;
  for (int v = 0; v < vertex_count && s.manifold; ++v) {
    if (offset[v] == offset[v + 1]) continue;
    const std::vector<int> around(incident.begin() + offset[v], incident.begin() + offset[v + 1]);
    if (!link_is_one_fan(v, around, tris)) s.manifold = false;
  }

  // Consistent orientation: the two triangles on an interior edge traverse it in opposite
  // directions. Directed edges sorted, then each undirected pair must appear once each way.
  if (s.manifold) {
    std::vector<std::pair<int, int>> directed;
    directed.reserve(tris.size() * 3);
    for (const Triangle& t : tris)
      for (int e = 0; e < 3; ++e) directed.emplace_back(t[e], t[(e + 1) % 3]);
    std::sort(directed.begin(), directed.end());
    s.oriented = std::adjacent_find(directed.begin(), directed.end()) == directed.end();
  }
  return s;
}

}  // namespace s4d
