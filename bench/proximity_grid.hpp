// The crumpled grid surface shared by the proximity benchmarks: an n × n grid of the unit square
// displaced by a deterministic sum of sinusoids in every coordinate, so that folds come close.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <span>
#include <vector>

#include "proximity/mesh_proximity.hpp"

namespace s4d::bench {

// Vertex (i, j) at "time" phase; D = 3 keeps the first three coordinates of the R^4 surface.
template <int D>
std::vector<Vec<D>> crumpled_grid(int n, double phase) {
  std::vector<Vec<D>> x;
  x.reserve(static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = double(i) / (n - 1), v = double(j) / (n - 1);
      Vec4 p(u + 0.08 * std::sin(7.0 * v + 2.0 * u + phase),
             v + 0.08 * std::sin(6.0 * u - 3.0 * v + 1.3 * phase),
             0.25 * std::sin(9.0 * u + phase) * std::cos(8.0 * v) + 0.05 * std::sin(23.0 * u * v),
             0.25 * std::cos(7.0 * u - 5.0 * v + 0.7 * phase) * std::sin(6.0 * v + u));
      x.push_back(p.head<D>());
    }
  return x;
}

inline std::vector<Cell<3>> grid_triangles(int n) {
  std::vector<Cell<3>> t;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j, b = a + 1, c = a + n, d = c + 1;
      t.push_back({a, b, d});
      t.push_back({a, d, c});
    }
  return t;
}

// Thickness for an n × n grid: half the grid spacing (scene units), so neighbouring rows are
// outside it but folds that come close are inside.
inline double grid_delta(int n) { return 0.5 / (n - 1); }

// The phase a stepping run advances by each step (largest vertex motion about 6 % of δ).
constexpr double kPhasePerStep = 0.002;

// The smallest distance of two triangles sharing no vertex at x (infinity beyond 2δ), found by
// `probe`, which a caller keeps from step to step so that it answers coherently.
inline double smallest_gap(SelfProximity<4, 3>& probe, int n, std::span<const Vec4> x) {
  std::vector<ProximityPair<4>> near;
  probe.pairs_within(x, 2 * grid_delta(n), near);
  double d = std::numeric_limits<double>::infinity();
  for (const auto& p : near) d = std::min(d, p.closest.distance);
  return d;
}

// The thickness of the stepping impact query's step from phase k·kPhasePerStep on the n × n grid:
// 0.995 × the smallest gap there, from a probe (a second SelfProximity). Kept for the whole
// process and worked out many phases at a time (256 at 64²), so that the probe seldom runs between
// two timed queries. Run before every step, its own bounds pushed the query's out of the cache and
// the benchmark timed that too (64², 2026-12-03: 0.75-0.77 ms a step with the probe run before
// each, 0.58-0.61 ms without). A physics step asks one SelfProximity both of its queries.
inline double stepping_thickness(int n, int k) {
  struct Probe {
    SelfProximity<4, 3> q;
    std::vector<double> thickness;
  };
  static std::map<int, Probe> probes;
  auto it = probes.find(n);
  if (it == probes.end()) it = probes.emplace(n, Probe{SelfProximity<4, 3>(grid_triangles(n)), {}}).first;
  Probe& p = it->second;
  const int chunk = std::max(16, 256 * 64 * 64 / (n * n));  // 256 at 64², fewer on larger grids
  while (static_cast<int>(p.thickness.size()) <= k) {
    const int first = static_cast<int>(p.thickness.size());
    for (int j = first; j < first + chunk; ++j)
      p.thickness.push_back(0.995 * smallest_gap(p.q, n, crumpled_grid<4>(n, j * kPhasePerStep)));
  }
  return p.thickness[k];
}

}  // namespace s4d::bench
