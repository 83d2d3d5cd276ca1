// A patch of a surface (or a curve) around some vertices: the vertices within a number of rings of
// mesh edges, each weighted from 1 at a centre down towards 0 at the rim — what a hand carrying a
// region moves, and how far (a sculptor's falloff). Counted along the mesh, never by distance in
// R^D or in a shadow: a sheet that passes near in space (or that the shadow folds onto this one)
// but is far along the surface is not taken along, and the patch has the same vertices whatever
// the surface's shape at the press.
#pragma once
#include <array>
#include <span>
#include <vector>

#include "physics/model.hpp"

namespace s4d {

struct Patch {
  std::vector<int> vertices;   // the centres first, then ring by ring
  std::vector<int> rings;      // each vertex's ring: 0 for a centre
  std::vector<double> weights; // (1 - (k / (n + 1))^2)^2 for ring k of n: 1 at a centre, > 0 at the rim
};

// Reusable buffers, so that growing a patch on a running simulation does not allocate once sized.
struct PatchScratch {
  std::vector<int> ring;  // nv: each vertex's ring, -1 not reached
  void reserve(int vertex_count);
};

// The patch of `rings` rings of edges around `centres` over a CSR adjacency (offset: nv + 1
// entries, adjacency: the neighbours of vertex v at [offset[v], offset[v + 1])). rings <= 0 gives
// the centres alone, each with weight 1. Centres out of range are skipped, repeated ones taken once.
void grow_patch(std::span<const int> offset, std::span<const int> adjacency, std::span<const int> centres, int rings,
                Patch& out, PatchScratch& scratch);

// The same over a Model's mesh (and curve) edges.
template <int D>
void grow_patch(const Model<D>& model, std::span<const int> centres, int rings, Patch& out, PatchScratch& scratch) {
  grow_patch(model.adjacency_offset, model.adjacency, centres, rings, out, scratch);
}

// The weight of ring k in a patch of `rings` rings.
double patch_weight(int k, int rings);

// A CSR adjacency over the edges of `triangles` on `vertex_count` vertices (what the window uses
// to show the patch a press would carry); triangles with a corner out of range are skipped.
void mesh_adjacency(std::span<const std::array<int, 3>> triangles, int vertex_count, std::vector<int>& offset,
                    std::vector<int>& adjacency);

}  // namespace s4d
