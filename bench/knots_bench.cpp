// Knot engine benchmarks (issue 7): identification of a 500-point curve, from curve to name
// (target <= 5 ms median, the live-naming budget), and relaxation of a 300-point curve (target
// >= 1000 iterations per second).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "knots/braid_closure.hpp"
#include "knots/knot_identify.hpp"
#include "knots/relax.hpp"
#include "knots/resample.hpp"
#include "shape/knot_curves.hpp"

namespace {

using namespace s4d;

struct Case {
  const char* name;
  Curve<3> curve;
};

// Curves of 500 points with up to 12 crossings (in their best view), and a messy unknot.
const std::vector<Case>& cases() {
  static const std::vector<Case> all = [] {
    auto braid = [](int strands, std::vector<int> w) {
      return resample_curve_to_count(braid_closure(strands, w, 9), 500);
    };
    std::vector<Case> c;
    c.push_back({"trefoil_T23", torus_knot(2, 3, 500)});
    c.push_back({"8_19_T34", torus_knot(3, 4, 500)});
    c.push_back({"10_crossing_T35", torus_knot(3, 5, 500)});
    c.push_back({"11_crossing_T2_11", torus_knot(2, 11, 500)});
    c.push_back({"10_161", braid(3, {-1, -1, -1, -2, 1, -2, -1, -1, -2, -2})});
    c.push_back({"10_123", braid(3, {-1, 2, -1, 2, -1, 2, -1, 2, -1, 2})});
    c.push_back({"5_1#7_1_12x", braid(3, {1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 2})});
    c.push_back({"3_1#3_1#4_1", braid(5, {1, 1, 1, 2, 2, 2, 3, -4, 3, -4})});
    // The unknot as the closed braid w s1 s2 s3 w^-1 (27 crossings as drawn).
    std::vector<int> w{1, -2, 3, 2, -1, 2, 3, -2, -3, 1, 1, 2}, word = w;
    for (int g : {1, 2, 3}) word.push_back(g);
    for (auto it = w.rbegin(); it != w.rend(); ++it) word.push_back(-*it);
    c.push_back({"unknot_27x", braid(4, word)});
    return c;
  }();
  return all;
}

void BM_IdentifyCurve500(benchmark::State& state) {
  const Case& c = cases()[state.range(0)];
  KnotIndex::shipped();  // loaded once at start-up in the app, not per identification
  std::string name;
  for (auto _ : state) {
    const auto id = identify_knot(c.curve);
    name = id.name;
    benchmark::DoNotOptimize(name);
  }
  state.SetLabel(std::string(c.name) + " -> " + name);
}
BENCHMARK(BM_IdentifyCurve500)->DenseRange(0, 8)->Unit(benchmark::kMillisecond)->Repetitions(5)
    ->ReportAggregatesOnly(true)->ComputeStatistics("max", [](const std::vector<double>& v) {
      return *std::max_element(v.begin(), v.end());
    });

void BM_RelaxStep300(benchmark::State& state) {
  const Curve<3> k = resample_curve_to_count(torus_knot(2, 3, 900), 300);
  RelaxModel m;
  RelaxData d;
  relax_setup(k, m, d);
  for (auto _ : state) {
    relax_step(m, d);
    benchmark::DoNotOptimize(d.x.data());
  }
  state.SetItemsProcessed(state.iterations());  // items/s = iterations per second
}
BENCHMARK(BM_RelaxStep300)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
