// Proximity benchmarks (issue 4): all pairs within δ and earliest time of impact on a crumpled
// 64×64 / 128×128 / 256×256 grid surface in R^4, one core. Targets at 64×64: 0.3 ms and 0.5 ms.
#include <benchmark/benchmark.h>

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

void BM_EarliestImpact4D(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  // One step of a slow deformation: the phase advances by 0.02 (vertices move up to ~0.005).
  const auto x0 = crumpled_grid<4>(n, 0.0);
  const auto x1 = crumpled_grid<4>(n, 0.02);
  SelfProximity<4, 3> q(grid_triangles(n));
  CcdOptions opt;
  opt.thickness = grid_delta(n);
  Impact<4> r = q.earliest_impact(x0, x1, opt);
  for (auto _ : state) {
    r = q.earliest_impact(x0, x1, opt);
    benchmark::DoNotOptimize(r.t);
  }
  state.counters["hit"] = r.hit;
  state.counters["toi"] = r.t;
  state.counters["narrow_tests"] = r.narrow_tests;
}
BENCHMARK(BM_EarliestImpact4D)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace s4d::bench

BENCHMARK_MAIN();
