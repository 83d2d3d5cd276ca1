// Finder (a): self-intersections of a surface, and intersections between two surfaces.
#include "proximity/self_intersections.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>

#include "core/error.hpp"
#include "proximity/narrow_phase.hpp"

namespace s4d {

namespace {

template <int D>
double diagonal(const std::vector<Vec<D>>& a, const std::vector<Vec<D>>* b) {
  Box<D> box;
  for (const auto& v : a)
    if (v.allFinite()) box.add(v);
  if (b)
    for (const auto& v : *b)
      if (v.allFinite()) box.add(v);
  const double d = (box.hi - box.lo).norm();
  return std::isfinite(d) && d > 0 ? d : 1.0;
}

template <int D>
struct CellKey {
  std::array<long long, D> c;
  friend bool operator==(const CellKey&, const CellKey&) = default;
};
template <int D>
struct CellHash {
  std::size_t operator()(const CellKey<D>& k) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a in 64 bits, whatever size_t is (wasm32's is 32)
    for (long long x : k.c) h = (h ^ static_cast<std::uint64_t>(x)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

template <int D>
IntersectionReport<D> finish(std::vector<ProximityPair<D>> pairs, double tol, double merge) {
  IntersectionReport<D> r;
  r.tolerance = tol;
  r.merge_distance = merge;
  std::vector<Vec<D>> pts;
  pts.reserve(pairs.size());
  for (const auto& p : pairs) pts.push_back(0.5 * (p.closest.p + p.closest.q));
  r.points = merge_points<D>(pts, merge);
  r.pairs = std::move(pairs);
  return r;
}

}  // namespace

template <int D>
std::vector<Vec<D>> merge_points(const std::vector<Vec<D>>& points, double distance) {
  const int n = static_cast<int>(points.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const double cell = distance > 0 ? distance : 1e-300;
  std::unordered_map<CellKey<D>, std::vector<int>, CellHash<D>> grid;
  auto key = [&](const Vec<D>& p) {
    CellKey<D> k;
    for (int i = 0; i < D; ++i) k.c[i] = static_cast<long long>(std::floor(p[i] / cell));
    return k;
  };
  for (int i = 0; i < n; ++i) {
    if (!points[i].allFinite()) continue;
    const CellKey<D> k = key(points[i]);
    // Visit the 3^D neighbouring cells.
    int combos = 1;
    for (int d = 0; d < D; ++d) combos *= 3;
    for (int m = 0; m < combos; ++m) {
      CellKey<D> nk = k;
      int r = m;
      for (int d = 0; d < D; ++d, r /= 3) nk.c[d] += r % 3 - 1;
      const auto it = grid.find(nk);
      if (it == grid.end()) continue;
      for (int j : it->second)
        if ((points[i] - points[j]).norm() <= distance) parent[find(parent, i)] = find(parent, j);
    }
    grid[k].push_back(i);
  }
  std::vector<Vec<D>> out;
  std::vector<char> seen(n, 0);
  for (int i = 0; i < n; ++i) {
    if (!points[i].allFinite()) continue;
    const int root = find(parent, i);
    if (!seen[root]) {
      seen[root] = 1;
      out.push_back(points[i]);
    }
  }
  return out;
}

template <int D>
IntersectionReport<D> self_intersections(const Surface<D>& s, const IntersectionOptions& opt) {
  const double diag = diagonal<D>(s.vertices, nullptr);
  const double tol = opt.tolerance >= 0 ? opt.tolerance : 1e-9 * diag;
  const double merge = opt.merge_distance >= 0 ? opt.merge_distance : 1e-6 * diag;
  SelfProximity<D, 3> q(s.triangles);
  std::vector<ProximityPair<D>> pairs;
  q.pairs_within(s.vertices, tol, pairs);
  return finish<D>(std::move(pairs), tol, merge);
}

template <int D>
IntersectionReport<D> self_intersections_among(const Surface<D>& s,
                                               std::span<const std::array<int, 2>> candidates,
                                               const IntersectionOptions& opt) {
  const double diag = diagonal<D>(s.vertices, nullptr);
  const double tol = opt.tolerance >= 0 ? opt.tolerance : 1e-9 * diag;
  const double merge = opt.merge_distance >= 0 ? opt.merge_distance : 1e-6 * diag;
  const int nt = static_cast<int>(s.triangles.size());
  prox_detail::check_size(s.vertices.size(), prox_detail::max_index<3>(s.triangles), "the surface");
  std::vector<std::array<int, 2>> pairs;
  pairs.reserve(candidates.size());
  for (const auto& [a, b] : candidates) {
    if (a < 0 || b < 0 || a >= nt || b >= nt)
      throw Error("proximity: a candidate pair names triangle " + std::to_string(a < 0 || a >= nt ? a : b) +
                  " of a surface of " + std::to_string(nt));
    if (a != b && !share_vertex<3, 3>(s.triangles[a], s.triangles[b]))
      pairs.push_back({std::min(a, b), std::max(a, b)});
  }
  // Each pair once, in self_intersections' order (a, b).
  if (!std::is_sorted(pairs.begin(), pairs.end())) std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<ProximityPair<D>> out;
  const std::span<const Vec<D>> x(s.vertices);
  // The broad phase's test, a pair at a time: boxes farther apart than the tolerance.
  std::vector<Box<D>> boxes;
  prox_detail::static_boxes<D, 3>(x, s.triangles, boxes);
  for (const auto& [a, b] : pairs)
    if (!(prox_detail::box_gap<D>(boxes[a], boxes[b]) > tol))
      prox_detail::narrow_within<D, 3, 3>(prox_detail::gather<D, 3>(x, s.triangles[a]),
                                          prox_detail::gather<D, 3>(x, s.triangles[b]), a, b, tol, out);
  return finish<D>(std::move(out), tol, merge);
}

template <int D>
IntersectionReport<D> surface_intersections(const Surface<D>& a, const Surface<D>& b,
                                            const IntersectionOptions& opt) {
  const double diag = diagonal<D>(a.vertices, &b.vertices);
  const double tol = opt.tolerance >= 0 ? opt.tolerance : 1e-9 * diag;
  const double merge = opt.merge_distance >= 0 ? opt.merge_distance : 1e-6 * diag;
  PairProximity<D, 3, 3> q(a.triangles, b.triangles);
  std::vector<ProximityPair<D>> pairs;
  q.pairs_within(a.vertices, b.vertices, tol, pairs);
  return finish<D>(std::move(pairs), tol, merge);
}

#define S4D_INSTANTIATE(D)                                                                       \
  template IntersectionReport<D> self_intersections<D>(const Surface<D>&,                        \
                                                       const IntersectionOptions&);              \
  template IntersectionReport<D> self_intersections_among<D>(                                    \
      const Surface<D>&, std::span<const std::array<int, 2>>, const IntersectionOptions&);       \
  template IntersectionReport<D> surface_intersections<D>(const Surface<D>&, const Surface<D>&,  \
                                                          const IntersectionOptions&);           \
  template std::vector<Vec<D>> merge_points<D>(const std::vector<Vec<D>>&, double);
S4D_INSTANTIATE(2)
S4D_INSTANTIATE(3)
S4D_INSTANTIATE(4)
#undef S4D_INSTANTIATE

}  // namespace s4d
