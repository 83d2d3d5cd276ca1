// Self-proximity of one mesh: leaf masks of topological neighbours, the list, the ring and the
// fringe (see self_proximity.hpp for why each bound holds), and the cold fall-backs.
// Sections: [SECTION] Broad phase, [SECTION] Motion since the build, [SECTION] Testing a pair,
// [SECTION] Queries
#include "proximity/self_proximity.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace s4d {

using namespace prox_detail;

namespace {

// A ring pair whose bound fails joins the fringe unless it is proven farther than kPromoteMargins
// margins; beyond kEvictMargins it goes back to the ring's cheaper bound (the gap between the two
// keeps pairs from going back and forth).
constexpr double kPromoteMargins = 1.5;
constexpr double kEvictMargins = 2.0;

// Whether x holds the very positions of `then`: bit for bit, which memcmp tests far faster than
// comparing coordinates. Only a -0 against a +0 differs from ==, and it costs a recomputation;
// a NaN is never kept where this is asked (see measure and advance_ring).
template <int D>
bool same_bits(std::span<const Vec<D>> x, const std::vector<Vec<D>>& then) {
  return x.size() == then.size() && std::memcmp(x.data(), then.data(), x.size_bytes()) == 0;
}

}  // namespace

template <int D, int K>
SelfProximity<D, K>::SelfProximity(std::vector<Cell<K>> cells)
    : cells_(std::move(cells)), max_index_(max_index<K>(cells_)), topo_(cells_, max_index_ + 1) {
  ring_gap_.assign(topo_.ring.size(), 0.0);
  ring_fringe_.assign(topo_.ring.size(), -1);
  ring_hints_.assign(topo_.ring.size(), {});
  ring_min_.assign(cells_.size(), 0.0);
  ring_odo_.assign(cells_.size(), 0.0);
}

template <int D, int K>
void SelfProximity<D, K>::check(std::size_t n) const {
  check_size(n, max_index_, "the position array");
}

template <int D, int K>
void SelfProximity<D, K>::set_temporal_coherence(bool on) {
  coherent_ = on;
  if (!on) radius_ = -1;
}

template <int D, int K>
void SelfProximity<D, K>::set_skin(double skin) {
  skin_ = std::clamp(skin, 0.0, 8.0);  // NaN stays NaN: clamp it too
  if (!(skin_ >= 0)) skin_ = kDefaultSkin;
  radius_ = -1;
}

// [SECTION] Broad phase: tree, leaf masks, list builds

template <int D, int K>
void SelfProximity<D, K>::refit_tree() {
  bvh_.refit(boxes_);
  if (mask_builds_ == bvh_.builds()) return;
  mask_builds_ = bvh_.builds();
  build_leaf_masks();
}

template <int D, int K>
void SelfProximity<D, K>::build_leaf_masks() {
  const int nc = static_cast<int>(cells_.size());
  const int nl = bvh_.leaf_count();
  std::vector<int> slot_of(nc), leaf_of_slot(nc);
  for (int k = 0; k < nc; ++k) slot_of[bvh_.id(k)] = k;
  for (int l = 0; l < nl; ++l)
    for (int k = bvh_.leaf_first(l); k < bvh_.leaf_first(l) + bvh_.leaf_size(l); ++k) leaf_of_slot[k] = l;
  leaf_mask_offset_.assign(1, 0);
  leaf_masks_.clear();
  // Per leaf, the other leaves met (a stamp array gives each its entry without a search).
  std::vector<int> entry_of(nl, -1);
  for (int leaf = 0; leaf < nl; ++leaf) {
    const int first = bvh_.leaf_first(leaf);
    const std::size_t begin = leaf_masks_.size();
    for (int k = first; k < first + bvh_.leaf_size(leaf); ++k)
      topo_.for_each_topological_neighbour(cells_[bvh_.id(k)], [&](int cell) {
        const int s = slot_of[cell];
        const int other = leaf_of_slot[s];
        if (entry_of[other] < static_cast<int>(begin)) {
          entry_of[other] = static_cast<int>(leaf_masks_.size());
          leaf_masks_.push_back({other, 0});
        }
        leaf_masks_[entry_of[other]].allowed |=
            std::uint64_t{1} << ((k - first) * kLeafBits + (s - bvh_.leaf_first(other)));
      });
    for (std::size_t e = begin; e < leaf_masks_.size(); ++e)
      leaf_masks_[e].allowed = ~leaf_masks_[e].allowed;  // shared bits → allowed bits
    std::sort(leaf_masks_.begin() + static_cast<std::ptrdiff_t>(begin), leaf_masks_.end(),
              [](const LeafMask& p, const LeafMask& q) { return p.other < q.other; });
    leaf_mask_offset_.push_back(static_cast<int>(leaf_masks_.size()));
  }
}

template <int D, int K>
void SelfProximity<D, K>::build_list(std::span<const Vec<D>> x, double margin, bool measured) {
  ++broad_phase_runs_;
  radius_ = margin * (1 + skin_);
  static_boxes<D, K>(x, cells_, boxes_);
  refit_tree();
  unsorted_.clear();
  // Room for four pairs a cell from the start, and doubling beyond: lists of a moving mesh vary a
  // little from build to build, and a warmed-up physics step should not allocate.
  if (unsorted_.capacity() == 0) unsorted_.reserve(4 * cells_.size());
  // The list keeps the Euclidean gap of the cells' boxes, the cheapest true bound: tighter
  // bounds are worked out lazily, by the queries, for the pairs that come near their margin.
  candidate_pairs(radius_, [&](int a, int b, double gap) { unsorted_.push_back({a, b, gap, {}}); });
  // Counting sort by a, then b within each a (a handful): linear, unlike a comparison sort.
  bucket_.assign(cells_.size() + 1, 0);
  for (const Tracked& p : unsorted_) ++bucket_[p.a + 1];
  for (std::size_t c = 1; c < bucket_.size(); ++c) bucket_[c] += bucket_[c - 1];
  // The old list (sorted too) hands its bounds and hints on to the pairs that stay, converted to
  // the new reference: a bound loses 2 rho, which holds every M_ab of the displacements since.
  listed_.swap(previous_);
  if (!measured) previous_.clear();
  if (listed_.capacity() < unsorted_.size()) listed_.reserve(unsorted_.capacity());
  listed_.resize(unsorted_.size());
  for (const Tracked& p : unsorted_) listed_[bucket_[p.a]++] = p;
  auto old = previous_.cbegin();
  for (std::size_t c = 0, begin = 0; c < cells_.size(); ++c) {
    const std::size_t end = static_cast<std::size_t>(bucket_[c]);
    std::sort(listed_.begin() + static_cast<std::ptrdiff_t>(begin),
              listed_.begin() + static_cast<std::ptrdiff_t>(end),
              [](const Tracked& p, const Tracked& q) { return p.b < q.b; });
    for (std::size_t k = begin; k < end; ++k) {
      Tracked& p = listed_[k];
      while (old != previous_.cend() && (old->a < p.a || (old->a == p.a && old->b < p.b))) ++old;
      if (old == previous_.cend() || old->a != p.a || old->b != p.b) continue;
      p.hints = old->hints;
      // The coarse carry-over only: the pair's own motion (relative_motion) would keep more of
      // the old bound, but costs more than the re-proofs it saves (measured, instructions: physics
      // step 4.831 M with it, 4.775 M without; stepping pairs 3.032 M / 2.980 M; impact 2.963 M
      // / 2.911 M).
      p.gap = std::max(p.gap, old->gap - 2 * rho_);
    }
    begin = end;
  }
  x_built_.assign(x.begin(), x.end());
  x_measured_ = x_built_;
  disp_.assign(x.size(), Vec<D>::Zero());
  rho_ = 0;
}

// [SECTION] Motion since the build

template <int D, int K>
void SelfProximity<D, K>::compute_ring_bounds(MotionBounds& m) {
  // Worked out for every cell at once (each edge once): asked for one cell, a query asks for a
  // good share of them (measured: a lazy cell-by-cell version cost more on both benchmarks).
  ring_motion_bounds<D, K>(m.u->data(), topo_, cells_, m.edge_max, m.around, m.ring);
  m.ring_valid = true;
}

template <int D, int K>
bool SelfProximity<D, K>::measure(std::span<const Vec<D>> x) {
  if (!coherent_ || radius_ < 0 || x_built_.size() != x.size()) {
    rho_ = std::numeric_limits<double>::infinity();
    return false;
  }
  // A physics step asks for its pairs and then for its step from the same positions.
  if (same_bits<D>(x, x_measured_)) return true;
  rho_ = centred_difference<D>(x, x_built_, disp_);
  if (!std::isfinite(rho_)) {  // a non-finite vertex: rebuild (its box is all space)
    x_measured_.clear();
    return false;
  }
  x_measured_.assign(x.begin(), x.end());
  return true;
}

template <int D, int K>
double SelfProximity<D, K>::relative_motion(int a, int b) const {
  return max_relative<D, K>(disp_, cells_[a], cells_[b]);
}

template <int D, int K>
void SelfProximity<D, K>::advance_ring(std::span<const Vec<D>> x) {
  const int nc = static_cast<int>(cells_.size());
  if (x_ring_.size() == x.size()) {
    if (same_bits<D>(x, x_ring_)) return;  // where it stopped (a step's x1)
    const double rho = centred_difference<D>(x, x_ring_, ring_move_);
    if (std::isfinite(rho)) {
      ring_motion_.reset(&ring_move_, rho);
      const double* ring = ring_bounds(ring_motion_);
      double* odos = ring_odo_.data();
      double* mins = ring_min_.data();
      for (int a = 0; a < nc; ++a) run_odometer(odos, mins, a, std::min(2 * rho, ring[a]));
      x_ring_.assign(x.begin(), x.end());
      return;
    }
  }
  // Nothing to run on from (first use, or non-finite positions now or then): every bound
  // restarts from the boxes at x (a cell with a non-finite vertex has all space for its box).
  for (const Fringe& f : fringe_) ring_fringe_[f.ring] = -1;
  fringe_.clear();
  static_boxes<D, K>(x, cells_, boxes_);
  for (int a = 0; a < nc; ++a) {
    double lowest = std::numeric_limits<double>::infinity();
    for (int k = topo_.ring_offset[a]; k < topo_.ring_offset[a + 1]; ++k) {
      ring_gap_[k] = box_gap<D>(boxes_[a], boxes_[topo_.ring[k]]);
      ring_hints_[k] = {};
      lowest = std::min(lowest, ring_gap_[k]);
    }
    ring_min_[a] = lowest;
    ring_odo_[a] = 0;
  }
  // Non-finite positions are not a place to run on from: the next call restarts again.
  if (all_finite<D>(x))
    x_ring_.assign(x.begin(), x.end());
  else
    x_ring_.clear();
}

// [SECTION] Testing a pair, and the fringe

namespace {
template <int D>
void store_axis(const Vec<D>& n, std::array<float, D>& axis) {
  const double len = n.norm();
  if (!(len > 0) || !std::isfinite(len)) return;
  for (int k = 0; k < D; ++k) axis[k] = static_cast<float>(n[k] / len);
}
}  // namespace

template <int D, int K>
double SelfProximity<D, K>::test_pair(int a, int b, Hints& h, std::span<const Vec<D>> x,
                                      double delta, bool& within, ClosestPoints<D>& cp) {
  within = false;
  // A pair last found within delta (resting contact) almost never proves farther now: go
  // straight to the exact distance. Others first try the gap along their axis.
  if (!h.touching) {
    ++bounds_tightened_;
    const double lower = axis_bound(a, b, h.axis, x);
    if (lower > delta) return lower;
  }
  ++exact_tests_;
  unsigned faces = h.faces;
  cp = closest_points_warm<D, K, K>(gather<D, K>(x, cells_[a]), gather<D, K>(x, cells_[b]), faces);
  h.faces = static_cast<std::uint8_t>(faces);
  h.touching = within = cp.distance <= delta;
  store_axis<D>(Vec<D>(cp.p - cp.q), h.axis);
  return cp.distance == cp.distance ? cp.distance : -std::numeric_limits<double>::infinity();
}

template <int D, int K>
double SelfProximity<D, K>::snapshot_motion(const Fringe& f, std::span<const Vec<D>> x) const {
  return motion_since_snapshot<D, K>(x, cells_[f.a], cells_[f.b], f.x0);
}

template <int D, int K>
void SelfProximity<D, K>::take_snapshot(Fringe& f, std::span<const Vec<D>> x) const {
  for (int i = 0; i < K; ++i) {
    f.x0[i] = x[cells_[f.a][i]];
    f.x0[K + i] = x[cells_[f.b][i]];
  }
}

template <int D, int K>
bool SelfProximity<D, K>::examine_ring(int k, int a, int b, std::span<const Vec<D>> x,
                                       double delta, ClosestPoints<D>& cp) {
  // The separating axes first (the cached one, then all): most pairs the odometer lets through
  // are still well apart (its per-cell strain bound outruns their own motion), and stay out of
  // the fringe.
  ++bounds_tightened_;
  Hints& h = ring_hints_[k];
  double lower = axis_bound(a, b, h.axis, x);
  if (!(lower > kPromoteMargins * delta))
    lower = std::max(lower, axes_bound(a, b, h, x, kEvictMargins * delta));
  if (lower > kPromoteMargins * delta) {
    ring_gap_[k] = std::max(ring_gap_[k], lower + ring_odo_[a]);
    return false;
  }
  ring_fringe_[k] = static_cast<int>(fringe_.size());
  ring_gap_[k] = std::numeric_limits<double>::infinity();
  Fringe& f = fringe_.emplace_back();
  f.a = a;
  f.b = b;
  f.ring = k;
  f.hints = h;
  take_snapshot(f, x);
  f.lower = lower;
  if (lower > delta) return false;
  bool within = false;
  f.lower = std::max(lower, test_pair(a, b, f.hints, x, delta, within, cp));
  return within;
}

template <int D, int K>
void SelfProximity<D, K>::evict(std::size_t i, double lower) {
  const Fringe& f = fringe_[i];
  ring_gap_[f.ring] = lower + ring_odo_[f.a];
  ring_min_[f.a] = std::min(ring_min_[f.a], ring_gap_[f.ring]);
  ring_hints_[f.ring] = f.hints;
  ring_fringe_[f.ring] = -1;
  if (i + 1 != fringe_.size()) {
    fringe_[i] = fringe_.back();
    ring_fringe_[fringe_[i].ring] = static_cast<int>(i);
  }
  fringe_.pop_back();
}

// [SECTION] Queries

template <int D, int K>
void SelfProximity<D, K>::pairs_within(std::span<const Vec<D>> x, double delta,
                                       std::vector<ProximityPair<D>>& out, RingPairs ring) {
  out.clear();
  check(x.size());
  if (std::isnan(delta)) throw Error("proximity: the distance of a pairs query is not a number");
  if (delta < 0) return;  // no distance is negative
  const bool with_ring = ring == RingPairs::kInclude;
  if (!coherent_) {
    ++broad_phase_runs_;
    static_boxes<D, K>(x, cells_, boxes_);
    refit_tree();
    candidate_pairs(delta, [&](int a, int b, double) {
      narrow_within<D, K, K>(gather<D, K>(x, cells_[a]), gather<D, K>(x, cells_[b]), a, b, delta, out);
    });
    if (with_ring)
      ring_pairs_near(delta, [&](int a, int b) {
        narrow_within<D, K, K>(gather<D, K>(x, cells_[a]), gather<D, K>(x, cells_[b]), a, b, delta, out);
      });
    sort_pairs(out, sort_keys_, sort_scratch_);
    return;
  }
  const bool measured = measure(x);
  if (!(measured && radius_ - 2 * rho_ >= delta)) build_list(x, delta, measured);
  ClosestPoints<D> cp;
  bool within = false;
  const double listed_limit = apart_limit(delta, 2 * rho_);
  for (Tracked& p : listed_) {
    if (p.gap > listed_limit) continue;
    const double m = relative_motion(p.a, p.b);
    if (p.gap - m > delta) continue;
    p.gap = std::max(p.gap, test_pair(p.a, p.b, p.hints, x, delta, within, cp) - m);
    if (within) out.push_back({p.a, p.b, cp});
  }
  if (with_ring) {
    // The list's answers are sorted; the ring's go after them, and the whole is sorted below.
    advance_ring(x);
    for (std::size_t i = 0; i < fringe_.size();) {
      Fringe& f = fringe_[i];
      const double lower = f.lower - snapshot_motion(f, x);
      if (lower > delta) {
        if (lower > kEvictMargins * delta) {
          evict(i, lower);
          continue;  // another entry moved into i
        }
      } else {
        f.lower = test_pair(f.a, f.b, f.hints, x, delta, within, cp);
        take_snapshot(f, x);
        if (within) out.push_back({f.a, f.b, cp});
      }
      ++i;
    }
    due_.clear();
    for (int a = 0; a < static_cast<int>(cells_.size()); ++a) {
      if (ring_min_[a] > apart_limit(delta, ring_odo_[a])) continue;
      mark_due(a);
    }
    for (const int a : due_) {
      const double limit = apart_limit(delta, ring_odo_[a]);
      double lowest = std::numeric_limits<double>::infinity();
      for (int k = topo_.ring_offset[a]; k < topo_.ring_offset[a + 1]; ++k) {
        // Never in the fringe (+inf).
        if (!(ring_gap_[k] > limit) && examine_ring(k, a, topo_.ring[k], x, delta, cp))
          out.push_back({a, topo_.ring[k], cp});
        lowest = std::min(lowest, ring_gap_[k]);
      }
      ring_min_[a] = lowest;
    }
  }
  sort_pairs(out, sort_keys_, sort_scratch_);
}

template <int D, int K>
bool SelfProximity<D, K>::step_candidate(int a, int b, Hints& h, std::span<const Vec<D>> x0,
                                         double thickness, double s, double& lower) {
  // Tighten the bound at x0 before handing the pair out: a pair that only looked close (its
  // bound was the gap of boxes) is then left out of this step and of the next few. The axes are
  // asked for a bound past the need, and the best one is kept for the next time. Measured
  // (instructions a step): physics_bench's crumpled cloth 11.55 M at 1.5 ×, 11.25 M at 2 ×, 10.99 M
  // at 3 ×; the stepping impact of proximity_bench 5.89 M, 5.87 M, 6.37 M (asking more than a
  // close pair's distance runs every axis).
  ++bounds_tightened_;
  lower = std::max(lower, axis_bound(a, b, h.axis, x0));
  return step_candidate_past_axis(a, b, h, x0, thickness, s, lower);
}

template <int D, int K>
bool SelfProximity<D, K>::step_candidate_past_axis(int a, int b, Hints& h,
                                                   std::span<const Vec<D>> x0, double thickness,
                                                   double s, double& lower) {
  if (!(lower - s > thickness)) lower = std::max(lower, axes_bound(a, b, h, x0, 2 * (thickness + s)));
  return !(lower - s > thickness);  // NaN: a candidate
}

template <int D, int K>
double SelfProximity<D, K>::axes_bound(int a, int b, Hints& h, std::span<const Vec<D>> x,
                                       double enough) {
  Vec<D> best = Vec<D>::Zero();
  const double lower = distance_lower_bound<D, K, K>(gather<D, K>(x, cells_[a]),
                                                     gather<D, K>(x, cells_[b]), enough, &best);
  store_axis<D>(best, h.axis);
  return lower;
}

template <int D, int K>
bool SelfProximity<D, K>::prepare_step(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1,
                                       double thickness) {
  check(x0.size());
  check(x1.size());
  const double step_rho = centred_difference<D>(x1, x0, step_);
  step_motion_.reset(&step_, step_rho);
  if (coherent_ && std::isfinite(step_rho)) {
    const bool have = measure(x0);
    bool listed = have && radius_ - 2 * rho_ - 2 * step_rho >= thickness;
    // A list for this step's motion pays off when the motion is small next to the thickness;
    // a few fast cells would inflate it for every cell, and then the swept tree is better.
    if (!listed && 2 * step_rho <= thickness) {
      build_list(x0, thickness + 2 * step_rho, have);
      listed = true;
    }
    if (listed) return true;
  }
  ++broad_phase_runs_;
  swept_boxes<D, K>(x0, x1, cells_, boxes_);
  refit_tree();
  return false;
}

template <int D, int K>
Impact<D> SelfProximity<D, K>::earliest_impact(std::span<const Vec<D>> x0,
                                               std::span<const Vec<D>> x1, const CcdOptions& opt) {
  Impact<D> best;
  step_candidates(x0, x1, opt.thickness, [&](int a, int b) {
    narrow_impact<D, K, K>(gather<D, K>(x0, cells_[a]), gather<D, K>(x1, cells_[a]),
                           gather<D, K>(x0, cells_[b]), gather<D, K>(x1, cells_[b]), a, b, opt,
                           best);
  });
  return best;
}

#define S4D_INSTANTIATE(D)            \
  template class SelfProximity<D, 2>; \
  template class SelfProximity<D, 3>;
S4D_INSTANTIATE(2)
S4D_INSTANTIATE(3)
S4D_INSTANTIATE(4)
#undef S4D_INSTANTIATE

}  // namespace s4d
