// Step times of issue 35's side-by-side table (docs/performance.md): the same three workloads as
// physics_bench's BM_SpunTrefoilStep and BM_Cloth4DCrumpledStep/64 and knots_bench's
// BM_NameKnot500ByEngine (own engine), timed with a plain clock so that one source builds both
// natively and with emscripten (Google Benchmark is not built for WebAssembly). One line per
// measure: "step_times NAME MS_PER_RUN (RUNS runs) NOTE".
//   native: build-test/bench/step_times [DATA_DIR]    web: node build-web/bench/step_times.js DATA_DIR
// DATA_DIR (a checkout, or an installed share/shadow4d) becomes S4D_DATA_DIR for the knot index:
// the program under node does not see the shell's environment.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cloth_scene.hpp"
#include "spun_trefoil_scene.hpp"
#include "knots/knot_naming.hpp"
#include "knots/knot_table.hpp"
#include "knots/resample.hpp"

namespace s4d {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

void report(const char* name, double total_ms, int runs, const std::string& note) {
  std::printf("step_times %s %.3f ms (%d runs) %s\n", name, total_ms / runs, runs, note.c_str());
  std::fflush(stdout);
}

// As BM_SpunTrefoilStep: the scenario's sphere (n=64, m=12) pulled apart, steps 501-1500.
void spun_trefoil() {
  World<4> w = bench::pulled_spun_trefoil();
  const int runs = 1000;
  const auto t0 = Clock::now();
  for (int i = 0; i < runs; ++i) w.step();
  report("spun_trefoil_step", ms_since(t0), runs, std::to_string(w.vertex_count()) + " vertices");
}

// As BM_Cloth4DCrumpledStep/64: steps 601-900 of the crumpling pull.
void crumpled_cloth_64() {
  const int n = 64;
  auto w = bench::crumpled_cloth<4>(n, 600);
  const int runs = 300;
  const auto t0 = Clock::now();
  for (int i = 0; i < runs; ++i) {
    bench::drive_corners(*w, n, w->data().time);
    w->step();
  }
  report("crumpled_cloth_64_step", ms_since(t0), runs, std::to_string(w->data().last_contacts) + " contacts");
}

// As BM_NameKnot500ByEngine with the own engine: a 500-point 7_4 and 12n_888, named fast (the
// live panel) and in full.
void name_knots() {
  KnotIndex::shipped();
  for (const char* name : {"7_4", "12n_888"}) {
    const Curve<3> curve = resample_curve_to_count(make_table_knot(name), 500);
    for (bool fast : {true, false}) {
      NamingOptions o;
      o.engine = KnotEngine::kOwn;
      o.fast = fast;
      KnotNaming n = name_knot(curve, o);  // the table's caches filled, as in a session
      const int runs = 10;
      const auto t0 = Clock::now();
      for (int i = 0; i < runs; ++i) n = name_knot(curve, o);
      const std::string what = std::string("name_500_point_") + name + (fast ? "_fast" : "_full");
      report(what.c_str(), ms_since(t0), runs, "-> " + n.headline());
    }
  }
}

}  // namespace
}  // namespace s4d

int main(int argc, char** argv) {
  if (argc > 1) setenv("S4D_DATA_DIR", argv[1], 1);
  try {
    s4d::spun_trefoil();
    s4d::crumpled_cloth_64();
    s4d::name_knots();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "step_times: %s\n", e.what());
    return 1;
  }
  return 0;
}
