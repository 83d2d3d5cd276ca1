// Collision avoidance for the mass-spring world, on the proximity kernel (exact closest points
// and conservative-advancement CCD in R^D), over cells of K vertices: triangles (K = 3) of
// surfaces or segments (K = 2) of curves. Two layers:
//  1. repulsion (the paper's §5.1.2): pairs closer than the contact thickness δ get inelastic
//     normal impulses with Coulomb friction (energy can only leave), plus the paper's equal and
//     opposite displacement along the closest-point line back towards δ (positions only);
//  2. a fail-safe: continuous collision over the step with the hard thickness η < δ; vertices of
//     any pair that would come within η are stopped where they were, pass after pass, and if
//     that has not converged every vertex is stopped. The start of a step is always η-separated,
//     so its end is too: no step ends with two surfaces (or strands) touching or crossed.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "physics/model.hpp"
#include "proximity/mesh_proximity.hpp"

namespace s4d {

struct PhysicsWarnings;

struct CollisionStats {
  int contacts = 0;       // pairs that received a repulsion impulse or push
  int frozen = 0;         // vertices stopped by the fail-safe
  int ccd_passes = 0;     // continuous passes run
  bool global_freeze = false;
  // The repulsion left a non-finite position or velocity (absurd input overflowing): the caller
  // rolls the step back. Only its impulses can do that: the integrator checked every vertex
  // before, and the fail-safe only puts vertices back where they started.
  bool nonfinite = false;
};

template <int D, int K>
class CollisionSolver {
 public:
  CollisionSolver() = default;
  explicit CollisionSolver(const Model<D>& model);

  // x0: the (η-separated) start of the step; x1: the proposed end, corrected in place; v: the
  // velocities, corrected in place; pinned vertices have infinite mass. Allocates nothing once
  // warmed up (its pair buffer only grows).
  CollisionStats solve(const Model<D>& model, std::span<const Vec<D>> x0, std::span<Vec<D>> x1,
                       std::span<Vec<D>> v, std::span<const std::uint8_t> pinned, double dt);
  // Broad-phase runs so far: the proximity list is rebuilt only when motion calls for it.
  long long broad_phase_runs() const { return prox_.broad_phase_runs(); }

 private:
  struct Contact {
    int a = 0, b = 0;                   // cells
    std::array<double, 3> wa{}, wb{};   // barycentric weights of the closest points
    Vec<D> n = Vec<D>::Zero();          // unit, from b's point to a's
    double d = 0;                       // distance at x0
  };
  void repulsion(const Model<D>& model, std::span<const Vec<D>> x0, std::span<Vec<D>> x1,
                 std::span<Vec<D>> v, std::span<const std::uint8_t> pinned, double dt,
                 CollisionStats& stats);
  // Whether the vertices of this step's contacts have finite positions and velocities.
  bool touched_finite(const Model<D>& model, std::span<const Vec<D>> x,
                      std::span<const Vec<D>> v) const;
  int failsafe_pass(const Model<D>& model, std::span<const Vec<D>> x0, std::span<Vec<D>> x1);

  // All pair finding goes through one coherent proximity query (self_proximity.hpp): its list
  // of close pairs with distance bounds is reused from step to step while motion is small, and
  // it answers both the repulsion's pairs within reach and the fail-safe's step candidates.
  SelfProximity<D, K> prox_;
  std::vector<ProximityPair<D>> pairs_;  // grows to the largest count seen
  std::vector<Contact> contacts_;      // grows to the largest contact count seen
  std::vector<std::uint8_t> hit_;      // nv, vertices of pairs the fail-safe caught this pass
  std::vector<double> w_;              // nv, inverse masses with pins at 0
};

}  // namespace s4d
