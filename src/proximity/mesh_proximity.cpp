// Two meshes against each other: BVH candidates, then the narrow phase of narrow_phase.hpp.
#include "proximity/mesh_proximity.hpp"

#include <limits>

#include "proximity/narrow_phase.hpp"
#include "proximity/smallest_within.hpp"

namespace s4d {

using namespace prox_detail;

template <int D, int KA, int KB>
PairProximity<D, KA, KB>::PairProximity(std::vector<Cell<KA>> cells_a, std::vector<Cell<KB>> cells_b)
    : cells_a_(std::move(cells_a)), cells_b_(std::move(cells_b)) {
  max_a_ = max_index<KA>(cells_a_);
  max_b_ = max_index<KB>(cells_b_);
}

template <int D, int KA, int KB>
void PairProximity<D, KA, KB>::refit_at(std::span<const Vec<D>> xa, std::span<const Vec<D>> xb) {
  check_size(xa.size(), max_a_, "the first position array");
  check_size(xb.size(), max_b_, "the second position array");
  static_boxes<D, KA>(xa, cells_a_, boxes_a_);
  static_boxes<D, KB>(xb, cells_b_, boxes_b_);
  bvh_a_.refit(boxes_a_);
  bvh_b_.refit(boxes_b_);
}

template <int D, int KA, int KB>
void PairProximity<D, KA, KB>::pairs_within(std::span<const Vec<D>> xa, std::span<const Vec<D>> xb,
                                            double delta, std::vector<ProximityPair<D>>& out) {
  out.clear();
  refit_at(xa, xb);
  bvh_a_.pairs_with(bvh_b_, delta, [&](int i, int j) {
    narrow_within<D, KA, KB>(gather<D, KA>(xa, cells_a_[i]), gather<D, KB>(xb, cells_b_[j]), i, j,
                             delta, out);
  });
  sort_pairs(out);
}

template <int D, int KA, int KB>
double PairProximity<D, KA, KB>::smallest_distance(std::span<const Vec<D>> xa, std::span<const Vec<D>> xb,
                                                   double up_to) {
  refit_at(xa, xb);
  return smallest_within(up_to, [&](double r) {
    double best = r;  // the narrow phase skips what is provably farther than the best so far
    bool found = false;
    bvh_a_.pairs_with(bvh_b_, r, [&](int i, int j) {
      const Simplex<D, KA> sa = gather<D, KA>(xa, cells_a_[i]);
      const Simplex<D, KB> sb = gather<D, KB>(xb, cells_b_[j]);
      if (provably_farther<D, KA, KB>(sa, sb, best)) return;
      const double d = closest_points<D, KA, KB>(sa, sb).distance;
      if (d <= best) best = d, found = true;
    });
    return found ? best : std::numeric_limits<double>::infinity();
  });
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
