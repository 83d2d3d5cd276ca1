// Critical vertices of a PL height function from their lower links (see critical_levels.hpp).
#include "shape/critical_levels.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "shape/topology.hpp"

namespace s4d {

const char* critical_kind_name(CriticalKind k) {
  switch (k) {
    case CriticalKind::kSaddle: return "saddle";
    case CriticalKind::kDeath: return "death";
    case CriticalKind::kBirth: break;
  }
  return "birth";
}

template <int D>
std::vector<CriticalPoint> critical_points(const Surface<D>& mesh, const Frame<D>& frame) {
  const int nv = static_cast<int>(mesh.vertices.size());
  std::vector<double> depth(mesh.vertices.size());
  for (int v = 0; v < nv; ++v) depth[v] = frame.depth(mesh.vertices[v]);
  auto below = [&](int a, int b) { return depth[a] < depth[b] || (depth[a] == depth[b] && a < b); };

  // χ(lower link) = its vertices − its edges; `used` marks the vertices some triangle has.
  std::vector<int> lower_vertices(mesh.vertices.size(), 0), lower_edges(mesh.vertices.size(), 0);
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      if (t[k] < 0 || t[k] >= nv)
        throw Error("a triangle uses vertex " + std::to_string(t[k]) + " of a mesh of " + std::to_string(nv));
      used[t[k]] = 1;
    }
  for (const MeshEdge& e : mesh_edges(mesh.triangles))
    if (e.a != e.b) ++lower_vertices[below(e.a, e.b) ? e.b : e.a];
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int v = t[k], a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      if (v != a && v != b && a != b && below(a, v) && below(b, v)) ++lower_edges[v];
    }

  std::vector<CriticalPoint> points;
  for (int v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    const int change = 1 - (lower_vertices[v] - lower_edges[v]);
    if (change == 0) continue;
    CriticalPoint p;
    p.vertex = v;
    p.level = depth[v];
    if (change > 0) {
      p.kind = lower_vertices[v] == 0 ? CriticalKind::kBirth : CriticalKind::kDeath;
      p.multiplicity = change;
    } else {
      p.kind = CriticalKind::kSaddle;
      p.multiplicity = -change;
    }
    points.push_back(p);
  }
  std::sort(points.begin(), points.end(),
            [&](const CriticalPoint& a, const CriticalPoint& b) { return below(a.vertex, b.vertex); });
  return points;
}

CriticalCount count_critical(const std::vector<CriticalPoint>& points) {
  CriticalCount c;
  for (const CriticalPoint& p : points) {
    switch (p.kind) {
      case CriticalKind::kBirth: c.births += p.multiplicity; break;
      case CriticalKind::kSaddle: c.saddles += p.multiplicity; break;
      case CriticalKind::kDeath: c.deaths += p.multiplicity; break;
    }
  }
  return c;
}

template std::vector<CriticalPoint> critical_points(const Surface<2>&, const Frame<2>&);
template std::vector<CriticalPoint> critical_points(const Surface<3>&, const Frame<3>&);
template std::vector<CriticalPoint> critical_points(const Surface<4>&, const Frame<4>&);

}  // namespace s4d
