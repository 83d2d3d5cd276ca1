// Counts the instructions of the figures issues 4 and 5 track, under callgrind: one physics step
// of the crumpled 4D cloth (or of the folded one, resting on itself or its upper layer dragged
// across the lower), one stepping "pairs within
// δ" query and one stepping earliest-impact query on the crumpled grid. Wall-clock runs on this VM
// swing by ±25 %; instruction counts repeat exactly, so they are what a change is judged by
// (scripts/count-instructions.sh runs it).
//
// Usage: count_instructions physics|folded|drag|pairs|impact [--n 64] [--warmup W] [--steps S] [--fresh 1]
// Only the S measured steps are collected (callgrind --collect-atstart=no); natively it prints
// their mean wall time as well.
#include <chrono>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_TOGGLE_COLLECT
#define RUNNING_ON_VALGRIND 0
#endif

#include "cloth_scene.hpp"
#include "proximity_grid.hpp"

namespace s4d::bench {
namespace {

struct Options {
  std::string what;
  int n = 64;
  int warmup = -1;  // -1: the figure's own default
  int steps = 100;
  bool fresh = false;  // folded: every contact found and solved afresh (persistent_contacts off)
};

using Clock = std::chrono::steady_clock;

// Runs query() once: when `timed`, with collection on (callgrind counts only what runs between
// the toggles) and returning its wall time in s; otherwise uncounted, returning 0.
template <class F>
double run(bool timed, F&& query) {
  if (!timed) {
    query();
    return 0;
  }
  CALLGRIND_TOGGLE_COLLECT;
  const auto t0 = Clock::now();
  query();
  const auto t1 = Clock::now();
  CALLGRIND_TOGGLE_COLLECT;
  return std::chrono::duration<double>(t1 - t0).count();
}

// Runs step(timed) for the warm-up (timed false), then for the measured steps; returns the mean
// wall time of a measured step, in ms.
template <class F>
double measure(const Options& o, int default_warmup, F&& step) {
  const int warmup = o.warmup >= 0 ? o.warmup : default_warmup;
  for (int k = 0; k < warmup; ++k) step(false);
  double seconds = 0;
  for (int k = 0; k < o.steps; ++k) seconds += step(true);
  return 1e3 * seconds / o.steps;
}

// FNV-1a of the positions' bits: a change that claims the same physics must leave it as it was.
std::uint64_t state_hash(std::span<const Vec4> x) {
  std::uint64_t hash = 1469598103934665603ull;
  for (const Vec4& p : x)
    for (int k = 0; k < 4; ++k) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &p[k], sizeof bits);
      hash = (hash ^ bits) * 1099511628211ull;
    }
  return hash;
}

// physics_bench's crumpled cloth: steps 611–710 at the defaults.
double physics(const Options& o) {
  std::unique_ptr<World<4>> w = crumpled_cloth<4>(o.n, 0);
  const double ms = measure(o, 610, [&](bool timed) {
    drive_corners(*w, o.n, w->data().time);
    return run(timed, [&] { w->step(); });
  });
  std::printf("physics: state hash %016llx after %lld steps, %lld list builds\n",
              static_cast<unsigned long long>(state_hash(w->positions())),
              static_cast<long long>(w->data().steps), w->broad_phase_runs());
  return ms;
}

// physics_bench's folded cloth resting on itself: steps 201–300 at the defaults.
double folded(const Options& o) {
  std::unique_ptr<World<4>> w = folded_cloth_on_table<4>(o.n);
  Model<4> m = w->model();
  m.params.persistent_contacts = !o.fresh;
  w->set_model(std::move(m));
  const double ms = measure(o, 200, [&](bool timed) { return run(timed, [&] { w->step(); }); });
  std::printf("folded: state hash %016llx after %lld steps, %d contacts in the last\n",
              static_cast<unsigned long long>(state_hash(w->positions())),
              static_cast<long long>(w->data().steps), w->data().last_contacts);
  const ContactCacheStats cs = w->contact_stats();
  std::printf("folded: persistent contacts: %lld searches, %lld exact re-solves, %lld carried; %lld exact distances\n",
              cs.searches, cs.solves, cs.carried, w->exact_distances());
  return ms;
}

// The folded cloth's upper layer dragged across the lower (cloth_scene.hpp's FoldedDrag): 200
// steps settling, then the drag's steps (warm-up 0 by default: its first 2 s are the drag).
double drag(const Options& o) {
  FoldedDrag<4> d(o.n, 200, !o.fresh);
  const double ms = measure(o, 0, [&](bool timed) { return run(timed, [&] { d.step(); }); });
  std::printf("drag: state hash %016llx after %lld steps, %d contacts in the last\n",
              static_cast<unsigned long long>(state_hash(d.world->positions())),
              static_cast<long long>(d.world->data().steps), d.world->data().last_contacts);
  const ContactCacheStats cs = d.world->contact_stats();
  std::printf("drag: persistent contacts: %lld searches, %lld exact re-solves, %lld carried; %lld exact distances\n",
              cs.searches, cs.solves, cs.carried, d.world->exact_distances());
  return ms;
}

double pairs(const Options& o) {
  SelfProximity<4, 3> q(grid_triangles(o.n));
  std::vector<ProximityPair<4>> out;
  double phase = 0;
  return measure(o, 20, [&](bool timed) {
    const auto x = crumpled_grid<4>(o.n, phase);
    phase += kPhasePerStep;
    return run(timed, [&] { q.pairs_within(x, grid_delta(o.n), out); });
  });
}

double impact(const Options& o) {
  SelfProximity<4, 3> q(grid_triangles(o.n));
  // Every step's thickness first, so that a profile of the run past this point (perf record -D)
  // sees the queries alone.
  stepping_thickness(o.n, o.warmup + o.steps);
  int k = 0;
  return measure(o, 20, [&](bool timed) {
    const auto x0 = crumpled_grid<4>(o.n, k * kPhasePerStep);
    const auto x1 = crumpled_grid<4>(o.n, (k + 1) * kPhasePerStep);
    CcdOptions opt;
    opt.thickness = stepping_thickness(o.n, k);  // outside the count, and seldom worked out
    ++k;
    return run(timed, [&] { q.earliest_impact(x0, x1, opt); });
  });
}

int usage() {
  std::fprintf(stderr,
               "usage: count_instructions physics|folded|drag|pairs|impact [--n N] [--warmup W] [--steps S] [--fresh 1]\n");
  return 2;
}

}  // namespace
}  // namespace s4d::bench

int main(int argc, char** argv) {
  using namespace s4d::bench;
  if (argc < 2) return usage();
  Options o;
  o.what = argv[1];
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const int value = std::atoi(argv[i + 1]);
    if (flag == "--n" && value >= 8) o.n = value;
    else if (flag == "--warmup" && value >= 0) o.warmup = value;
    else if (flag == "--steps" && value >= 1) o.steps = value;
    else if (flag == "--fresh") o.fresh = value != 0;
    else return usage();
  }
  if ((argc - 2) % 2 != 0) return usage();
  double ms = 0;
  if (o.what == "physics") ms = physics(o);
  else if (o.what == "folded") ms = folded(o);
  else if (o.what == "drag") ms = drag(o);
  else if (o.what == "pairs") ms = pairs(o);
  else if (o.what == "impact") ms = impact(o);
  else return usage();
  std::printf("%s n=%d steps=%d: %.3f ms a step (wall clock, %s)\n", o.what.c_str(), o.n, o.steps,
              ms, RUNNING_ON_VALGRIND ? "under valgrind" : "native");
  return 0;
}
