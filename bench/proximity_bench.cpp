// Proximity benchmarks (issue 4): all pairs within δ and earliest time of impact on a crumpled
// 64×64 / 128×128 / 256×256 grid surface in R^4, one core. Targets at 64×64: 0.3 ms and 0.5 ms.
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>

#include "proximity_grid.hpp"

namespace s4d::bench {
namespace {

void BM_PairsWithinDelta4D(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto x = crumpled_grid<4>(n, 0.0);
  SelfProximity<4, 3> q(grid_triangles(n));
  std::vector<ProximityPair<4>> out;
  q.pairs_within(x, grid_delta(n), out);  // first call builds the BVH; later calls refit
  for (auto _ : state) {
    q.pairs_within(x, grid_delta(n), out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["triangles"] = static_cast<double>(q.cells().size());
  state.counters["pairs"] = static_cast<double>(out.size());
}
BENCHMARK(BM_PairsWithinDelta4D)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

// One step that creates contacts from a contact-free start: the thickness is 0.995 × the smallest
// distance of non-adjacent triangles at the start (so no pair starts within it), and over the step
// the surface deforms (phase +0.02) while shrinking by 1% about its centre (every distance
// shrinks with it), so the closest folds cross the thickness part-way through the step.
void BM_EarliestImpact4D(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto x0 = crumpled_grid<4>(n, 0.0);
  auto x1 = crumpled_grid<4>(n, 0.02);
  const Vec4 centre(0.5, 0.5, 0.0, 0.0);
  for (Vec4& p : x1) p = centre + 0.99 * (p - centre);
  SelfProximity<4, 3> q(grid_triangles(n));
  std::vector<ProximityPair<4>> near;
  q.pairs_within(x0, 2 * grid_delta(n), near);
  double d_min = std::numeric_limits<double>::infinity();
  for (const auto& p : near) d_min = std::min(d_min, p.closest.distance);
  CcdOptions opt;
  opt.thickness = 0.995 * d_min;
  Impact<4> r = q.earliest_impact(x0, x1, opt);
  if (!std::isfinite(d_min) || !r.hit || !(r.t > 0)) {
    state.SkipWithError("benchmark step does not go from contact-free to contact");
    return;
  }
  for (auto _ : state) {
    r = q.earliest_impact(x0, x1, opt);
    benchmark::DoNotOptimize(r.t);
  }
  state.counters["thickness"] = opt.thickness;
  state.counters["hit"] = r.hit;
  state.counters["toi"] = r.t;
  state.counters["narrow_tests"] = r.narrow_tests;
}
BENCHMARK(BM_EarliestImpact4D)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace s4d::bench

BENCHMARK_MAIN();
