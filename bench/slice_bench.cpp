// Slices of the spun trefoil at the scenario's resolution (issue 37): the level curves the window
// redraws live while the surface is pulled (target <= 2 ms), the critical levels, one slice named
// (off the UI thread in the window), and the 41 slices of a movie named (the CLI adds the drawing:
// measure `time shadow4d slice ... --levels 41`, target <= 10 s).
#include <benchmark/benchmark.h>

#include "io/scene.hpp"
#include "knots/slice_naming.hpp"
#include "shape/level_set.hpp"
#include "view/scene_slice.hpp"

namespace s4d {
namespace {

const Scene& spun_trefoil_scenario() {
  static const Scene scene = load_scene(S4D_SOURCE_DIR "/scenarios/spun-trefoil-tighten.json");
  return scene;
}

double middle_level(const Scene& scene) {
  const auto [lo, hi] = scene_depth_range(scene);
  return 0.5 * (lo + hi);
}

void BM_SpunTrefoilLevelCurves(benchmark::State& state) {
  const Scene& scene = spun_trefoil_scenario();
  const double c = middle_level(scene);
  std::size_t points = 0;
  for (auto _ : state) {
    const SceneSlice slice = scene_slice(scene, c);
    points = slice.curve.point_count();
    benchmark::DoNotOptimize(points);
  }
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_SpunTrefoilLevelCurves)->Unit(benchmark::kMicrosecond);

void BM_SpunTrefoilCriticalLevels(benchmark::State& state) {
  const Scene& scene = spun_trefoil_scenario();
  for (auto _ : state) benchmark::DoNotOptimize(scene_critical_points(scene).size());
}
BENCHMARK(BM_SpunTrefoilCriticalLevels)->Unit(benchmark::kMicrosecond);

// One slice named: 0 = fast (the live line), 1 = every refinement.
void BM_SpunTrefoilSliceNamed(benchmark::State& state) {
  const Scene& scene = spun_trefoil_scenario();
  const SceneSlice slice = scene_slice(scene, middle_level(scene));
  NamingOptions o;
  o.fast = state.range(0) == 0;
  for (auto _ : state) benchmark::DoNotOptimize(name_slice(slice.curve, slice.level, o).name);
}
BENCHMARK(BM_SpunTrefoilSliceNamed)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

void BM_SpunTrefoilMovie41Named(benchmark::State& state) {
  const Scene& scene = spun_trefoil_scenario();
  const auto [lo, hi] = scene_depth_range(scene);
  for (auto _ : state)
    for (double c : movie_levels(lo, hi, 41)) benchmark::DoNotOptimize(name_slice(scene_slice(scene, c).curve, c).name);
}
BENCHMARK(BM_SpunTrefoilMovie41Named)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
}  // namespace s4d

BENCHMARK_MAIN();
