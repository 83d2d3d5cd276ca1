// Proximity benchmarks (issue 4): all pairs within δ and earliest time of impact on a crumpled
// 64×64 / 128×128 / 256×256 grid surface in R^4, one core. Targets at 64×64: 0.3 ms and 0.5 ms.
//
// Two kinds of run:
//  - Cold: every query runs the broad phase from scratch (temporal coherence off), as a one-off
//    check of a mesh would.
//  - Stepping: the surface deforms a little between queries, as in a 1 kHz simulation (largest
//    vertex motion per step reported as max_move, about 6 % of δ), and one SelfProximity answers
//    them all: this is what the physics loop pays per step. Position updates are not timed.
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <vector>

#include "proximity_grid.hpp"

namespace s4d::bench {
namespace {

double max_move(std::span<const Vec4> a, std::span<const Vec4> b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, (a[i] - b[i]).norm());
  return m;
}

void BM_PairsWithinDelta4D_Cold(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto x = crumpled_grid<4>(n, 0.0);
  SelfProximity<4, 3> q(grid_triangles(n));
  q.set_temporal_coherence(false);
  std::vector<ProximityPair<4>> out;
  q.pairs_within(x, grid_delta(n), out);  // the first call builds the BVH; later calls refit
  for (auto _ : state) {
    q.pairs_within(x, grid_delta(n), out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["triangles"] = static_cast<double>(q.cells().size());
  state.counters["pairs"] = static_cast<double>(out.size());
}
BENCHMARK(BM_PairsWithinDelta4D_Cold)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

void BM_PairsWithinDelta4D_Stepping(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  SelfProximity<4, 3> q(grid_triangles(n));
  std::vector<ProximityPair<4>> out;
  double phase = 0, pairs = 0, moved = 0;
  auto x = crumpled_grid<4>(n, phase);
  q.pairs_within(x, grid_delta(n), out);
  const long long runs0 = q.broad_phase_runs();
  for (auto _ : state) {
    state.PauseTiming();
    phase += kPhasePerStep;
    auto next = crumpled_grid<4>(n, phase);
    moved = std::max(moved, max_move(x, next));
    x = std::move(next);
    state.ResumeTiming();
    q.pairs_within(x, grid_delta(n), out);
    pairs += static_cast<double>(out.size());
  }
  state.counters["pairs"] = pairs / static_cast<double>(state.iterations());
  state.counters["max_move"] = moved;
  state.counters["rebuilds_per_step"] =
      static_cast<double>(q.broad_phase_runs() - runs0) / static_cast<double>(state.iterations());
  state.counters["listed"] = static_cast<double>(q.listed_pairs());
}
BENCHMARK(BM_PairsWithinDelta4D_Stepping)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

// One step that creates contacts from a contact-free start: the thickness is 0.995 × the smallest
// distance of non-adjacent triangles at the start (so no pair starts within it), and over the step
// the surface deforms (phase +0.02) while shrinking by 1% about its centre (every distance
// shrinks with it), so the closest folds cross the thickness part-way through the step.
void BM_EarliestImpact4D_Cold(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto x0 = crumpled_grid<4>(n, 0.0);
  auto x1 = crumpled_grid<4>(n, 0.02);
  const Vec4 centre(0.5, 0.5, 0.0, 0.0);
  for (Vec4& p : x1) p = centre + 0.99 * (p - centre);
  SelfProximity<4, 3> q(grid_triangles(n)), probe(grid_triangles(n));
  q.set_temporal_coherence(false);
  const double d_min = smallest_gap(probe, n, x0);
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
  state.counters["toi"] = r.t;
  state.counters["narrow_tests"] = r.narrow_tests;
}
BENCHMARK(BM_EarliestImpact4D_Cold)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

// Steps along the same deformation as the stepping pairs query, each with the thickness set just
// under the smallest gap at its start (stepping_thickness): every step starts contact-free with a
// fold about to touch, the hardest case for the query. The fraction of steps that hit is reported.
void BM_EarliestImpact4D_Stepping(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  SelfProximity<4, 3> q(grid_triangles(n));
  int k = 0;  // the step goes from phase k to k + 1
  double hits = 0, tests = 0;
  auto x0 = crumpled_grid<4>(n, 0.0);
  auto x1 = crumpled_grid<4>(n, kPhasePerStep);
  CcdOptions opt;
  opt.thickness = stepping_thickness(n, 0);
  q.earliest_impact(x0, x1, opt);
  const long long runs0 = q.broad_phase_runs();
  for (auto _ : state) {
    state.PauseTiming();
    ++k;
    x0 = std::move(x1);
    x1 = crumpled_grid<4>(n, (k + 1) * kPhasePerStep);
    opt.thickness = stepping_thickness(n, k);
    state.ResumeTiming();
    const Impact<4> r = q.earliest_impact(x0, x1, opt);
    hits += r.hit;
    tests += r.narrow_tests;
  }
  const double steps = static_cast<double>(state.iterations());
  state.counters["hit_fraction"] = hits / steps;
  state.counters["narrow_tests"] = tests / steps;
  state.counters["rebuilds_per_step"] = static_cast<double>(q.broad_phase_runs() - runs0) / steps;
}
BENCHMARK(BM_EarliestImpact4D_Stepping)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace s4d::bench

BENCHMARK_MAIN();
