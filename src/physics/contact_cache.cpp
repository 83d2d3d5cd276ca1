// Persistent contacts (see contact_cache.hpp for the bounds they rest on).
#include "physics/contact_cache.hpp"

#include <algorithm>
#include <cmath>

#include "proximity/closest_points.hpp"
#include "proximity/motion_kernels.hpp"

namespace s4d {

template <int D, int K>
void ContactCache<D, K>::search(SelfProximity<D, K>& prox, std::span<const std::array<int, K>> cells,
                             std::span<const Vec<D>> x, double reach) {
  radius_ = reach * (1 + skin_);
  prox.pairs_within(x, radius_, found_, RingPairs::kExclude);
  entries_.clear();
  for (const ProximityPair<D>& p : found_) {
    Entry e;
    e.a = p.a;
    e.b = p.b;
    e.wa = p.closest.wa;
    e.wb = p.closest.wb;
    e.d = e.solved = p.closest.distance;
    if (p.closest.distance > 0) e.n = (p.closest.p - p.closest.q) / p.closest.distance;
    e.code = face_pair_code(e.wa, e.wb);
    e.key_a = feature_key<K>(cells[e.a], e.wa);
    e.key_b = feature_key<K>(cells[e.b], e.wb);
    entries_.push_back(e);
  }
  x_search_.assign(x.begin(), x.end());
  x_last_.assign(x.begin(), x.end());
  ++stats_.searches;
}

template <int D, int K>
bool ContactCache<D, K>::search_stale(std::span<const Vec<D>> x, double reach) const {
  if (x_search_.size() != x.size() || x.empty() || !(radius_ > reach)) return true;
  // ρ: the largest net displacement since the search, less the mean one (a common translation
  // brings no pair closer).
  Vec<D> mean = Vec<D>::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) mean += x[i] - x_search_[i];
  mean /= static_cast<double>(x.size());
  double rho2 = 0;
  for (std::size_t i = 0; i < x.size(); ++i) rho2 = std::max(rho2, (x[i] - x_search_[i] - mean).squaredNorm());
  // Not finite (NaN compares false): stale, and the search reports what is wrong.
  return !(2 * std::sqrt(rho2) <= radius_ - reach);
}

template <int D, int K>
void ContactCache<D, K>::solve(Entry& e, std::span<const std::array<int, K>> cells, std::span<const Vec<D>> x) {
  const auto& ta = cells[e.a];
  const auto& tb = cells[e.b];
  Simplex<D, K> a, b;
  for (int q = 0; q < K; ++q) {
    a[q] = x[ta[q]];
    b[q] = x[tb[q]];
  }
  const ClosestPoints<D> cp = closest_points_warm<D, K, K>(a, b, e.code);
  e.wa = cp.wa;
  e.wb = cp.wb;
  e.d = e.solved = cp.distance;
  e.n = cp.distance > 0 ? Vec<D>((cp.p - cp.q) / cp.distance) : Vec<D>::Zero();
  e.moved = 0;
  e.key_a = feature_key<K>(ta, e.wa);
  e.key_b = feature_key<K>(tb, e.wb);
  ++stats_.solves;
}

template <int D, int K>
void ContactCache<D, K>::update(SelfProximity<D, K>& prox, std::span<const std::array<int, K>> cells,
                             std::span<const Vec<D>> x, double reach) {
  if (search_stale(x, reach)) {
    search(prox, cells, x, reach);
    return;
  }
  step_.resize(x.size());
  Vec<D> mean = Vec<D>::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    step_[i] = x[i] - x_last_[i];
    mean += step_[i];
  }
  mean /= static_cast<double>(x.size());
  std::copy(x.begin(), x.end(), x_last_.begin());
  // Each cell's largest move less the common one: a pair's relative motion is at most the sum of
  // its two cells' (two loads a pair, where the exact maximum over nine vertex pairs costs sixty
  // instructions; the looser bound only brings a re-solve sooner).
  vertex_move_.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) vertex_move_[i] = (step_[i] - mean).norm();
  cell_move_.resize(cells.size());
  for (std::size_t t = 0; t < cells.size(); ++t) {
    double m = 0;
    for (int q = 0; q < K; ++q) m = std::max(m, vertex_move_[cells[t][q]]);
    cell_move_[t] = m;
  }
  const double re_solve = re_solve_ * reach;
  for (Entry& e : entries_) {
    const auto& ta = cells[e.a];
    const auto& tb = cells[e.b];
    e.moved += cell_move_[e.a] + cell_move_[e.b];
    if (lower_bound(e) <= reach && e.moved > re_solve) {
      solve(e, cells, x);
      continue;
    }
    // The first-order change of the distance: the closest points move with their cells'
    // vertices, the features and the normal stay.
    Vec<D> dp = Vec<D>::Zero();
    for (int q = 0; q < K; ++q) dp += e.wa[q] * step_[ta[q]] - e.wb[q] * step_[tb[q]];
    // Within what the Lipschitz bound allows (the first order can overshoot on a turning pair).
    e.d = std::clamp(e.d + e.n.dot(dp), std::max(0.0, e.solved - e.moved), e.solved + e.moved);
    ++stats_.carried;
  }
}

template class ContactCache<2, 3>;
template class ContactCache<3, 3>;
template class ContactCache<4, 3>;
template class ContactCache<2, 2>;
template class ContactCache<3, 2>;
template class ContactCache<4, 2>;

}  // namespace s4d
