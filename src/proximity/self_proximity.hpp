// One mesh (or curve) against itself: all cell pairs within δ and the earliest impact of a step,
// answered from temporally coherent bounds so that a simulation's per-step query costs a
// fraction of a fresh broad phase.
#pragma once
#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "proximity/bvh.hpp"
#include "proximity/cell_topology.hpp"
#include "proximity/cells.hpp"
#include "proximity/continuous_collision.hpp"
#include "proximity/motion_kernels.hpp"
#include "proximity/narrow_phase.hpp"
#include "proximity/separating_axes.hpp"

namespace s4d {

// Whether a self query reports ring pairs (cells sharing no vertex but joined by a mesh edge; see
// cell_topology.hpp). A cloth simulation leaves them to its springs and asks for the others only.
enum class RingPairs { kInclude, kExclude };

// Holds the BVH, the topology and the bounds, so repeated queries on moving vertices refit rather
// than rebuild and do not allocate once warmed up (beyond growing `out`).
//
// Temporal coherence (on by default) rests on one fact: a distance is 1-Lipschitz in relative
// motion. If the vertices moved by Δ_v since some time t0, dist_ab(t) >= dist_ab(t0) - M_ab with
// M_ab = max |Δ_i - Δ_j| over the vertices i of a and j of b. Pairs are tracked in two sets:
//  - the list: every non-adjacent pair that is not a ring pair (below) and whose boxes were
//    within R = margin · (1 + skin) at the last build. Each keeps g = (a lower bound at some t0)
//    - M_ab(t0), with motion measured from the build, so that dist_ab(t) >= g - M_ab(t). An
//    unlisted pair is still farther than R - 2ρ, where ρ is the radius of a ball holding every
//    displacement since the build (net, not path length; a common translation costs nothing).
//    The list is rebuilt, keeping what it knew of the pairs that stay, when R - 2ρ falls below
//    the margin.
//  - the ring pairs (fixed by the topology: next-nearest neighbours on the mesh), on a fine mesh
//    most of what any query near the mesh's own spacing finds. They do not depend on the list:
//    the strain of the edges around a cell bounds M_ab for all its ring partners at once (three
//    edges join any vertex of a to any of b; see ring_bounds), and each cell sums these bounds
//    over the moves between the queries that look at ring pairs (an odometer, S_a). A pair proven
//    at least L apart keeps G = L + S_a, and dist_ab >= G - S_a for as long as the odometer runs:
//    a bound re-proven now loses nothing of the motion before, and far pairs cost a comparison per
//    cell.
//    Ring pairs that come near the margin move to the fringe, where each keeps a lower bound of
//    its distance at its own snapshot (its six vertices' positions then): M_ab is then their
//    exact relative motion since, and a pair is looked at again only once it has really moved
//    by its slack.
// Answers are exactly those of a fresh broad phase; only their cost changes.
template <int D, int K>
class SelfProximity {
 public:
  SelfProximity() = default;
  // Throws s4d::Error if a cell has a negative index.
  explicit SelfProximity(std::vector<Cell<K>> cells);

  const std::vector<Cell<K>>& cells() const { return cells_; }
  const CellTopology<K>& topology() const { return topo_; }

  // Every pair of cells sharing no vertex whose distance is <= delta at positions x (nv × D),
  // sorted by (a, b); ring pairs left out when asked. Throws s4d::Error if x is shorter than the
  // largest index or delta is NaN.
  void pairs_within(std::span<const Vec<D>> x, double delta, std::vector<ProximityPair<D>>& out,
                    RingPairs ring = RingPairs::kInclude);
  // Earliest time in [0, 1] at which two cells sharing no vertex come within opt.thickness, every
  // vertex moving linearly from x0 to x1 (nv × D each).
  Impact<D> earliest_impact(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1,
                            const CcdOptions& opt);
  // Calls f(a, b) (a < b, sharing no vertex) for a superset of the pairs that come within
  // `thickness` while every vertex moves linearly from x0 to x1; the caller runs the exact test.
  // Pairs whose bound proves them apart over the step are left out.
  template <class F>
  void step_candidates(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1, double thickness,
                       F&& f);

  // Off: every query runs the broad phase from scratch (benchmarks of the cold query use this).
  void set_temporal_coherence(bool on);
  // The list's radius is margin · (1 + skin): a larger skin lists more pairs but survives more
  // motion before a rebuild. Clamped to [0, 8]; NaN gives the default.
  void set_skin(double skin);
  // Measured on proximity_bench's stepping 64² queries (instructions a query under callgrind):
  // skin 0.8 → pairs 3.58 M, impact 4.23 M; 1.0 → 3.41 M, 4.18 M; 1.25 → 3.43 M, 4.00 M;
  // 1.5 → 3.41 M, 4.01 M. A physics step sets its own (collision.cpp).
  static constexpr double kDefaultSkin = 1.5;
  // Broad-phase runs so far (list builds and cold queries): what coherence saves.
  long long broad_phase_runs() const { return broad_phase_runs_; }
  // Pairs whose bound was tightened, and exact distances computed, by the queries so far.
  long long bounds_tightened() const { return bounds_tightened_; }
  long long exact_tests() const { return exact_tests_; }
  std::size_t listed_pairs() const { return listed_.size(); }
  std::size_t ring_pairs() const { return ring_gap_.size(); }
  std::size_t fringe_pairs() const { return fringe_.size(); }
  const Bvh<D>& bvh() const { return bvh_; }

 private:
  // What a query knows of one pair beyond its bound, to re-prove it cheaply.
  struct Hints {
    bool touching = false;   // within the margin at its last exact test (a resting contact)
    std::uint8_t faces = 0;  // face pair of its last exact answer (face_pair_code): warm start
    // The separating direction last found for it (zero: none): motion turns it slowly, so the
    // gap of the cells' projections on it stays a tight lower bound, six dot products against
    // the forty of the separating axes (and more of the exact distance).
    std::array<float, D> axis{};
  };
  // A listed pair: dist_ab(t) >= gap - M_ab(t), M over the displacement since the build. (Ring
  // pairs keep their G and hints in ring_gap_ and ring_hints_.)
  struct Tracked {
    int a = 0, b = 0;
    double gap = 0;
    Hints hints;
  };
  // A ring pair near the margin: dist_ab(t) >= lower - (its vertices' relative motion since x0).
  struct Fringe {
    int a = 0, b = 0;
    int ring = 0;  // its index among the ring pairs
    double lower = 0;
    std::array<Vec<D>, 2 * K> x0;  // the snapshot: a's vertices, then b's
    Hints hints;
  };
  // The motion bounds of one displacement field u (nv, centred), coarse to fine, the finer ones
  // worked out only when a coarser one does not settle a pair: every |u| <= rho (so every
  // M_ab <= 2 rho); per cell, a bound of M_ab over all its ring partners (ring_bounds, never more
  // than 2 rho); per pair, M_ab itself (max_relative).
  struct MotionBounds {
    const std::vector<Vec<D>>* u = nullptr;
    double rho = 0;
    std::vector<double> ring;             // per cell, once ring_valid
    // Scratch, per vertex: the largest change of its edges (squared, then its root); the same over
    // the vertex and its neighbours.
    std::vector<double> edge_max, around;
    bool ring_valid = false;
    void reset(const std::vector<Vec<D>>* field, double radius) {
      u = field;
      rho = radius;
      ring_valid = false;
    }
  };
  // A pair whose bound is gap - slack is apart beyond `threshold` when gap > this limit: one
  // comparison a pair instead of a subtraction, the sum rounded up by 1e-12 relative, far more
  // than the few ulps the subtractions could lose and far less than any slack that matters (a
  // pair at the limit is looked at, never left out). slack, threshold >= 0.
  static double apart_limit(double threshold, double slack) {
    return (threshold + slack) * (1 + 1e-12);
  }
  // Per cell a, a bound of M_ab over all its ring partners b (prox_detail::ring_motion_bounds).
  const double* ring_bounds(MotionBounds& m) {
    if (!m.ring_valid) compute_ring_bounds(m);
    return m.ring.data();
  }
  void compute_ring_bounds(MotionBounds& m);

  void check(std::size_t n) const;
  // Displacements since the build for x (disp_, rho_); false when there is no build to
  // compare with or x is not comparable (sizes, non-finite), so the caller rebuilds.
  bool measure(std::span<const Vec<D>> x);
  // M_ab for the displacements since the build.
  double relative_motion(int a, int b) const;
  // Runs the ring pairs' odometer on to x (every S_a grows by cell a's ring bound of the move
  // since it last ran); when there is nothing to run on from (first use, non-finite positions)
  // it restarts their bounds from the cells' boxes at x and empties the fringe.
  void advance_ring(std::span<const Vec<D>> x);
  // S_a += m, settled into the cell's bounds once it outgrows their slack, so that G - S_a never
  // loses precision to a large S_a. Through the data of ring_odo_ and ring_min_ (odos, mins),
  // which a loop over every cell holds in registers.
  void run_odometer(double* odos, double* mins, int a, double m) {
    double& odo = odos[a];
    odo += m;
    if (!(odo > std::abs(mins[a] - odo))) return;
    for (int k = topo_.ring_offset[a]; k < topo_.ring_offset[a + 1]; ++k) ring_gap_[k] -= odo;
    mins[a] -= odo;
    odo = 0;
  }
  // Lists cell a for the ring pass's second loop and starts fetching its ring pairs' bounds,
  // partners and hints. The ring's data (1.8 MB of hints at 64²) outgrows the cache and the due
  // cells are far apart, so a pass that loaded them pair by pair stalled on every miss (measured
  // with the bounds and hints fetched, ABBA series of 16 runs: stepping impact 0.69-0.77 ->
  // 0.53-0.61 ms, stepping pairs 0.40-0.50 -> 0.37-0.41 ms, physics step 0.46-0.53 -> 0.45-0.47 ms).
  void mark_due(int a) {
    due_.push_back(a);
    const int begin = topo_.ring_offset[a], end = topo_.ring_offset[a + 1];
    prefetch_range(ring_gap_.data() + begin, ring_gap_.data() + end);
    prefetch_range(topo_.ring.data() + begin, topo_.ring.data() + end);
    prefetch_range(ring_hints_.data() + begin, ring_hints_.data() + end);
  }
  template <class T>
  static void prefetch_range(const T* first, const T* last) {
    if (first == last) return;
    const char* end = reinterpret_cast<const char*>(last) - 1;
    for (const char* p = reinterpret_cast<const char*>(first); p < end; p += 64) __builtin_prefetch(p);
    __builtin_prefetch(end);
  }
  // `measured`: disp_ holds the displacements from the last build to x (measure(x) succeeded),
  // so the bounds carry over to the new reference; otherwise they restart from boxes.
  void build_list(std::span<const Vec<D>> x, double margin, bool measured);
  // The step's motion (step_, step_motion_) and whether the tracked pairs (built now
  // if there were none and the motion is small) answer it; false when the caller must sweep the
  // BVH instead (after which swept boxes are in boxes_ and the refitted tree).
  bool prepare_step(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1, double thickness);

  // The gap along `axis` between cells a and b at x (a lower bound of their distance; -inf when
  // the axis is zero). Inline: one call, not two, for each of the step's thousands of re-proofs.
  double axis_bound(int a, int b, const std::array<float, D>& axis, std::span<const Vec<D>> x) const {
    return prox_detail::stored_axis_gap<D, K>(x, cells_[a], cells_[b], axis);
  }
  // Re-proves pair (a, b) at x: the gap along its axis unless it was touching, else the exact
  // distance (warm-started). Returns a lower bound of its distance now; `within` (with the
  // closest points) when that is <= delta.
  double test_pair(int a, int b, Hints& h, std::span<const Vec<D>> x, double delta, bool& within,
                   ClosestPoints<D>& cp);
  // [Fringe]
  // Relative motion of f's vertices from its snapshot to x.
  double snapshot_motion(const Fringe& f, std::span<const Vec<D>> x) const;
  void take_snapshot(Fringe& f, std::span<const Vec<D>> x) const;
  // Ring pair k = (a, b), whose bound came within delta at x: proven farther, or moved into the
  // fringe and tested there. True (with the closest points) when within delta.
  bool examine_ring(int k, int a, int b, std::span<const Vec<D>> x, double delta,
                    ClosestPoints<D>& cp);
  // Hands fringe_[i] back to its ring pair with the bound `lower` at x, and drops it.
  void evict(std::size_t i, double lower);
  // Tightens a pair's bound at x0 over a step of relative motion s: true if it may come within
  // `thickness` (`lower` in: the bound known, out: the bound at x0).
  bool step_candidate(int a, int b, Hints& h, std::span<const Vec<D>> x0, double thickness,
                      double s, double& lower);
  // The same once `lower` already holds the gap along the pair's cached axis: the separating
  // axes, only if that was not enough.
  bool step_candidate_past_axis(int a, int b, Hints& h, std::span<const Vec<D>> x0,
                                double thickness, double s, double& lower);
  // The separating axes' lower bound of the pair's distance at x, worked out until it passes
  // `enough` (or all are tried); the axis that gave it is kept for the next time.
  double axes_bound(int a, int b, Hints& h, std::span<const Vec<D>> x, double enough);
  // A ring pair re-proven with less than kStaleReach of its cell's step bounds (reach) to spare
  // asks the separating axes for kFreshReach of them: its cached axis has gone stale. Measured on
  // the crumpled cloth, the ring pairs re-proven at consecutive steps were mostly 8 to 64 reaches
  // farther than the fail-safe's thickness, yet their cached axes proved less than 2. Instructions
  // a physics step / a stepping impact query, the two read at run time (4.822 M / 2.929 M with
  // the refresh off): (1, 12) 4.639 / 2.922, (2, 8) 4.592 / 2.942, (4, 8) 4.550 / 2.970, (6, 12)
  // 4.533 / 2.996. The impact query's larger steps leave less to gain; (2, 8) costs it least.
  // Compiled in: physics 4.777 M -> 4.577 M, impact 2.911 M -> 2.938 M.
  static constexpr double kStaleReach = 2;
  static constexpr double kFreshReach = 8;

  std::vector<Cell<K>> cells_;
  int max_index_ = -1;
  CellTopology<K> topo_;
  std::vector<Box<D>> boxes_;  // nc, one per cell
  Bvh<D> bvh_;
  // Refits the tree to boxes_, and redoes the leaf masks when that rebuilt it.
  void refit_tree();
  long long mask_builds_ = -1;  // bvh_.builds() when the leaf masks were made
  // Calls f(a, b, gap), a < b, for every pair of cells that are not topological neighbours
  // (sharing a vertex or a ring pair) whose boxes' Euclidean gap may be <= margin; gap is a
  // lower bound of that gap. Topological neighbours are most of what boxes find on a mesh;
  // leaf_masks_ drops them a leaf pair at a time, and each cell is tested against a whole leaf
  // at once (leaf_gaps2).
  template <class F>
  void candidate_pairs(double margin, F&& f) const;
  // Calls f(a, b) for every ring pair whose boxes (boxes_) may be within margin.
  template <class F>
  void ring_pairs_near(double margin, F&& f) const {
    for (int a = 0; a < static_cast<int>(cells_.size()); ++a)
      for (int k = topo_.ring_offset[a]; k < topo_.ring_offset[a + 1]; ++k)
        if (!(prox_detail::box_gap<D>(boxes_[a], boxes_[topo_.ring[k]]) > margin)) f(a, topo_.ring[k]);
  }
  // Per leaf, the leaves holding topological neighbours of its cells and which of their slot
  // pairs are not (bit i·kLeafBits + j: slot i of the first against slot j of the other),
  // sorted by the other leaf. Redone when the tree is rebuilt.
  static constexpr int kLeafBits = 8;
  static_assert(Bvh<D>::kLeafSize <= kLeafBits, "leaf masks hold 8 × 8 slot pairs");
  // A byte's bits in every row of a mask; the pairs (i, j) with j > i.
  static constexpr std::uint64_t kEachRow = 0x0101010101010101ull;
  static constexpr std::uint64_t kStrictUpper = [] {
    std::uint64_t m = 0;
    for (int i = 0; i < kLeafBits; ++i)
      m |= std::uint64_t{(0xFFu << (i + 1)) & 0xFFu} << (i * kLeafBits);
    return m;
  }();
  // Bit i set when row i of a mask has a bit set: each row folded onto its lowest bit, and those
  // eight bits gathered into the top byte by one multiplication (no two products meet).
  static unsigned nonzero_rows(std::uint64_t m) {
    m |= m >> 4;
    m |= m >> 2;
    m |= m >> 1;
    return static_cast<unsigned>(((m & kEachRow) * 0x0102040810204080ull) >> 56);
  }
  struct LeafMask {
    int other = 0;
    std::uint64_t allowed = ~std::uint64_t{0};
  };
  void build_leaf_masks();
  std::vector<int> leaf_mask_offset_;
  std::vector<LeafMask> leaf_masks_;

  bool coherent_ = true;
  double skin_ = kDefaultSkin;
  double radius_ = -1;             // every unlisted pair was farther than this at the build (< 0: none)
  std::vector<Tracked> listed_;    // sorted by (a, b)
  std::vector<Tracked> unsorted_;  // scratch of the build
  std::vector<Tracked> previous_;  // scratch of the build: the list it replaces
  std::vector<int> bucket_;        // scratch of the build: counting sort by a
  // The ring pairs, in topo_.ring order (sorted by (a, b)), their fields apart so that the scan
  // reads eight bytes a pair: G = (a lower bound at some time) + S_a (then).
  std::vector<double> ring_gap_;   // G; +inf while in the fringe
  std::vector<int> ring_fringe_;   // its entry in fringe_, or -1
  std::vector<Hints> ring_hints_;
  std::vector<int> due_;           // scratch of the ring pass: the cells with a pair due
  std::vector<double> ring_min_;   // nc: smallest G of the pairs (a, ·)
  std::vector<double> ring_odo_;   // nc: S_a
  std::vector<Vec<D>> x_ring_;     // where the odometer last ran to (empty: never)
  std::vector<Vec<D>> ring_move_;  // nv: the move since, less a common centre
  MotionBounds ring_motion_;       // of ring_move_
  std::vector<Fringe> fringe_;
  std::vector<std::pair<std::uint64_t, int>> sort_keys_;  // scratch of the answers' sort
  std::vector<ProximityPair<D>> sort_scratch_;
  std::vector<Vec<D>> x_built_;    // positions at the build
  std::vector<Vec<D>> x_measured_;  // positions disp_ and rho_ were measured at (empty: none)
  std::vector<Vec<D>> disp_;       // nv: displacement since the build, less a common centre
  double rho_ = 0;                 // every |disp_| is <= rho_ (so every M_ab <= 2 rho_)
  std::vector<Vec<D>> step_;       // nv: motion of the current step, less a common centre
  MotionBounds step_motion_;       // of step_
  bool ring_bounds_wanted_ = false;  // the last step's ring pass needed step_motion_'s ring bounds
  long long broad_phase_runs_ = 0;
  long long bounds_tightened_ = 0;
  long long exact_tests_ = 0;
};


template <int D, int K>
template <class F>
void SelfProximity<D, K>::candidate_pairs(double margin, F&& f) const {
  const double m2 = margin * margin * (1 + 1e-6);
  float r2 = static_cast<float>(m2);
  if (static_cast<double>(r2) < m2) r2 = std::nextafter(r2, std::numeric_limits<float>::infinity());
  if (!(margin >= 0)) r2 = std::numeric_limits<float>::infinity();  // NaN: everything is near
  bvh_.self_leaf_pairs(margin, [&](int la, int lb) {
    std::uint64_t allowed = ~std::uint64_t{0};
    // lb's entry among la's (sorted by other): a binary search whose steps depend only on the
    // count, so that they compile to conditional moves (std::lower_bound's branches mispredict).
    const LeafMask* e = leaf_masks_.data() + leaf_mask_offset_[la];
    int n = leaf_mask_offset_[la + 1] - leaf_mask_offset_[la];
    if (n > 0) {
      for (; n > 1; n -= n / 2) e = e[n / 2 - 1].other < lb ? e + n / 2 : e;
      if (e->other == lb) allowed = e->allowed;
    }
    if (allowed == 0) return;
    const int fa = bvh_.leaf_first(la), ca = bvh_.leaf_size(la);
    const int fb = bvh_.leaf_first(lb), cb = bvh_.leaf_size(lb);
    // The slot pairs to test, all rows at once: lb's lanes only, and within one leaf j > i only.
    allowed &= kEachRow * ((1u << cb) - 1);
    if (la == lb) allowed &= kStrictUpper;
    // The rows with a pair left that are near lb's box at all (those tested together).
    unsigned rows = nonzero_rows(allowed) & ((1u << ca) - 1);
    if (rows != 0 && la != lb) rows &= bvh_.leaf_rows_near(la, lb, r2);
    for (; rows != 0; rows &= rows - 1) {
      const int i = __builtin_ctz(rows);
      unsigned row = static_cast<unsigned>(allowed >> (i * kLeafBits)) & 0xFFu;
      float g2[Bvh<D>::kLeafSize];
      row &= bvh_.leaf_gaps2(fa + i, lb, r2, g2);
      const int p = bvh_.id(fa + i);
      for (; row != 0; row &= row - 1) {
        const int j = __builtin_ctz(row);
        const int q = bvh_.id(fb + j);
        f(std::min(p, q), std::max(p, q), std::sqrt(static_cast<double>(g2[j])));
      }
    }
  });
}

template <int D, int K>
template <class F>
void SelfProximity<D, K>::step_candidates(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1,
                                          double thickness, F&& f) {
  using prox_detail::max_relative;
  const double th = thickness > 0 ? thickness : 0.0;
  if (!prepare_step(x0, x1, th)) {
    // Swept boxes: the tree for the other pairs, the boxes themselves for the ring pairs.
    candidate_pairs(th, [&](int a, int b, double) { f(a, b); });
    ring_pairs_near(th, f);
    return;
  }
  advance_ring(x0);
  // Over the step, the relative motion grows by at most S_ab, that of the step.
  for (Fringe& e : fringe_) {
    const double s = max_relative<D, K>(step_, cells_[e.a], cells_[e.b]);
    double lower = e.lower - snapshot_motion(e, x0);
    if (lower - s > th) continue;
    if (step_candidate(e.a, e.b, e.hints, x0, th, s, lower)) f(e.a, e.b);
    take_snapshot(e, x0);
    e.lower = lower;
  }
  const double coarse = 2 * (rho_ + step_motion_.rho);
  const double listed_limit = apart_limit(th, coarse);
  for (Tracked& p : listed_) {
    if (p.gap > listed_limit) continue;
    const double m0 = relative_motion(p.a, p.b);
    double lower = p.gap - m0;
    if (lower - 2 * step_motion_.rho > th) continue;  // the step's own motion is not needed
    const double s = max_relative<D, K>(step_, cells_[p.a], cells_[p.b]);
    if (lower - s > th) continue;
    if (step_candidate(p.a, p.b, p.hints, x0, th, s, lower)) f(p.a, p.b);
    p.gap = std::max(p.gap, lower - m0);
  }
  // The ring's odometer runs on to x1 with the step's own bounds: the next step starts where this
  // one ends (unless its fail-safe stopped vertices) and finds nothing to measure.
  const double step_coarse = 2 * step_motion_.rho;
  // The step's ring bounds, once a cell needs them; from the start when the last step needed
  // them, so that every cell's odometer runs on by its own bound, not by the coarse one, which
  // would use its slack up several times as fast (measured on the crumpled cloth: 2ρ is about 7 ×
  // a cell's bound) and bring it due all the sooner.
  const double* ring = ring_bounds_wanted_ && step_coarse > 0 ? ring_bounds(step_motion_) : nullptr;
  // Raw pointers for the scan of every cell: through the vectors, each call below would make the
  // compiler reload their data.
  const int nc = static_cast<int>(cells_.size());
  const int* ring_offset = topo_.ring_offset.data();
  const int* partner = topo_.ring.data();
  double* odos = ring_odo_.data();
  double* mins = ring_min_.data();
  double* gaps = ring_gap_.data();  // +inf in the fringe
  due_.clear();
  for (int a = 0; a < nc; ++a) {
    const double odo = odos[a];
    double reach = ring ? std::min(step_coarse, ring[a]) : step_coarse;
    // A pair may come within th unless gap - odo - reach > th.
    double limit = apart_limit(th, odo + reach);
    if (mins[a] > limit) {
      run_odometer(odos, mins, a, reach);
      continue;
    }
    // Apart from the test above, which is all most cells pay: folding the two tests into one
    // costs 21 k instructions a physics step (measured).
    if (!ring) {
      ring = ring_bounds(step_motion_);
      reach = std::min(step_coarse, ring[a]);
      limit = apart_limit(th, odo + reach);
      if (mins[a] > limit) {
        run_odometer(odos, mins, a, reach);
        continue;
      }
    }
    mark_due(a);
  }
  // The first due cell made the loop above work out the ring bounds: `ring` is set here.
  for (const int a : due_) {
    const double odo = odos[a];
    const double reach = std::min(step_coarse, ring[a]);
    const double limit = apart_limit(th, odo + reach);
    double lowest = std::numeric_limits<double>::infinity();
    for (int k = ring_offset[a], end = ring_offset[a + 1]; k < end; ++k) {
      double gap = gaps[k];
      if (!(gap > limit)) {
        const int b = partner[k];
        // Its cached axis first, even when its own motion would settle it: the axis usually
        // proves the pair far enough apart for many steps. Most are settled against the cell's
        // bound (reach >= the pair's own motion s), without working out s (measured: physics
        // step -2%, stepping impact -1.7%, though the pairs so settled keep less slack).
        ++bounds_tightened_;
        Hints& h = ring_hints_[k];
        double lower = std::max(gap - odo, axis_bound(a, b, h.axis, x0));
        double s = reach;
        if (!(lower - reach > th)) s = max_relative<D, K>(step_, cells_[a], cells_[b]);
        // Within th, or soon due again: the separating axes (see kStaleReach).
        if (!(lower - s - th > kStaleReach * reach)) {
          // Past the need as in step_candidate (twice th + s), or by kFreshReach reaches.
          const double enough = th + s + std::max(th + s, kFreshReach * reach);
          lower = std::max(lower, axes_bound(a, b, h, x0, enough));
          if (!(lower - s > th)) f(a, b);
        }
        // At x1 the pair is at least lower - s apart, and the odometer will have run on by reach
        // (>= s): the pair keeps what its own motion did not use, or it would stay due.
        gap = std::max(gap, lower - s + odo + reach);
        gaps[k] = gap;
      }
      lowest = std::min(lowest, gap);
    }
    mins[a] = lowest;
    run_odometer(odos, mins, a, reach);
  }
  ring_bounds_wanted_ = ring != nullptr;
  x_ring_.assign(x1.begin(), x1.end());
}

}  // namespace s4d
