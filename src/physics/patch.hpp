// A patch of a surface (or a curve) around some vertices: the vertices within a geodesic radius
// along mesh edges, each weighted from 1 at a centre to 0 at the rim — what a hand carrying a
// region moves, and how far (a sculptor's falloff). Geodesic, not Euclidean: a sheet that passes
// near in R^D but is far along the surface is not taken along.
#pragma once
#include <span>
#include <vector>

#include "physics/model.hpp"

namespace s4d {

struct Patch {
  std::vector<int> vertices;   // the centres first, then by distance along the surface
  std::vector<double> weights; // (1 - (d/r)^2)^2 for geodesic distance d < r; 1 at a centre
};

// Reusable buffers, so that growing a patch on a running simulation does not allocate once sized.
struct PatchScratch {
  std::vector<double> distance;              // nv
  std::vector<std::pair<double, int>> heap;  // Dijkstra's frontier
  void reserve(int vertex_count, std::size_t edge_ends);
};

// The patch of radius `radius` (scene units, along mesh edges at positions x) around `centres`.
// radius <= 0 gives the centres alone, each with weight 1. Centres out of range are skipped.
template <int D>
void grow_patch(const Model<D>& model, std::span<const Vec<D>> x, std::span<const int> centres, double radius,
                Patch& out, PatchScratch& scratch);

}  // namespace s4d
