// Broad + narrow phase over whole meshes and curves in R^D: all cell pairs within δ, the earliest
// time of impact over a step, and intersecting pairs, for one mesh against itself or two meshes.
#pragma once
#include <array>
#include <span>
#include <vector>

#include "proximity/bvh.hpp"
#include "proximity/closest_points.hpp"
#include "proximity/continuous_collision.hpp"

namespace s4d {

// A cell is a simplex of a mesh given by vertex indices: K = 2 curve segments, K = 3 triangles.
template <int K>
using Cell = std::array<int, K>;

template <int D>
struct ProximityPair {
  int a = 0, b = 0;          // cell indices (self queries: a < b; pair queries: a in first mesh)
  ClosestPoints<D> closest;  // exact closest points, p on cell a, q on cell b
};

template <int D>
struct Impact {
  bool hit = false;          // some pair comes within the thickness during the step
  double t = 1;              // earliest such time in [0, 1] (conservative: never late)
  int a = -1, b = -1;        // the pair that hits first
  ClosestPoints<D> at_t;     // their closest points at time t
  int narrow_tests = 0;      // pairs that reached exact continuous collision (for tuning)
};

// Cells that share a vertex touch by construction and are never paired in self queries.
template <int KA, int KB>
inline bool share_vertex(const Cell<KA>& a, const Cell<KB>& b) {
  for (int i = 0; i < KA; ++i)
    for (int j = 0; j < KB; ++j)
      if (a[i] == b[j]) return true;
  return false;
}

// One mesh (or curve) against itself. Holds its BVH and box buffers, so repeated queries on
// moving vertices refit rather than rebuild and do not allocate (beyond growing `out`).
template <int D, int K>
class SelfProximity {
 public:
  SelfProximity() = default;
  // Throws s4d::Error if a cell has a negative index.
  explicit SelfProximity(std::vector<Cell<K>> cells);

  const std::vector<Cell<K>>& cells() const { return cells_; }

  // Every pair of cells sharing no vertex whose distance is <= delta at positions x (nv × D),
  // sorted by (a, b). Throws s4d::Error if x is shorter than the largest index.
  void pairs_within(std::span<const Vec<D>> x, double delta, std::vector<ProximityPair<D>>& out);
  // Earliest time in [0, 1] at which two cells sharing no vertex come within opt.thickness, every
  // vertex moving linearly from x0 to x1 (nv × D each).
  Impact<D> earliest_impact(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1,
                            const CcdOptions& opt);
  const Bvh<D>& bvh() const { return bvh_; }

 private:
  void check(std::size_t n) const;
  std::vector<Cell<K>> cells_;
  int max_index_ = -1;
  std::vector<Box<D>> boxes_;  // nc, one per cell
  Bvh<D> bvh_;
};

// Two meshes (or a mesh and a curve) against each other; cells of the two never count as adjacent.
template <int D, int KA, int KB>
class PairProximity {
 public:
  PairProximity() = default;
  PairProximity(std::vector<Cell<KA>> cells_a, std::vector<Cell<KB>> cells_b);

  void pairs_within(std::span<const Vec<D>> xa, std::span<const Vec<D>> xb, double delta,
                    std::vector<ProximityPair<D>>& out);
  Impact<D> earliest_impact(std::span<const Vec<D>> xa0, std::span<const Vec<D>> xa1,
                            std::span<const Vec<D>> xb0, std::span<const Vec<D>> xb1,
                            const CcdOptions& opt);

 private:
  std::vector<Cell<KA>> cells_a_;
  std::vector<Cell<KB>> cells_b_;
  int max_a_ = -1, max_b_ = -1;
  std::vector<Box<D>> boxes_a_, boxes_b_;  // one per cell of each mesh
  Bvh<D> bvh_a_, bvh_b_;
};

// Convenience: pairs of a mesh's own cells that touch or cross (distance <= tolerance, scene
// units; floating point never gives exactly 0 for a crossing in R^4).
template <int D, int K>
std::vector<ProximityPair<D>> intersecting_pairs(std::span<const Vec<D>> x,
                                                 const std::vector<Cell<K>>& cells,
                                                 double tolerance);

}  // namespace s4d
