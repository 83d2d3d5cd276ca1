// Broad + narrow phase over whole meshes and curves in R^D: all cell pairs within δ, the earliest
// time of impact over a step, and intersecting pairs, for one mesh against itself or two meshes.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "proximity/bvh.hpp"
#include "proximity/closest_points.hpp"
#include "proximity/continuous_collision.hpp"
#include "proximity/separating_axes.hpp"

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
//
// Temporal coherence (on by default): a query keeps a list of every non-adjacent pair that was
// within a radius R = margin · (1 + skin) when it last ran the broad phase, each with a lower bound
// of its distance. Distances are 1-Lipschitz in the motion of the cells, so while the vertices
// stay close to where they were, a pair outside the list is still farther than the margin and a
// listed pair whose bound minus its cells' motion exceeds the margin needs no exact test. The list
// is rebuilt only when the motion since its build could break that promise. Answers are exactly
// those of a fresh broad phase; only their cost changes.
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
  // The same, leaving out the pairs `skip(a, b)` names (a < b) without looking at them: a caller
  // that ignores some pairs (the physics leaves a triangle's 2-ring to its springs) saves their
  // cost. `skip` must be a fixed property of the pair: its answer is kept with the listed pair.
  void pairs_within(std::span<const Vec<D>> x, double delta, std::vector<ProximityPair<D>>& out,
                    const std::function<bool(int, int)>& skip);
  // Earliest time in [0, 1] at which two cells sharing no vertex come within opt.thickness, every
  // vertex moving linearly from x0 to x1 (nv × D each).
  Impact<D> earliest_impact(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1,
                            const CcdOptions& opt);
  // Calls f(a, b) (a < b, sharing no vertex) for a superset of the pairs that come within
  // `thickness` while every vertex moves linearly from x0 to x1; the caller runs the exact test.
  // Pairs whose cached bound proves them apart over the step are left out.
  template <class F>
  void step_candidates(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1, double thickness,
                       F&& f);

  // Off: every query runs the broad phase from scratch (benchmarks of the cold query use this).
  void set_temporal_coherence(bool on);
  // The list's radius is margin · (1 + skin): a larger skin lists more pairs but survives more
  // motion before a rebuild. Clamped to [0, 8].
  void set_skin(double skin);
  // Broad-phase runs so far (list builds and cold queries): what coherence saves.
  long long broad_phase_runs() const { return broad_phase_runs_; }
  // Listed pairs whose bound was tightened, and exact distances computed, by pairs_within so far.
  long long bounds_tightened() const { return bounds_tightened_; }
  long long exact_tests() const { return exact_tests_; }
  std::size_t listed_pairs() const { return listed_.size(); }
  const Bvh<D>& bvh() const { return bvh_; }

 private:
  struct Listed {
    int a = 0, b = 0;
    double gap = 0;       // a lower bound of their distance when their cells had moved `moved_at`
    double moved_at = 0;  // moved_[a] + moved_[b] then
    std::int8_t skipped = -1;  // pairs_within's skip(a, b), once asked (-1: not yet)
    bool exact = false;        // gap is their exact distance (not a cheap bound)
    std::uint8_t faces = 0;    // face pair of their last exact answer (face_pair_code), a warm start
  };
  void check(std::size_t n) const;
  // Accumulates the motion from the last seen positions to x; false when there is no list (or
  // the positions are not comparable), so the caller rebuilds.
  bool advance(std::span<const Vec<D>> x);
  // Every unlisted pair is still farther than `margin` (plus `extra` of further motion per cell).
  bool list_covers(double margin, double extra) const;
  void build_list(std::span<const Vec<D>> x, double margin);
  // Per-cell motion over the step into step_; true when the list (built now if there was none and
  // the motion is small) answers the step, false when the caller must sweep the BVH instead
  // (after which swept boxes are in the refitted tree).
  bool prepare_step(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1, double thickness);
  double bound(const Listed& p) const { return p.gap - (moved_[p.a] + moved_[p.b] - p.moved_at); }

  std::vector<Cell<K>> cells_;
  int max_index_ = -1;
  std::vector<Box<D>> boxes_;  // nc, one per cell
  Bvh<D> bvh_;
  // Refits the tree to boxes_, and redoes the leaf masks when that rebuilt it.
  void refit_tree();
  long long mask_builds_ = -1;       // bvh_.builds() when the leaf masks were made
  // Calls f(a, b), a < b, for every pair of cells sharing no vertex whose boxes are near. Pairs
  // sharing a vertex are most of what boxes find on a mesh; leaf_masks_ drops them a leaf pair
  // at a time, with no test per pair.
  template <class F>
  void candidate_pairs(double margin, F&& f) const {
    const float fm = float_margin(margin);
    bvh_.self_leaf_pairs(margin, [&](int fa, int ca, int fb, int cb) {
      unsigned allowed = 0xFFFFu;
      const int la = leaf_of_slot_[fa], lb = leaf_of_slot_[fb];
      for (int e = leaf_mask_offset_[la]; e < leaf_mask_offset_[la + 1]; ++e)
        if (leaf_masks_[e].other == lb) {
          allowed = leaf_masks_[e].allowed;
          break;
        }
      for (int i = 0; i < ca; ++i)
        for (int j = fa == fb ? i + 1 : 0; j < cb; ++j) {
          if (!((allowed >> (i * kLeafBits + j)) & 1u) || !bvh_.prim_near(fa + i, fb + j, fm)) continue;
          const int p = bvh_.id(fa + i), q = bvh_.id(fb + j);
          f(std::min(p, q), std::max(p, q));
        }
    });
  }
  // Per leaf, the leaves it shares a vertex with and which of their slot pairs share none (bit
  // i·kLeafBits + j: slot first_a + i against first_b + j). Redone when the tree is rebuilt.
  static constexpr int kLeafBits = 4;
  static_assert(Bvh<D>::kLeafSize <= kLeafBits, "leaf masks hold 4 × 4 slot pairs");
  struct LeafMask {
    int other = 0;
    unsigned allowed = 0xFFFFu;
  };
  void build_leaf_masks();
  std::vector<int> leaf_of_slot_;
  std::vector<int> leaf_first_;
  std::vector<int> leaf_mask_offset_;
  std::vector<LeafMask> leaf_masks_;
  std::vector<int> around_offset_, around_;  // cells around each vertex (CSR, fixed)

  bool coherent_ = true;
  double skin_ = 1.0;
  double radius_ = -1;           // every unlisted pair was farther than this at the build (< 0: none)
  std::vector<Listed> listed_;   // sorted by (a, b), so answers come out sorted
  std::vector<Listed> unsorted_;  // scratch of the build
  std::vector<int> bucket_;       // scratch of the build: counting sort by a
  std::vector<Vec<D>> x_seen_;   // positions at the last query
  std::vector<double> vertex_move_;  // nv, scratch: one vertex's displacement
  std::vector<double> moved_;    // nc: motion bound of each cell accumulated since the build
  std::vector<double> step_;     // nc: motion bound of each cell over the current step
  double max_moved_ = 0;
  long long broad_phase_runs_ = 0;
  long long bounds_tightened_ = 0;
  long long exact_tests_ = 0;
};

template <int D, int K>
template <class F>
void SelfProximity<D, K>::step_candidates(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1,
                                          double thickness, F&& f) {
  const double th = thickness > 0 ? thickness : 0.0;
  if (prepare_step(x0, x1, th)) {
    for (Listed& p : listed_) {
      const double reach = th + step_[p.a] + step_[p.b];
      if (bound(p) > reach) continue;
      // Tighten the bound at x0 before handing the pair out: a pair that only looked close
      // (its bound was the gap of boxes) is then left out of this step and of the next few.
      Simplex<D, K> sa, sb;
      for (int i = 0; i < K; ++i) sa[i] = x0[cells_[p.a][i]], sb[i] = x0[cells_[p.b][i]];
      ++bounds_tightened_;
      const double lower = distance_lower_bound<D, K, K>(sa, sb, 1.5 * reach);
      if (lower > bound(p)) {
        p.gap = lower;
        p.exact = false;
        p.moved_at = moved_[p.a] + moved_[p.b];
      }
      if (!(lower > reach)) f(p.a, p.b);  // NaN: test it
    }
    return;
  }
  candidate_pairs(th, f);
}

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
