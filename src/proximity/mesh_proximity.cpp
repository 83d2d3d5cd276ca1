// Whole-mesh proximity and continuous collision: BVH candidates, cheap separating-axis rejection
// (separating_axes.hpp), then the exact kernels of closest_points.hpp / continuous_collision.hpp.
#include "proximity/mesh_proximity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "proximity/separating_axes.hpp"

namespace s4d {

namespace {

template <int K>
int max_index(const std::vector<Cell<K>>& cells) {
  int m = -1;
  for (const auto& c : cells)
    for (int v : c) {
      if (v < 0) throw Error("proximity: cell with negative vertex index " + std::to_string(v));
      m = std::max(m, v);
    }
  return m;
}

void check_size(std::size_t n, int max_index, const char* what) {
  if (max_index >= 0 && n <= static_cast<std::size_t>(max_index))
    throw Error(std::string("proximity: ") + what + " has " + std::to_string(n) +
                " vertices but the cells use index " + std::to_string(max_index));
}

template <int D, int K>
Simplex<D, K> gather(std::span<const Vec<D>> x, const Cell<K>& c) {
  Simplex<D, K> s;
  for (int i = 0; i < K; ++i) s[i] = x[c[i]];
  return s;
}

// A cell with a non-finite vertex gets the whole space as its box: it stays a candidate with
// every other cell, and the exact kernels (NaN distance, contact at once) decide what it means.
template <int D>
void add_point(Box<D>& b, const Vec<D>& p) {
  if (p.allFinite()) {
    b.add(p);
  } else {
    b.lo.setConstant(-std::numeric_limits<double>::infinity());
    b.hi.setConstant(std::numeric_limits<double>::infinity());
  }
}

template <int D, int K>
void static_boxes(std::span<const Vec<D>> x, const std::vector<Cell<K>>& cells,
                  std::vector<Box<D>>& boxes) {
  boxes.resize(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    Box<D> b;
    for (int v : cells[i]) add_point<D>(b, x[v]);
    boxes[i] = b;
  }
}

template <int D, int K>
void swept_boxes(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1,
                 const std::vector<Cell<K>>& cells, std::vector<Box<D>>& boxes) {
  boxes.resize(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    Box<D> b;
    for (int v : cells[i]) {
      add_point<D>(b, x0[v]);
      add_point<D>(b, x1[v]);
    }
    boxes[i] = b;
  }
}

template <int D, int KA, int KB>
void narrow_within(const Simplex<D, KA>& sa, const Simplex<D, KB>& sb, int a, int b, double delta,
                   std::vector<ProximityPair<D>>& out) {
  if (provably_farther<D, KA, KB>(sa, sb, delta)) return;
  const ClosestPoints<D> cp = closest_points<D, KA, KB>(sa, sb);
  if (cp.distance <= delta) out.push_back({a, b, cp});
}

// Continuous test of one candidate pair against the best impact so far.
template <int D, int KA, int KB>
void narrow_impact(const Simplex<D, KA>& a0, const Simplex<D, KA>& a1, const Simplex<D, KB>& b0,
                   const Simplex<D, KB>& b1, int a, int b, const CcdOptions& opt, Impact<D>& best) {
  const double t_max = best.hit ? best.t : opt.t_max;
  // Cheap exclusion: the swept vertex sets stay apart along some axis over [0, t_max].
  if (provably_apart_over_step<D, KA, KB>(a0, a1, b0, b1, t_max, opt.thickness)) return;
  CcdOptions o = opt;
  o.t_max = t_max;
  ++best.narrow_tests;
  const CcdResult<D> r = earliest_contact<D, KA, KB>(a0, a1, b0, b1, o);
  if (r.hit && (!best.hit || r.t < best.t || (r.t == best.t && std::pair(a, b) < std::pair(best.a, best.b)))) {
    best.hit = true;
    best.t = r.t;
    best.a = a;
    best.b = b;
    best.at_t = r.at_t;
  }
}

template <int D>
void sort_pairs(std::vector<ProximityPair<D>>& out) {
  std::sort(out.begin(), out.end(), [](const ProximityPair<D>& x, const ProximityPair<D>& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
}

}  // namespace

// [SECTION] SelfProximity

template <int D, int K>
SelfProximity<D, K>::SelfProximity(std::vector<Cell<K>> cells) : cells_(std::move(cells)) {
  max_index_ = max_index<K>(cells_);
}

template <int D, int K>
void SelfProximity<D, K>::check(std::size_t n) const {
  check_size(n, max_index_, "the position array");
}

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
  if (around_offset_.empty()) {
    around_offset_.assign(max_index_ + 2, 0);
    for (const auto& c : cells_)
      for (int v : c) ++around_offset_[v + 1];
    for (std::size_t v = 1; v < around_offset_.size(); ++v) around_offset_[v] += around_offset_[v - 1];
    around_.resize(around_offset_.back());
    std::vector<int> fill(around_offset_.begin(), around_offset_.end() - 1);
    for (int c = 0; c < nc; ++c)
      for (int v : cells_[c]) around_[fill[v]++] = c;
  }
  leaf_of_slot_.resize(nc);
  leaf_first_.clear();
  bvh_.for_each_leaf([&](int first, int count) {
    for (int k = first; k < first + count; ++k) leaf_of_slot_[k] = static_cast<int>(leaf_first_.size());
    leaf_first_.push_back(first);
  });
  std::vector<int> slot_of(nc);
  for (int k = 0; k < nc; ++k) slot_of[bvh_.id(k)] = k;
  leaf_mask_offset_.assign(1, 0);
  leaf_masks_.clear();
  std::vector<LeafMask> found;
  for (std::size_t leaf = 0; leaf < leaf_first_.size(); ++leaf) {
    const int first = leaf_first_[leaf];
    found.clear();
    for (int k = first; k < nc && leaf_of_slot_[k] == static_cast<int>(leaf); ++k)
      for (int v : cells_[bvh_.id(k)])
        for (int e = around_offset_[v]; e < around_offset_[v + 1]; ++e) {
          const int s = slot_of[around_[e]];
          const int other = leaf_of_slot_[s];
          found.push_back({other, 1u << ((k - first) * kLeafBits + (s - leaf_first_[other]))});
        }
    std::sort(found.begin(), found.end(),
              [](const LeafMask& p, const LeafMask& q) { return p.other < q.other; });
    for (std::size_t i = 0; i < found.size();) {
      unsigned shared = 0;
      const int other = found[i].other;
      for (; i < found.size() && found[i].other == other; ++i) shared |= found[i].allowed;
      leaf_masks_.push_back({other, ~shared & 0xFFFFu});
    }
    leaf_mask_offset_.push_back(static_cast<int>(leaf_masks_.size()));
  }
}

template <int D, int K>
void SelfProximity<D, K>::set_temporal_coherence(bool on) {
  coherent_ = on;
  if (!on) radius_ = -1;
}

template <int D, int K>
void SelfProximity<D, K>::set_skin(double skin) {
  skin_ = std::clamp(skin, 0.0, 8.0);  // NaN stays NaN: clamp it too
  if (!(skin_ >= 0)) skin_ = 1.0;
  radius_ = -1;
}

template <int D, int K>
bool SelfProximity<D, K>::advance(std::span<const Vec<D>> x) {
  if (!coherent_ || radius_ < 0 || x_seen_.size() != x.size()) return false;
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < x.size(); ++v) {
    const double d = (x[v] - x_seen_[v]).norm();
    vertex_move_[v] = d >= 0 ? d : inf;  // NaN moves without bound
    x_seen_[v] = x[v];
  }
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    double m = 0;
    for (int v : cells_[c]) m = std::max(m, vertex_move_[v]);
    moved_[c] += m;
    max_moved_ = std::max(max_moved_, moved_[c]);
  }
  return max_moved_ < inf;
}

template <int D, int K>
bool SelfProximity<D, K>::list_covers(double margin, double extra) const {
  return radius_ >= 0 && radius_ - 2 * (max_moved_ + extra) >= margin;
}

template <int D, int K>
void SelfProximity<D, K>::build_list(std::span<const Vec<D>> x, double margin) {
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
  candidate_pairs(radius_, [&](int a, int b) {
    const Box<D>& p = boxes_[a];
    const Box<D>& q = boxes_[b];
    double g2 = 0;
    for (int k = 0; k < D; ++k) {
      const double g = std::max(q.lo[k] - p.hi[k], p.lo[k] - q.hi[k]);
      if (g > 0) g2 += g * g;
    }
    const double gap = std::sqrt(g2) * (1 - 1e-12);
    if (!(gap > radius_)) unsorted_.push_back({a, b, gap, 0, -1, false, 0});
  });
  // Counting sort by a, then b within each a (a handful): linear, unlike a comparison sort.
  bucket_.assign(cells_.size() + 1, 0);
  for (const Listed& p : unsorted_) ++bucket_[p.a + 1];
  for (std::size_t c = 1; c < bucket_.size(); ++c) bucket_[c] += bucket_[c - 1];
  if (listed_.capacity() < unsorted_.size()) listed_.reserve(unsorted_.capacity());
  listed_.resize(unsorted_.size());
  for (const Listed& p : unsorted_) listed_[bucket_[p.a]++] = p;
  for (std::size_t c = 0, begin = 0; c < cells_.size(); ++c) {
    const std::size_t end = static_cast<std::size_t>(bucket_[c]);
    std::sort(listed_.begin() + begin, listed_.begin() + end,
              [](const Listed& p, const Listed& q) { return p.b < q.b; });
    begin = end;
  }
  x_seen_.assign(x.begin(), x.end());
  vertex_move_.assign(x.size(), 0.0);
  moved_.assign(cells_.size(), 0.0);
  max_moved_ = 0;
}

template <int D, int K>
void SelfProximity<D, K>::pairs_within(std::span<const Vec<D>> x, double delta,
                                       std::vector<ProximityPair<D>>& out) {
  pairs_within(x, delta, out, nullptr);
}

template <int D, int K>
void SelfProximity<D, K>::pairs_within(std::span<const Vec<D>> x, double delta,
                                       std::vector<ProximityPair<D>>& out,
                                       const std::function<bool(int, int)>& skip) {
  out.clear();
  check(x.size());
  if (std::isnan(delta)) throw Error("proximity: the distance of a pairs query is not a number");
  if (delta < 0) return;  // no distance is negative
  if (!coherent_) {
    ++broad_phase_runs_;
    static_boxes<D, K>(x, cells_, boxes_);
    refit_tree();
    candidate_pairs(delta, [&](int a, int b) {
      if (skip && skip(a, b)) return;
      narrow_within<D, K, K>(gather<D, K>(x, cells_[a]), gather<D, K>(x, cells_[b]), a, b, delta,
                             out);
    });
    sort_pairs(out);
    return;
  }
  if (!(advance(x) && list_covers(delta, 0))) build_list(x, delta);
  for (Listed& p : listed_) {
    if (bound(p) > delta) continue;
    if (skip) {
      if (p.skipped < 0) p.skipped = skip(p.a, p.b) ? 1 : 0;
      if (p.skipped) continue;
    }
    const Simplex<D, K> sa = gather<D, K>(x, cells_[p.a]), sb = gather<D, K>(x, cells_[p.b]);
    p.moved_at = moved_[p.a] + moved_[p.b];
    // A pair last found within delta (resting contact) almost never proves farther now: go
    // straight to the exact distance. Others first try the cheap bound, aiming past delta, since a
    // bound that only just clears it is spent by the next step's motion (measured on the stepping
    // benchmark: goal 1 → 5,450 bounds a step, 1.5 → 3,400, 3 → 3,350, each costlier to reach).
    if (!(p.exact && p.gap <= delta)) {
      ++bounds_tightened_;
      const double lower = distance_lower_bound<D, K, K>(sa, sb, 1.5 * delta);
      if (lower > delta) {
        p.gap = lower;
        p.exact = false;
        continue;
      }
    }
    ++exact_tests_;
    unsigned faces = p.faces;
    const ClosestPoints<D> cp = closest_points_warm<D, K, K>(sa, sb, faces);
    p.faces = static_cast<std::uint8_t>(faces);
    p.gap = cp.distance;
    p.exact = true;
    if (cp.distance <= delta) out.push_back({p.a, p.b, cp});
  }
}

template <int D, int K>
bool SelfProximity<D, K>::prepare_step(std::span<const Vec<D>> x0, std::span<const Vec<D>> x1,
                                       double thickness) {
  check(x0.size());
  check(x1.size());
  step_.resize(cells_.size());
  double max_step = 0;
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    double m = 0;
    for (int v : cells_[c]) {
      const double d = (x1[v] - x0[v]).norm();
      m = std::max(m, d >= 0 ? d : std::numeric_limits<double>::infinity());
    }
    step_[c] = m;
    max_step = std::max(max_step, m);
  }
  if (coherent_ && std::isfinite(max_step)) {
    const bool have = advance(x0);
    if (have && list_covers(thickness, max_step)) return true;
    // A list for this step's motion pays off when the motion is small next to the thickness;
    // a few fast cells would inflate it for every cell, and then the swept tree is better.
    if (max_step <= thickness) {
      build_list(x0, thickness + 2 * max_step);
      return true;
    }
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

// [SECTION] PairProximity

template <int D, int KA, int KB>
PairProximity<D, KA, KB>::PairProximity(std::vector<Cell<KA>> cells_a, std::vector<Cell<KB>> cells_b)
    : cells_a_(std::move(cells_a)), cells_b_(std::move(cells_b)) {
  max_a_ = max_index<KA>(cells_a_);
  max_b_ = max_index<KB>(cells_b_);
}

template <int D, int KA, int KB>
void PairProximity<D, KA, KB>::pairs_within(std::span<const Vec<D>> xa, std::span<const Vec<D>> xb,
                                            double delta, std::vector<ProximityPair<D>>& out) {
  out.clear();
  check_size(xa.size(), max_a_, "the first position array");
  check_size(xb.size(), max_b_, "the second position array");
  static_boxes<D, KA>(xa, cells_a_, boxes_a_);
  static_boxes<D, KB>(xb, cells_b_, boxes_b_);
  bvh_a_.refit(boxes_a_);
  bvh_b_.refit(boxes_b_);
  bvh_a_.pairs_with(bvh_b_, delta, [&](int i, int j) {
    narrow_within<D, KA, KB>(gather<D, KA>(xa, cells_a_[i]), gather<D, KB>(xb, cells_b_[j]), i, j,
                             delta, out);
  });
  sort_pairs(out);
}

template <int D, int KA, int KB>
Impact<D> PairProximity<D, KA, KB>::earliest_impact(std::span<const Vec<D>> xa0,
                                                    std::span<const Vec<D>> xa1,
                                                    std::span<const Vec<D>> xb0,
                                                    std::span<const Vec<D>> xb1,
                                                    const CcdOptions& opt) {
  check_size(std::min(xa0.size(), xa1.size()), max_a_, "the first position array");
  check_size(std::min(xb0.size(), xb1.size()), max_b_, "the second position array");
  Impact<D> best;
  swept_boxes<D, KA>(xa0, xa1, cells_a_, boxes_a_);
  swept_boxes<D, KB>(xb0, xb1, cells_b_, boxes_b_);
  bvh_a_.refit(boxes_a_);
  bvh_b_.refit(boxes_b_);
  bvh_a_.pairs_with(bvh_b_, opt.thickness, [&](int i, int j) {
    narrow_impact<D, KA, KB>(gather<D, KA>(xa0, cells_a_[i]), gather<D, KA>(xa1, cells_a_[i]),
                             gather<D, KB>(xb0, cells_b_[j]), gather<D, KB>(xb1, cells_b_[j]), i,
                             j, opt, best);
  });
  return best;
}

template <int D, int K>
std::vector<ProximityPair<D>> intersecting_pairs(std::span<const Vec<D>> x,
                                                 const std::vector<Cell<K>>& cells,
                                                 double tolerance) {
  SelfProximity<D, K> q(cells);
  std::vector<ProximityPair<D>> out;
  q.pairs_within(x, tolerance, out);
  return out;
}

#define S4D_INSTANTIATE(D)                                                                       \
  template class SelfProximity<D, 2>;                                                            \
  template class SelfProximity<D, 3>;                                                            \
  template class PairProximity<D, 2, 2>;                                                         \
  template class PairProximity<D, 2, 3>;                                                         \
  template class PairProximity<D, 3, 2>;                                                         \
  template class PairProximity<D, 3, 3>;                                                         \
  template std::vector<ProximityPair<D>> intersecting_pairs<D, 2>(                               \
      std::span<const Vec<D>>, const std::vector<Cell<2>>&, double);                             \
  template std::vector<ProximityPair<D>> intersecting_pairs<D, 3>(                               \
      std::span<const Vec<D>>, const std::vector<Cell<3>>&, double);
S4D_INSTANTIATE(2)
S4D_INSTANTIATE(3)
S4D_INSTANTIATE(4)
#undef S4D_INSTANTIATE

}  // namespace s4d
