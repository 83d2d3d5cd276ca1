// The surface explorer's costs (issue 25 point 6): one 1 kHz update (the navigation spring with the
// mesh walk and the crossing test) on spun-trefoil:n=64,m=12 in a generic view, and the crossing
// table's refresh, which the window runs off the loop when the view turns.
#include <benchmark/benchmark.h>

#include <cmath>

#include "interact/live/surface_explorer.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

struct Setup {
  Surface<4> surface;
  Frame<4> frame;
  Setup() {
    surface = std::get<Surface<4>>(generate("spun-trefoil", {{"n", 64}, {"m", 12}}));
    apply_rotations(frame, parse_rotation_list("xw=30,yw=20", 4));
  }
};

const Setup& setup() {
  static const Setup s;
  return s;
}

// The device point circles through the shadow at 0.5 m/s-like pace (a 1.2-unit circle in 4 s), so
// the probe keeps crossing triangles, folds and intersection curves.
void BM_ExplorerUpdate(benchmark::State& state) {
  const Setup& s = setup();
  SurfaceExplorer e(s.surface.triangles, static_cast<int>(s.surface.vertices.size()));
  e.refresh_crossings(s.surface.vertices, s.frame);
  e.place(s.surface.vertices, s.frame, Vec3(1.2, 0, 0));
  const DampedSpring spring{200, 1};
  std::int64_t tick = 0;
  for (auto _ : state) {
    const double t = 1e-3 * static_cast<double>(tick++), a = 2 * 3.14159265358979 * t / 4;
    const Vec3 c(1.2 * std::cos(a), 1.2 * std::sin(a), 0.3 * std::sin(3 * a));
    const Vec3 v(-1.2 * std::sin(a), 1.2 * std::cos(a), 0.9 * std::cos(3 * a));
    benchmark::DoNotOptimize(e.update(s.surface.vertices, s.frame, c, v * (2 * 3.14159265358979 / 4), 1000, t, spring));
    while (e.pop_event()) {
    }
  }
  state.counters["edges_per_tick"] = double(e.counters().edges_walked) / double(tick);
  state.counters["events"] = double(e.counters().events);
}
BENCHMARK(BM_ExplorerUpdate);

void BM_CrossingTableRefresh(benchmark::State& state) {
  const Setup& s = setup();
  SurfaceExplorer e(s.surface.triangles, static_cast<int>(s.surface.vertices.size()));
  for (auto _ : state) e.refresh_crossings(s.surface.vertices, s.frame);
  state.counters["segments"] = e.crossings().segments;
}
BENCHMARK(BM_CrossingTableRefresh)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace s4d

BENCHMARK_MAIN();
