// Whole-mesh proximity and continuous collision: BVH candidates, cheap separating-axis rejection
// (separating_axes.hpp), then the exact kernels of closest_points.hpp / continuous_collision.hpp.
#include "proximity/mesh_proximity.hpp"

#include <algorithm>
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

template <int D, int K>
void static_boxes(std::span<const Vec<D>> x, const std::vector<Cell<K>>& cells,
                  std::vector<Box<D>>& boxes) {
  boxes.resize(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    Box<D> b;
    for (int v : cells[i]) b.add(x[v]);
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
      b.add(x0[v]);
      b.add(x1[v]);
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
void SelfProximity<D, K>::pairs_within(std::span<const Vec<D>> x, double delta,
                                       std::vector<ProximityPair<D>>& out) {
  out.clear();
  check(x.size());
  static_boxes<D, K>(x, cells_, boxes_);
  bvh_.refit(boxes_);
  bvh_.self_pairs(delta, [&](int i, int j) {
    const Cell<K>& ci = cells_[i];
    const Cell<K>& cj = cells_[j];
    if (share_vertex<K, K>(ci, cj)) return;
    const int a = std::min(i, j), b = std::max(i, j);
    narrow_within<D, K, K>(gather<D, K>(x, cells_[a]), gather<D, K>(x, cells_[b]), a, b, delta, out);
  });
  sort_pairs(out);
}

template <int D, int K>
Impact<D> SelfProximity<D, K>::earliest_impact(std::span<const Vec<D>> x0,
                                               std::span<const Vec<D>> x1, const CcdOptions& opt) {
  check(x0.size());
  check(x1.size());
  Impact<D> best;
  swept_boxes<D, K>(x0, x1, cells_, boxes_);
  bvh_.refit(boxes_);
  bvh_.self_pairs(opt.thickness, [&](int i, int j) {
    if (share_vertex<K, K>(cells_[i], cells_[j])) return;
    const int a = std::min(i, j), b = std::max(i, j);
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
