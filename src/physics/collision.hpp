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
#include <utility>
#include <vector>

#include "physics/contact_cache.hpp"
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
  // The persistent contacts' counts (searches, exact re-solves, carried updates).
  const ContactCacheStats& contact_stats() const { return cache_.stats(); }
  // Exact cell-pair distances computed so far, by the proximity queries and the cache's re-solves.
  long long exact_distances() const { return prox_.exact_tests() + cache_.stats().solves; }

 private:
  struct Contact {
    int a = 0, b = 0;                   // cells
    std::array<double, 3> wa{}, wb{};   // barycentric weights of the closest points
    Vec<D> n = Vec<D>::Zero();          // unit, from b's point to a's
    double d = 0;                       // distance at x0
    double wsum = 0;                    // Σ w² / m over its vertices: the impulse's denominator
    double slack = 0;                   // m/s its normal velocity had to spare when last looked at
    double kicks = 0;                   // its vertices' weighted kick_ then
  };
  void repulsion(const Model<D>& model, std::span<const Vec<D>> x0, std::span<Vec<D>> x1,
                 std::span<Vec<D>> v, std::span<const std::uint8_t> pinned, double dt,
                 CollisionStats& stats);
  // Whether the vertices of this step's contacts have finite positions and velocities.
  bool touched_finite(const Model<D>& model, std::span<const Vec<D>> x,
                      std::span<const Vec<D>> v) const;
  int failsafe_pass(const Model<D>& model, std::span<const Vec<D>> x0, std::span<Vec<D>> x1);
  // This step's contacts within `reach` at x0, into contacts_ (with their impulse weight sums).
  void gather_contacts(const Model<D>& model, std::span<const Vec<D>> x0, double reach);

  // All pair finding goes through one coherent proximity query (self_proximity.hpp): its list
  // of close pairs with distance bounds is reused from step to step while motion is small, and
  // it answers both the repulsion's pairs within reach and the fail-safe's step candidates.
  SelfProximity<D, K> prox_;
  std::vector<ProximityPair<D>> pairs_;  // grows to the largest count seen
  std::vector<Contact> contacts_;      // grows to the largest contact count seen
  std::vector<std::uint8_t> hit_;      // nv, vertices of pairs the fail-safe caught this pass
  std::vector<double> w_;              // nv, inverse masses with pins at 0
  std::vector<double> kick_;           // nv, |Δv| the impulses gave the vertex this step, summed
  // The feature pairs given a contact this step (open addressing; keys never 0). Placing a pair
  // by its vertex, so that probes follow the cells' order, measured slower (more probes, no fewer
  // misses): hashed it is.
  struct FeatureSet {
    std::vector<std::array<std::uint64_t, 2>> slots;
    std::size_t mask = 0;
    int shift = 60;
    void reset(std::size_t n) {
      std::size_t size = 16;
      shift = 60;
      while (size < 2 * n) size *= 2, --shift;
      slots.assign(size, {0, 0});
      mask = size - 1;
    }
    // False when the pair (either order) is in already.
    bool insert(std::uint64_t a, std::uint64_t b) {
      if (a > b) std::swap(a, b);
      // The keys' low bits are often zero (a vertex's key is its index alone): mix, then take the
      // product's high bits.
      std::uint64_t h = a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full;
      h ^= h >> 31;
      std::size_t i = static_cast<std::size_t>((h * 0x9E3779B97F4A7C15ull) >> shift);
      for (;; i = (i + 1) & mask) {
        if (slots[i][0] == 0) {
          slots[i] = {a, b};
          return true;
        }
        if (slots[i][0] == a && slots[i][1] == b) return false;
      }
    }
  };
  FeatureSet features_;
  // Measured on the folded 64² cloth (count_instructions folded): see docs/performance.md.
  static constexpr double kCacheSkin = 0.2;
  static constexpr double kCacheReSolve = 0.02;
  ContactCache<D, K> cache_{kCacheSkin, kCacheReSolve};
};

}  // namespace s4d
