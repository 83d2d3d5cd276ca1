// Knot engine benchmarks (issues 7 and 26): identification of a 500-point curve, from curve to name
// (target <= 5 ms median, the live-naming budget), the live panel's knot_info of 500-point prime
// knots of up to 12 crossings made from the table (same budget), the further invariants where
// candidates remain (off the UI thread, no budget), making table knots, and relaxation of a
// 300-point curve (target >= 1000 iterations per second).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "knots/braid_closure.hpp"
#include "knots/knot_identify.hpp"
#include "knots/knot_info.hpp"
#include "knots/knot_naming.hpp"
#include "knots/knot_table.hpp"
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

// 500-point curves of table knots up to 12 crossings (drawn, relaxed, resampled), seen from +z.
const std::vector<Case>& table_cases() {
  static const std::vector<Case> all = [] {
    std::vector<Case> c;
    for (const char* name : {"3_1", "7_4", "10_165", "11n_34", "12a_1", "12a_803", "12n_888"})
      c.push_back({name, resample_curve_to_count(make_table_knot(name), 500)});
    return c;
  }();
  return all;
}

void BM_KnotInfoLive500(benchmark::State& state) {
  const Case& c = table_cases()[state.range(0)];
  KnotIndex::shipped();
  KnotInfoOptions o;
  o.fast = true;  // the live path; the further invariants follow on the worker
  KnotInfo k;
  for (auto _ : state) {
    k = knot_info(c.curve, std::nullopt, o);
    benchmark::DoNotOptimize(k.name);
  }
  state.SetLabel(std::string(c.name) + " (" + std::to_string(k.view_crossings) + " in view) -> " + k.name);
}
BENCHMARK(BM_KnotInfoLive500)->DenseRange(0, 6)->Unit(benchmark::kMillisecond)->Repetitions(5)
    ->ReportAggregatesOnly(true)->ComputeStatistics("max", [](const std::vector<double>& v) {
      return *std::max_element(v.begin(), v.end());
    });

// The same curves named by each engine (issue 35: the web page's own engine against Regina), the
// live path (fast, as the panel names while dragging) and in full. Args: case, engine (0 Regina,
// 1 own), fast.
void BM_NameKnot500ByEngine(benchmark::State& state) {
  const Case& c = table_cases()[state.range(0)];
  KnotIndex::shipped();
  NamingOptions o;
  o.engine = state.range(1) == 0 ? KnotEngine::kRegina : KnotEngine::kOwn;
  o.fast = state.range(2) != 0;
  if (o.engine == KnotEngine::kRegina && !regina_available()) {
    state.SkipWithError("built without Regina");
    return;
  }
  KnotNaming n = name_knot(c.curve, o);  // the table's cover signatures cached, as in a session
  for (auto _ : state) {
    n = name_knot(c.curve, o);
    benchmark::DoNotOptimize(n.identification.name);
  }
  state.SetLabel(std::string(c.name) + " [" + engine_name(o.engine) + (o.fast ? ", fast" : "") + "] -> " +
                 n.headline());
}
BENCHMARK(BM_NameKnot500ByEngine)
    ->ArgsProduct({benchmark::CreateDenseRange(0, 6, 1), {0, 1}, {1, 0}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.2);

// 500-point curves of table links (the Borromean rings; 4 and 5 components; 11 crossings with a
// split alternative to rule out), named live as the panel does.
const std::vector<Case>& link_cases() {
  static const std::vector<Case> all = [] {
    std::vector<Case> c;
    for (const char* name : {"L6a4", "L10n113", "L11a1", "L11n459"})
      c.push_back({name, resample_curve_to_count(make_table_knot(name), 500)});
    return c;
  }();
  return all;
}

void BM_LinkInfoLive500(benchmark::State& state) {
  const Case& c = link_cases()[state.range(0)];
  KnotIndex::shipped();
  LinkTable::shipped();
  KnotInfoOptions o;
  o.fast = true;
  KnotInfo k = knot_info(c.curve, std::nullopt, o);  // the split/composite pieces are made once
  for (auto _ : state) {
    k = knot_info(c.curve, std::nullopt, o);
    benchmark::DoNotOptimize(k.name);
  }
  state.SetLabel(std::string(c.name) + " (" + std::to_string(c.curve.point_count()) + " points, " +
                 std::to_string(k.view_crossings) + " in view) -> " + k.name + (k.proven ? " (proven)" : ""));
}
BENCHMARK(BM_LinkInfoLive500)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Repetitions(5)
    ->ReportAggregatesOnly(true)->ComputeStatistics("max", [](const std::vector<double>& v) {
      return *std::max_element(v.begin(), v.end());
    });

// The Conway knot: its mutant 11n_42 shares every polynomial; covers and a Reidemeister search.
void BM_KnotInfoRefineConway(benchmark::State& state) {
  const Case& c = table_cases()[3];
  KnotInfo k;
  for (auto _ : state) {
    k = knot_info(c.curve);
    benchmark::DoNotOptimize(k.name);
  }
  state.SetLabel(std::string(c.name) + " -> " + k.name + (k.proven ? " (proven)" : ""));
}
BENCHMARK(BM_KnotInfoRefineConway)->Unit(benchmark::kMillisecond)->Iterations(3);

// Issue 37, point 4: what tells mutants apart and what it costs. Covers of index 2 to 6 of the
// group of a table diagram (uncached: the naming computes the curve's own once per request).
void BM_CoverSignatureIndex6(benchmark::State& state) {
  const char* names[] = {"11n_34", "11n_42", "10_132", "L11n432", "L11n437"};
  const char* name = names[state.range(0)];
  const KnotDiagram d = table_knot(name).diagram;
  std::string sig;
  for (auto _ : state) sig = cover_signature(d, 6);
  state.SetLabel(std::string(name) + ", signature hash " + std::to_string(std::hash<std::string>{}(sig) % 100000));
}
BENCHMARK(BM_CoverSignatureIndex6)->DenseRange(0, 4)->Unit(benchmark::kMillisecond)->Iterations(1);

// The one naming in full (name_knot, the default of `knot identify`, `knot info` and the panel) on
// 500-point curves turned away from the table's view; the candidates' signatures cached (as after
// the first request of a session).
void BM_NameKnotFull(benchmark::State& state) {
  const char* names[] = {"10_132 mirror", "11n_34", "11n_42 mirror"};
  const char* name = names[state.range(0)];
  Curve<3> c = resample_curve_to_count(make_table_knot(name), 500);
  const Mat<3> turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (auto& p : c.components)
    for (Vec3& q : p.points) q = turn * q;
  KnotNaming n = name_knot(c);
  for (auto _ : state) {
    n = name_knot(c);
    benchmark::DoNotOptimize(n.identification.name);
  }
  state.SetLabel(std::string(name) + " -> " + n.headline());
}
BENCHMARK(BM_NameKnotFull)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_MakeTableKnot(benchmark::State& state) {
  const char* names[] = {"3_1", "10_165", "12a_1", "14nh_7499"};
  const char* name = names[state.range(0)];
  KnotIndex::shipped();
  int points = 0;
  for (auto _ : state) points = make_table_knot(name).point_count();
  state.SetLabel(std::string(name) + ", " + std::to_string(points) + " points");
}
BENCHMARK(BM_MakeTableKnot)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Iterations(2);

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
