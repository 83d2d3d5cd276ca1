// The window's case (issue 25): the real 1 kHz HapticLoop thread (start(), SCHED_FIFO when granted)
// runs a LiveSimulation, its World stepped on a thread of its own (async) or inside the tick
// (inline), while the simulated arm's hand, button held, drags a vertex out and back. Per case:
// the loop's period p50 / p99 / p99.9 / max and missed deadlines, physics steps per wall second,
// the real-time ratio (simulated s per wall s), and true intersections found by the proximity
// finder in the states saved during the run and at its end.
//   case 0: the spun trefoil of scenarios/spun-trefoil-tighten.json (746 vertices)
//   case 1: scenes/cloth.json, the window's 32² cloth, hung by one edge
//   case 2: the 64² cloth folded onto itself on a held table (bench/cloth_scene.hpp), async only
//   case 3: that cloth's upper layer dragged 3 cm across the lower one and back over 2 s by the
//           replay device (a recorded hand, the `--device replay:FILE` path), async (issue 28)
// Targets: loop p99.9 ≤ 1.2 ms and physics ≥ real time for cases 0 and 1; case 2 keeps the loop at
// 1 kHz while its physics falls behind, and nothing passes through. S4D_LIVE_BENCH_SECONDS sets a
// run's length (default 4 s).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <thread>

#include "haptics/haptic_loop.hpp"
#include "haptics/replay_device.hpp"
#include "haptics/simulated_arm.hpp"
#include "haptics/trajectory_file.hpp"
#include "interact/live/haptic_scenes.hpp"
#include "interact/live/live_simulation.hpp"
#include "io/scene.hpp"
#include "shape/mesh_checks.hpp"
#include "scenario/scenario.hpp"
#include "scenario/world_builder.hpp"

#include "cloth_scene.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

// Case 3's run: 0.3 s at rest, the 2 s drag, 0.5 s held.
constexpr double kReplayRunSeconds = 2.8;

double bench_seconds(int which) {
  if (which == 3) return kReplayRunSeconds;
  const char* env = std::getenv("S4D_LIVE_BENCH_SECONDS");
  const double s = env ? std::atof(env) : 4.0;
  return s > 0.5 ? s : 4.0;
}

struct Case {
  const char* name;
  Scene scene;
  std::vector<int> held;  // vertices of object 0 the scene holds (a table), none for a free body
  int vertex;             // the vertex the hand drags (object 0's, local)
  Vec3 pull;              // m, device: the drag's far point from the start
};

Case make_case(int which) {
  const fs::path root(S4D_SOURCE_DIR);
  if (which == 0) {
    Case c{"spun trefoil 746 v", load_scenario(root / "scenarios" / "spun-trefoil-tighten.json").scene, {}, 0,
           Vec3::Zero()};
    // As the scenario's instruction says: one pole held (pinned in the window), the other pulled 4 cm
    // outwards in the device's xy plane (the roomy axes) and back.
    c.held = {static_cast<int>(std::get<Surface<4>>(c.scene.objects[0].shape).vertices.size()) - 1};
    const Vec3 p = shadow_of_vertex(c.scene, 0, 0);
    const DeviceMapping m = fit_to_workspace(c.scene, SimulatedArm().capabilities());
    Vec3 out = m.vector_to_device(p - m.centre);
    out.z() = 0;
    c.pull = 0.04 * out.normalized();
    return c;
  }
  if (which == 1) {
    // Free, its 1 kg would fall out of the 2 N band: its edge y = max is held (pinned in the window)
    // and it swings down to hang as a curtain, dragged by its middle towards the eye and back.
    const int n = 32;
    std::vector<int> edge;
    for (int i = 0; i < n; ++i) edge.push_back(i * n + n - 1);
    return Case{"cloth 32x32", load_scene(root / "scenes" / "cloth.json"), edge, 16 * n + 16, Vec3(0, 0, 0.025)};
  }
  const int n = 64;
  // The upper layer's free edge, in its middle, slid sideways over the lower layer and back.
  if (which == 3)
    return Case{"folded cloth 64x64, replay", bench::folded_cloth_scene<4>(n), bench::folded_cloth_table(n),
                (n - 1) * n + n / 2, Vec3(0, 0, 0.03)};
  return Case{"folded cloth 64x64", bench::folded_cloth_scene<4>(n), bench::folded_cloth_table(n), (n - 1) * n + n / 2,
              Vec3(0, 0, 0.02)};
}

// The hand's path as a recorded trajectory at 1 kHz, button 1 held throughout: what a replay of a
// session's drag plays.
Trajectory recorded_hand(const std::function<Vec3(double)>& hand, double seconds, const DeviceCapabilities& caps) {
  Trajectory t;
  t.header.device = "sim";
  t.header.scene = "live-simulation";
  t.header.caps = caps;
  const int ticks = static_cast<int>(seconds * t.header.rate);
  for (int k = 0; k < ticks; ++k) {
    const double time = k / t.header.rate;
    DeviceState st;
    st.position = hand(time);
    st.velocity = (hand(time + 1 / t.header.rate) - st.position) * t.header.rate;
    st.target = st.position;
    st.buttons = 1;
    TickRecord r;
    r.tick = static_cast<std::uint64_t>(k);
    r.set_state(st);
    t.ticks.push_back(r);
  }
  return t;
}

// Smooth ramp 0 → 1 over [a, b].
double ramp(double t, double a, double b) {
  const double u = std::clamp((t - a) / (b - a), 0.0, 1.0);
  return u * u * (3 - 2 * u);
}

// Pairs of triangles that touch or cross (every body's together), by the checker that shares no
// code with the engine (shape/mesh_checks.hpp).
int true_intersections(const Scene& scene, const std::vector<double>& points) {
  std::vector<int> first, count;
  body_vertex_ranges(scene, first, count);
  Surface<4> all;
  all.vertices.resize(points.size() / 4);
  for (std::size_t i = 0; i < all.vertices.size(); ++i)
    all.vertices[i] = Vec4(points[4 * i], points[4 * i + 1], points[4 * i + 2], points[4 * i + 3]);
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const auto* s = std::get_if<Surface<4>>(&scene.objects[o].shape);
    if (!s) continue;
    for (const Triangle& t : s->triangles) all.triangles.push_back({t[0] + first[o], t[1] + first[o], t[2] + first[o]});
  }
  return independent::self_intersections<4>(all).intersecting_pairs;
}

// range(0): the case; range(1): 1 = async physics (the window's mode), 0 = inline.
void BM_LiveHapticDrag(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const bool async = state.range(1) != 0;
  const double seconds = bench_seconds(which);
  PeriodSummary p, work;
  SceneStatus status;
  bool realtime = false;
  double wall = 0, max_force = 0;
  int worst = 0, saved = 0, grabbed = -2, most_contacts = 0;
  for (auto _ : state) {
    Case c = make_case(which);
    auto arm = std::make_unique<SimulatedArm>();
    LiveOptions o;
    o.async_physics = async;
    o.frame = c.scene.frame;
    o.mapping = fit_to_workspace(c.scene, arm->capabilities());
    const Vec3 start = o.mapping.to_device(shadow_of_vertex(c.scene, 0, c.vertex));
    if (!arm->capabilities().clamp(start + c.pull).isApprox(start + c.pull))
      state.SkipWithError("the drag leaves the workspace");
    std::unique_ptr<HapticScene> scene =
        c.held.empty() ? make_live_simulation(c.scene, nullptr, o)
                       : make_held_live_simulation(c.name, c.scene, c.scene.objects[0].name, c.held, o);
    // The hand rests 0.3 s, pulls out over 40 % of the rest of the run, comes back over as long, holds.
    const double out_end = 0.3 + 0.4 * (seconds - 0.3), back_end = 0.3 + 0.8 * (seconds - 0.3);
    const Vec3 pull = c.pull;
    const std::function<Vec3(double)> hand = [=](double t) -> Vec3 {
      return start + (ramp(t, 0.3, out_end) - ramp(t, out_end, back_end)) * pull;
    };
    std::unique_ptr<Device> device;
    if (which == 3) {
      device = std::make_unique<ReplayDevice>(recorded_hand(hand, seconds, arm->capabilities()), false);
    } else {
      arm->set_position(start);
      arm->set_hand_script(hand);
      device = std::move(arm);
    }
    HapticLoop loop(std::move(device), std::move(scene));
    loop.set_pointer(start, 1u);  // button 1 held from the first tick: the arm starts on the vertex
    std::vector<std::vector<double>> states;
    const auto t0 = std::chrono::steady_clock::now();
    loop.start();
    for (int k = 1; k <= 3; ++k) {  // three states saved during the run, checked after it
      std::this_thread::sleep_until(t0 + std::chrono::duration<double>(seconds * k / 4));
      states.push_back(loop.snapshot().points);
      most_contacts = std::max(most_contacts, loop.snapshot().status.contacts);
      if (k == 1) grabbed = loop.snapshot().status.held_vertex;
    }
    std::this_thread::sleep_until(t0 + std::chrono::duration<double>(seconds));
    loop.stop();
    wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const HapticSnapshot& s = loop.snapshot();
    states.push_back(s.points);
    p = s.period;
    work = s.work;
    status = s.status;
    realtime = s.realtime;
    max_force = s.max_force_output;
    worst = 0;
    for (const auto& x : states) worst = std::max(worst, true_intersections(c.scene, x));
    saved = static_cast<int>(states.size());
  }
  const double steps_per_s = static_cast<double>(status.sim_steps) / wall;
  const double ratio = status.sim_time / wall;
  state.counters["p50_us"] = p.p50_us;
  state.counters["p99_us"] = p.p99_us;
  state.counters["p999_us"] = p.p999_us;
  state.counters["max_us"] = p.max_us;
  state.counters["missed"] = static_cast<double>(p.missed);
  state.counters["work_max_us"] = work.max_us;
  state.counters["steps_per_s"] = steps_per_s;
  state.counters["rt_ratio"] = ratio;
  state.counters["true_intersections"] = worst;
  state.counters["contacts_max"] = most_contacts;
  const Case c = make_case(which);
  std::printf(
      "%s, %s: loop p50 %.1f / p99 %.1f / p99.9 %.1f / max %.1f us, missed %llu, over 2 ms %llu; tick work p99 %.1f / "
      "max %.1f us; physics %.0f "
      "steps/s, %.2f x real time (lag %.3f s, contacts %d at most / %d at the end, %d pinned); held vertex %d (meant %d), max "
      "force %.2f N; "
      "true intersections %d in %d states; SCHED_FIFO %s\n",
      c.name, async ? "async physics" : "inline physics", p.p50_us, p.p99_us, p.p999_us, p.max_us,
      static_cast<unsigned long long>(p.missed), static_cast<unsigned long long>(p.over_2ms), work.p99_us, work.max_us,
      steps_per_s, ratio,
      status.lag, most_contacts, status.contacts, status.pinned, grabbed, c.vertex, max_force, worst, saved, realtime ? "yes" : "no");
}

BENCHMARK(BM_LiveHapticDrag)
    ->ArgNames({"case", "async"})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({2, 1})
    ->Args({3, 1})
    ->Args({0, 0})
    ->Args({1, 0})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace s4d

BENCHMARK_MAIN();
