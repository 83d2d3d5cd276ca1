// Broad + narrow phase over whole meshes and curves in R^D: all cell pairs within δ, the earliest
// time of impact over a step, and intersecting pairs, for one mesh against itself
// (self_proximity.hpp) or two meshes (here).
#pragma once
#include <span>
#include <vector>

#include "proximity/bvh.hpp"
#include "proximity/cells.hpp"
#include "proximity/continuous_collision.hpp"
#include "proximity/self_proximity.hpp"

namespace s4d {

// Two meshes (or a mesh and a curve) against each other; cells of the two never count as adjacent.
template <int D, int KA, int KB>
class PairProximity {
 public:
  PairProximity() = default;
  PairProximity(std::vector<Cell<KA>> cells_a, std::vector<Cell<KB>> cells_b);

  void pairs_within(std::span<const Vec<D>> xa, std::span<const Vec<D>> xb, double delta,
                    std::vector<ProximityPair<D>>& out);
  // The smallest distance between a cell of each, when it is at most `up_to`; else infinity.
  // Keeps no pairs, so it stays small where pairs_within at `up_to` would list millions.
  double smallest_distance(std::span<const Vec<D>> xa, std::span<const Vec<D>> xb, double up_to);
  Impact<D> earliest_impact(std::span<const Vec<D>> xa0, std::span<const Vec<D>> xa1,
                            std::span<const Vec<D>> xb0, std::span<const Vec<D>> xb1,
                            const CcdOptions& opt);

 private:
  void refit_at(std::span<const Vec<D>> xa, std::span<const Vec<D>> xb);  // the boxes and trees at rest

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
