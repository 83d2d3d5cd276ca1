// Combinatorial facts about a triangle mesh: edges, boundary, Euler characteristic, manifold-ness.
#pragma once
#include <array>
#include <vector>

#include "shape/surface.hpp"

namespace s4d {

struct MeshEdge {
  int a = 0, b = 0;     // vertex indices, a < b
  int triangles = 0;    // how many triangles use this edge
};

// Unique edges of the triangles, sorted by (a, b).
std::vector<MeshEdge> mesh_edges(const std::vector<Triangle>& tris);

struct TopologySummary {
  int vertices = 0;        // vertices used by at least one triangle
  int edges = 0;
  int faces = 0;
  int boundary_edges = 0;  // edges in exactly one triangle
  int singular_edges = 0;  // edges in three or more triangles
  int euler_characteristic = 0;  // V - E + F
  bool closed = false;     // no boundary edge
  bool manifold = false;   // every edge in 1 or 2 triangles and every vertex link one fan
  int components = 0;      // connected components of the triangle adjacency
  // Added by the shape layer:
  int degenerate_triangles = 0;  // triangles repeating a vertex (they make the mesh non-manifold)
  bool oriented = false;   // manifold, and neighbouring triangles agree on orientation (no edge
                           // is traversed twice in the same direction)
};

// Throws s4d::Error if a triangle uses a vertex index outside [0, vertex_count).
TopologySummary summarize_topology(int vertex_count, const std::vector<Triangle>& tris);

template <int D>
TopologySummary summarize_topology(const Surface<D>& s) {
  return summarize_topology(static_cast<int>(s.vertices.size()), s.triangles);
}

}  // namespace s4d
