// What the whole-mesh queries share below the broad phase: gathering a cell's vertices (their boxes
// are in cell_boxes.hpp) and the narrow phase of one candidate pair (cheap separating-axis
// rejection, then the exact kernels of closest_points.hpp / continuous_collision.hpp).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "proximity/bvh.hpp"
#include "proximity/cell_boxes.hpp"
#include "proximity/cells.hpp"
#include "proximity/continuous_collision.hpp"
#include "proximity/separating_axes.hpp"

namespace s4d::prox_detail {

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

inline void check_size(std::size_t n, int max_index, const char* what) {
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

// Euclidean gap of two boxes, a lower bound of the distance of anything inside them (0 for a
// non-finite box).
template <int D>
double box_gap(const Box<D>& p, const Box<D>& q) {
  double g2 = 0;
  for (int k = 0; k < D; ++k) {
    const double g = std::max(q.lo[k] - p.hi[k], p.lo[k] - q.hi[k]);
    if (g > 0) g2 += g * g;
  }
  return g2 < std::numeric_limits<double>::infinity() ? std::sqrt(g2) * (1 - 1e-12) : 0.0;
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
  if (r.hit &&
      (!best.hit || r.t < best.t || (r.t == best.t && std::pair(a, b) < std::pair(best.a, best.b)))) {
    best.hit = true;
    best.t = r.t;
    best.a = a;
    best.b = b;
    best.at_t = r.at_t;
  }
}

// Sorts pairs by (a, b). A pair carries its closest points (some 130 bytes): the sort runs on
// (key, index) and the pairs move once, through `scratch`; nothing moves when already sorted.
template <int D>
void sort_pairs(std::vector<ProximityPair<D>>& out, std::vector<std::pair<std::uint64_t, int>>& keys,
                std::vector<ProximityPair<D>>& scratch) {
  auto key = [](const ProximityPair<D>& p) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(p.a)) << 32 |
           static_cast<std::uint32_t>(p.b);
  };
  bool sorted = true;
  for (std::size_t i = 1; i < out.size() && sorted; ++i) sorted = key(out[i - 1]) < key(out[i]);
  if (sorted) return;
  keys.resize(out.size());
  for (std::size_t i = 0; i < out.size(); ++i) keys[i] = {key(out[i]), static_cast<int>(i)};
  std::sort(keys.begin(), keys.end());
  scratch.resize(out.size());
  for (std::size_t i = 0; i < out.size(); ++i) scratch[i] = out[keys[i].second];
  out.swap(scratch);
}

template <int D>
void sort_pairs(std::vector<ProximityPair<D>>& out) {
  std::vector<std::pair<std::uint64_t, int>> keys;
  std::vector<ProximityPair<D>> scratch;
  sort_pairs(out, keys, scratch);
}

}  // namespace s4d::prox_detail
