// `shadow4d soak --minutes N`: every scenario, in turn, live on the real 1 kHz loop with a replay
// device whose hand wanders, grabs and drops out (disconnects and reconnects), while random 4D
// turns, grabs, pins, explorations, ribbon strokes, undo / redo and autosaves are thrown at it;
// then the knot tools (strokes, crossing changes, undo). It reports what ran and everything that
// must never happen: a pass-through (judged by the independent checker, shape/mesh_checks.hpp),
// a non-finite force sent to the device, a non-finite value in a file.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <thread>
#include <utility>

#include "command.hpp"
#include "core/data_paths.hpp"
#include "core/error.hpp"
#include "haptics/trajectory_file.hpp"
#include "interact/session/autosave.hpp"
#include "interact/tools/knot_sketch_tool.hpp"
#include "interact/live/live_simulation.hpp"
#include "interact/tools/ribbon_tool.hpp"
#include "interact/session/session.hpp"
#include "interact/tools/view_edit.hpp"
#include "shape/mesh_checks.hpp"

namespace s4d::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct SoakArgs {
  double minutes = 1;
  std::string scenarios;  // empty: the program's examples (core/data_paths.hpp)
  std::string out;  // folder for the replay files and autosaves; empty: a temporary one
  unsigned seed = 1;
  bool json = false;
};

struct Totals {
  long long steps = 0, rounds = 0, grabs = 0, turns = 0, pins = 0, explorations = 0, ribbons = 0, ribbons_refused = 0;
  long long undos = 0, redos = 0, autosaves = 0, reconnects = 0, disconnects = 0, rollbacks = 0, freezes = 0;
  long long clamped = 0, nonfinite_requests = 0, nonfinite_to_device = 0, nonfinite_in_files = 0;
  long long checks = 0, pass_throughs = 0, knot_strokes = 0, crossing_changes = 0;
  // The longest loop period, and what tells its cause: the same loop's longest tick of its own
  // work (a stall inside a tick) and latest wake-up after a deadline (the CPU withheld).
  double worst_period_us = 0, worst_period_work_us = 0, worst_period_lateness_us = 0;
  std::string worst_period_round;
  double worst_work_us = 0;  // the longest tick's own work over every loop
  long long loops = 0, realtime_loops = 0;  // loops run, and those granted SCHED_FIFO
  std::vector<std::string> problems;
};

// A hand that wanders in the workspace, holds its button now and then, and drops out.
Trajectory wandering_hand(double seconds, std::mt19937& rng) {
  Trajectory t;
  t.header.device = "soak-hand";
  t.header.caps.max_force = 3.3;
  t.header.caps.max_continuous_force = 0.88;
  t.header.caps.max_stiffness = 1000;
  t.header.caps.max_force_rate = 1000;
  t.header.caps.outputs_force = true;
  const auto n = static_cast<std::size_t>(seconds * 1000);
  std::normal_distribution<double> jitter(0, 2e-4);
  std::uniform_real_distribution<double> u(0, 1);
  Vec3 p = Vec3::Zero(), v = Vec3::Zero();
  std::uint32_t buttons = 0;
  std::size_t gone_until = 0;
  for (std::size_t i = 0; i < n; ++i) {
    v = 0.995 * v + Vec3(jitter(rng), jitter(rng), jitter(rng));
    p = (p + v).cwiseMax(Vec3::Constant(-0.07)).cwiseMin(Vec3::Constant(0.07));
    if (u(rng) < 0.002) buttons ^= 1u;
    if (u(rng) < 0.0005) buttons ^= 2u;
    if (i >= gone_until && u(rng) < 0.0003) {
      gone_until = i + 50 + static_cast<std::size_t>(u(rng) * 400);  // 50-450 ms without the cable
    }
    TickRecord r;
    r.tick = i;
    for (int k = 0; k < 3; ++k) r.position[k] = r.target[k] = p[k];
    for (int k = 0; k < 3; ++k) r.velocity[k] = v[k] * 1000;
    r.buttons = buttons;
    if (i < gone_until) r.events = kEventDisconnected;
    t.ticks.push_back(r);
  }
  return t;
}

// Every surface of the scene as one mesh of R^4 (so pairs of objects are judged too), checked by
// the independent checker.
int independent_pass_throughs(const Session& s) {
  Surface<4> all;
  for (const SceneObject& obj : s.scene().objects) {
    Surface<4> one;
    if (const auto* s4 = std::get_if<Surface<4>>(&obj.shape)) one = *s4;
    else if (const auto* s3 = std::get_if<Surface<3>>(&obj.shape)) one = lift_to_4d(*s3);
    else continue;
    const int base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), one.vertices.begin(), one.vertices.end());
    for (Triangle t : one.triangles) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  return independent::self_intersections<4>(all).intersecting_pairs;
}

bool all_finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// The counters of the loop running now, folded into the totals when it is replaced or at the end.
struct LoopCounts {
  const HapticLoop* loop = nullptr;
  long long steps = 0, rollbacks = 0, freezes = 0, disconnects = 0, reconnects = 0, clamped = 0, nonfinite = 0;

  void see(const HapticLoop* now, const HapticSnapshot& snap, Totals& t, const std::string& round) {
    if (now != loop) {
      fold(t);
      ++t.loops;
      t.realtime_loops += snap.realtime ? 1 : 0;
    }
    loop = now;
    steps = snap.status.sim_steps;
    rollbacks = snap.status.rollbacks;
    freezes = snap.status.global_freezes;
    disconnects = static_cast<long long>(snap.disconnects);
    reconnects = static_cast<long long>(snap.reconnects);
    clamped = static_cast<long long>(snap.safety.clamped);
    nonfinite = static_cast<long long>(snap.safety.nonfinite);
    if (snap.period.max_us > t.worst_period_us) {
      t.worst_period_us = snap.period.max_us;
      t.worst_period_work_us = snap.work.max_us;
      t.worst_period_lateness_us = snap.period.worst_lateness_us;
      t.worst_period_round = round;
    }
    t.worst_work_us = std::max(t.worst_work_us, snap.work.max_us);
  }
  void fold(Totals& t) {
    t.steps += steps;
    t.rollbacks += rollbacks;
    t.freezes += freezes;
    t.disconnects += disconnects;
    t.reconnects += reconnects;
    t.clamped += clamped;
    t.nonfinite_requests += nonfinite;
    *this = LoopCounts{};
  }
};

void soak_scenario(const fs::path& scenario, double seconds, const fs::path& dir, std::mt19937& rng, Totals& t) {
  const fs::path replay = dir / (scenario.stem().string() + ".traj");
  write_trajectory(replay, wandering_hand(seconds + 5, rng));
  Session s;
  SessionOptions o;
  o.device = "replay:" + replay.string();
  s.open(load_document(scenario.string()), o);
  if (!s.simulating()) {
    t.problems.push_back(scenario.filename().string() + " did not simulate: " + s.physics_error() + s.device_error());
    return;
  }
  if (!s.device_error().empty()) {  // the soak's hand must be the one that drops out
    t.problems.push_back(scenario.filename().string() + ": the replay hand did not open: " + s.device_error());
    return;
  }
  s.send(live::Play{});
  Autosaver autosaver({dir / "autosave.s4d", 2.0, 2});
  RibbonTool ribbon;
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<int> plane(0, 5);
  const auto t0 = Clock::now();
  auto next_action = t0, next_check = t0 + std::chrono::seconds(1);
  int autosaves_seen = 0;
  // A new ribbon or an undo across it restarts the simulation with a new loop: what the old one
  // counted is kept by folding its last counts in whenever the loop changes.
  LoopCounts counts;
  while (Clock::now() - t0 < std::chrono::duration<double>(seconds)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    s.refresh();
    const HapticSnapshot* snap = s.snapshot();
    if (!snap) continue;
    counts.see(s.loop(), *snap, t, scenario.stem().string());
    if (!snap->force_output.allFinite()) ++t.nonfinite_to_device;
    const auto now = Clock::now();
    const int nv = snap->point_dimension > 0 ? static_cast<int>(snap->points.size()) / snap->point_dimension : 0;
    if (now >= next_action && nv > 0) {
      next_action = now + std::chrono::milliseconds(50 + static_cast<int>(u(rng) * 250));
      const double a = u(rng);
      std::uniform_int_distribution<int> vertex(0, nv - 1);
      if (a < 0.25) {
        const int v = vertex(rng);
        s.record("drag vertex " + std::to_string(v));
        s.send(live::Grab{v, u(rng) < 0.2 ? live::GrabMode::kAlongRay : live::GrabMode::kShadow, live::point(s.vertex_shadow(v))});
        ++t.grabs;
      } else if (a < 0.35) {
        s.send(live::Release{});
      } else if (a < 0.45) {
        s.record("turn in 4D");
        s.scene().frame.rotate(all_planes(4)[static_cast<std::size_t>(plane(rng))], (u(rng) - 0.5) * 0.6);
        s.send(live::SetFrame::from(s.scene().frame));
        ++t.turns;
      } else if (a < 0.55) {
        const int v = vertex(rng);
        s.record("pin vertex " + std::to_string(v));
        s.send(live::Pin{v, live::PinAction::kToggle});
        ++t.pins;
      } else if (a < 0.62) {
        if (s.undo()) {
          ++t.undos;
          s.send(live::Play{});
        }
      } else if (a < 0.67) {
        if (s.redo()) {
          ++t.redos;
          s.send(live::Play{});
        }
      } else if (a < 0.75 && s.dimension() == 4) {
        if (snap->status.exploring) s.send(live::StopExploring{});
        else s.send(live::StartExploring{live::point(s.vertex_shadow(vertex(rng)))});
        ++t.explorations;
      } else if (a < 0.77) {
        // A ribbon stroke across the scene, above or below where it passes other sheets.
        std::vector<RibbonStrokeSample> stroke;
        const Vec3 c = s.vertex_shadow(vertex(rng)), d = Vec3(u(rng) - 0.5, u(rng) - 0.5, 0).normalized();
        for (int i = 0; i < 60; ++i) stroke.push_back({c + (i / 59.0 - 0.5) * 3.0 * d + Vec3(0, 0, 0.3), i * 0.01, u(rng) < 0.5});
        if (ribbon.finish(stroke, Vec3::UnitZ(), 4.0, s)) {
          ++t.ribbons;
          s.send(live::Play{});
        } else {
          ++t.ribbons_refused;  // refused with a reason (a fold, contradictory choices): fine
        }
      } else if (a < 0.78) {
        s.send(live::SetPhysics::from(s.scene().physics));  // a settings round trip through the loop
      }
    }
    if (autosaver.tick(s, now)) ++t.autosaves;
    if (autosaver.saves() > autosaves_seen) {
      autosaves_seen = autosaver.saves();
      try {
        const SessionFile f = read_session(autosaver.path());
        if (!all_finite(f.simulation.positions) || !all_finite(f.simulation.velocities)) ++t.nonfinite_in_files;
      } catch (const std::exception& e) {
        ++t.nonfinite_in_files;
        t.problems.push_back(std::string("an autosave did not read back: ") + e.what());
      }
    }
    if (now >= next_check) {
      next_check = now + std::chrono::seconds(1);
      const int bad = independent_pass_throughs(s);
      ++t.checks;
      if (bad > 0) {
        t.pass_throughs += bad;
        t.problems.push_back(scenario.filename().string() + ": " + std::to_string(bad) + " triangle pair(s) meet at t = " +
                             std::to_string(snap->status.sim_time));
      }
    }
  }
  s.refresh();
  if (const HapticSnapshot* snap = s.snapshot()) counts.see(s.loop(), *snap, t, scenario.stem().string());
  counts.fold(t);
  ++t.rounds;
}

// The knot tools: strokes drawn through a camera, crossings changed, steps undone and redone.
void soak_knots(double seconds, std::mt19937& rng, Totals& t) {
  Session s;
  Document empty;  // named, not a braced temporary: gcc 12 -O3 sees its Scene's strings as uninitialised
  empty.spec = "knots";
  s.open(std::move(empty), SessionOptions{});
  const Vec2 window(800, 600);
  const Camera camera = make_camera(BoundingSphere{Vec3::Zero(), 2}, Eigen::Quaterniond::Identity(), 0, 35, 800.0 / 600, 1);
  std::uniform_real_distribution<double> u(0, 1);
  const auto t0 = Clock::now();
  while (Clock::now() - t0 < std::chrono::duration<double>(seconds)) {
    CursorKnotSketchTool tool;
    ToolInput in;
    in.view.camera = camera;
    in.view.window = window;
    const int lobes = 2 + static_cast<int>(u(rng) * 4);
    const double phase = u(rng) * 6.28;
    for (int i = 0; i < 200; ++i) {
      const double a = 2 * std::numbers::pi * 0.99 * i / 199;
      const double r = 150 + 90 * std::cos(lobes * a + phase);
      in.view.cursor = Vec2(400 + r * std::cos(a * (lobes - 1)), 300 + r * std::sin(a * (lobes - 1)));
      in.shift = u(rng) < 0.5;
      in.time = i * 0.01;
      if (i == 0) tool.press(in, s);
      else tool.drag(in, s);
    }
    tool.release(in, s);
    ++t.knot_strokes;
    if (!s.scene().objects.empty()) {
      s.scene().view.intersections = true;
      const ScreenCrossings c = screen_crossings(s.scene(), camera);
      if (!c.crossings.empty()) {
        const Vec2 n = camera.ndc(c.crossings[0].over);
        in.view.cursor = Vec2((n.x() + 1) / 2 * window.x(), (1 - n.y()) / 2 * window.y());
        std::string message;
        if (change_crossing_under(in.view, s, message)) ++t.crossing_changes;
      }
    }
    if (u(rng) < 0.5 && s.undo()) ++t.undos;
    if (u(rng) < 0.3 && s.redo()) ++t.redos;
    if (s.scene().objects.size() > 6) s.scene().objects.erase(s.scene().objects.begin());
  }
}

void soak(const SoakArgs& a) {
  const fs::path dir = a.out.empty() ? fs::temp_directory_path() / "shadow4d-soak" : fs::path(a.out);
  fs::create_directories(dir);
  const fs::path folder = a.scenarios.empty() ? data_dirs().scenarios : fs::path(a.scenarios);
  std::vector<fs::path> scenarios;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (e.path().extension() == ".json") scenarios.push_back(e.path());
  std::sort(scenarios.begin(), scenarios.end());
  if (scenarios.empty()) throw Error("no scenarios in " + folder.string() + " (give --scenarios DIR)");
  std::mt19937 rng(a.seed);
  Totals t;
  const double total = a.minutes * 60;
  const double round = std::clamp(total / (scenarios.size() + 1), 3.0, 120.0);
  const auto t0 = Clock::now();
  for (std::size_t k = 0; Clock::now() - t0 < std::chrono::duration<double>(total); ++k) {
    const std::size_t i = k % (scenarios.size() + 1);
    try {
      if (i == scenarios.size()) soak_knots(round, rng, t);
      else soak_scenario(scenarios[i], round, dir, rng, t);
    } catch (const std::exception& e) {
      t.problems.push_back(std::string("round ") + std::to_string(k) + ": " + e.what());
    }
  }
  // A problem (a scenario that did not simulate, an autosave that did not read back, a round that
  // threw) fails the soak as surely as a pass-through: each is work a user would have lost.
  const bool ok = t.pass_throughs == 0 && t.nonfinite_to_device == 0 && t.nonfinite_in_files == 0 && t.problems.empty();
  if (a.json) {
    nlohmann::ordered_json j{{"pass", ok}, {"minutes", a.minutes}, {"rounds", t.rounds}, {"steps", t.steps},
                             {"grabs", t.grabs}, {"turns", t.turns}, {"pins", t.pins}, {"explorations", t.explorations},
                             {"ribbons", t.ribbons}, {"ribbons_refused", t.ribbons_refused}, {"knot_strokes", t.knot_strokes},
                             {"crossing_changes", t.crossing_changes}, {"undos", t.undos}, {"redos", t.redos},
                             {"autosaves", t.autosaves}, {"disconnects", t.disconnects}, {"reconnects", t.reconnects},
                             {"rollbacks", t.rollbacks}, {"global_freezes", t.freezes},
                             {"worst_loop_period_us", t.worst_period_us},
                             {"worst_loop_period", {{"round", t.worst_period_round},
                                                    {"longest_tick_work_us", t.worst_period_work_us},
                                                    {"latest_wake_up_us", t.worst_period_lateness_us}}},
                             {"longest_tick_work_us", t.worst_work_us}, {"loops", t.loops},
                             {"realtime_loops", t.realtime_loops}, {"forces_clamped", t.clamped},
                             {"nonfinite_requests_stopped", t.nonfinite_requests},
                             {"nonfinite_to_device", t.nonfinite_to_device}, {"nonfinite_in_files", t.nonfinite_in_files},
                             {"independent_checks", t.checks}, {"pass_throughs", t.pass_throughs}, {"problems", t.problems}};
    std::cout << j.dump(2) << std::endl;
  } else {
    std::printf("soak: %s after %.1f min, %lld scenario rounds\n", ok ? "PASS" : "FAIL", a.minutes, t.rounds);
    std::printf("  physics steps %lld, rollbacks %lld, global freezes %lld\n", t.steps, t.rollbacks, t.freezes);
    std::printf("  grabs %lld, 4D turns %lld, pins %lld, explorations %lld, ribbons %lld (%lld refused with a reason)\n",
                t.grabs, t.turns, t.pins, t.explorations, t.ribbons, t.ribbons_refused);
    std::printf("  knot strokes %lld, crossing changes %lld, undos %lld, redos %lld, autosaves %lld\n", t.knot_strokes,
                t.crossing_changes, t.undos, t.redos, t.autosaves);
    std::printf("  device: %lld disconnects, %lld recoveries; forces clamped %lld\n", t.disconnects, t.reconnects,
                t.clamped);
    // Work near the period: a stall inside a tick; lateness near it: the CPU was withheld.
    std::printf("  worst loop period %.0f us (%s; that loop's longest tick of work %.0f us, latest wake-up %.0f us "
                "after its deadline); longest tick of work in any loop %.0f us; %lld of %lld loops real-time (SCHED_FIFO)\n",
                t.worst_period_us, t.worst_period_round.empty() ? "no loop" : t.worst_period_round.c_str(),
                t.worst_period_work_us, t.worst_period_lateness_us, t.worst_work_us, t.realtime_loops, t.loops);
    std::printf("  must be zero: pass-throughs %lld (in %lld independent checks), non-finite forces to the device %lld "
                "(%lld non-finite requests stopped by the safety layer), non-finite values in files %lld\n",
                t.pass_throughs, t.checks, t.nonfinite_to_device, t.nonfinite_requests, t.nonfinite_in_files);
    for (const std::string& p : t.problems) std::printf("  problem: %s\n", p.c_str());
  }
  if (!ok) throw ExitStatus{2};
}

const CommandRegistrar kSoak(
    "soak",
    "every scenario and the studios' tools, live, under random use for N minutes; exit 2 if anything must-never "
    "happened (example: shadow4d soak --minutes 30)",
    [](CLI::App& sub) {
      auto a = std::make_shared<SoakArgs>();
      sub.add_option("--minutes", a->minutes, "how long")->check(CLI::Range(0.05, 1e4));
      sub.add_option("--scenarios", a->scenarios, "folder of scenario files (default: the installed examples)");
      sub.add_option("--out", a->out, "folder for the replay files and autosaves");
      sub.add_option("--seed", a->seed, "of the random use");
      sub.add_flag("--json", a->json, "the report as JSON");
      sub.callback([a] { soak(*a); });
    });

}  // namespace
}  // namespace s4d::cli
