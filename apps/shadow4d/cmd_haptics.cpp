// `shadow4d haptics`: runs the haptic loop headless with a device (sim, mouse, replay, spacenav,
// openhaptics) on the sticky plane or a 4D cloth (a live simulation, interact/haptic_scenes),
// optionally recording, and prints its statistics.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "command.hpp"
#include "core/error.hpp"
#include "haptics/device_spec.hpp"
#include "haptics/haptic_loop.hpp"
#include "haptics/haptic_session.hpp"
#include "haptics/replay_device.hpp"
#include "haptics/simulated_arm.hpp"
#include "interact/live/haptic_scenes.hpp"

namespace s4d::cli {
namespace {

struct HapticsArgs {
  std::string device = "sim";
  double seconds = 5;
  double rate = 1000;
  std::string record;
  bool json = false;
  HapticSceneChoice scene;
  bool no_collisions = false;
  bool no_realtime = false;
};

nlohmann::json summary_json(const PeriodSummary& p) {
  return {{"ticks", p.ticks},       {"nominal_us", p.nominal_us}, {"p50_us", p.p50_us},
          {"p99_us", p.p99_us},     {"p999_us", p.p999_us},       {"max_us", p.max_us},
          {"mean_us", p.mean_us},   {"missed", p.missed},         {"over_2ms", p.over_2ms},
          {"worst_lateness_us", p.worst_lateness_us}};
}

// The scene construction a replay needs beyond the parameters: "cloth_n=64 collisions=1 async=0".
std::string format_setup(const HapticSceneChoice& c) {
  return "cloth_n=" + std::to_string(c.cloth_n) + " collisions=" + (c.collisions ? "1" : "0") +
         " async=" + (c.async_physics ? "1" : "0");
}

void parse_setup(const std::string& setup, HapticSceneChoice& c) {
  std::istringstream in(setup);
  std::string item;
  while (in >> item) {
    const auto eq = item.find('=');
    const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
    try {
      if (key == "cloth_n") c.cloth_n = std::stoi(value);
      else if (key == "collisions") c.collisions = value != "0";
      else if (key == "async") c.async_physics = value != "0";  // only reported: replays run synchronously
    } catch (const std::exception&) {
      throw Error("replay: bad setup item '" + item + "' in the recording");
    }
  }
}

// A recording of the cloth made before it ran as a live simulation (scene "rubber-band"): its band
// held the nearest vertex without a button and pulled it differently, so the replay drives the
// cloth of today with that hand but its forces are not comparable.
bool is_legacy_cloth(const std::string& recorded_scene) { return recorded_scene == "rubber-band"; }

// What a run of the loop leaves to report: the loop's last snapshot and what the set-up decided.
struct HapticsRun {
  std::string device, scene, record;
  double rate_hz = 0, wall = 0;
  std::uint64_t ticks = 0;
  bool async_physics = false;
  const HapticSnapshot* snapshot = nullptr;
  const ReplayDevice* replay = nullptr;  // a replay's device (owned by the loop), else null
  bool recorded_async = false, legacy = false;
  std::vector<std::string> skipped_params;
};

void print_json(const HapticsRun& r) {
  const HapticSnapshot& s = *r.snapshot;
  const SceneStatus& st = s.status;
  nlohmann::json j = {{"device", r.device},
                      {"scene", r.scene},
                      {"rate_hz", r.rate_hz},
                      {"wall_seconds", r.wall},
                      {"ticks", r.ticks},
                      {"realtime_priority", s.realtime},
                      {"device_connected", s.device_connected},
                      {"max_force_n", s.max_force_output},
                      {"safety",
                       {{"phase", safety_phase_name(s.safety_phase)},
                        {"clamped", s.safety.clamped},
                        {"rate_limited", s.safety.rate_limited},
                        {"nonfinite", s.safety.nonfinite},
                        {"disarms", s.safety.disarms}}}};
  if (!r.replay) {
    j["period"] = summary_json(s.period);
    j["work"] = summary_json(s.work);
  }
  if (st.simulating)
    j["physics"] = {{"steps", st.sim_steps},       {"simulated_seconds", st.sim_time},
                    {"lag_seconds", st.lag},       {"held_vertex", st.held_vertex},
                    {"pinned", st.pinned},         {"contacts", st.contacts},
                    {"async", r.async_physics}};
  if (!r.record.empty()) j["recorded"] = {{"file", r.record}, {"ticks", r.ticks}};
  if (r.replay)
    j["replay"] = {{"compared", r.replay->compared()},
                   {"mismatches", r.replay->mismatches()},
                   {"recorded_async_physics", r.recorded_async},
                   {"recorded_rubber_band", r.legacy}};
  std::cout << j.dump(2) << "\n";
}

void print_text(const HapticsRun& r) {
  const HapticSnapshot& s = *r.snapshot;
  const SceneStatus& st = s.status;
  std::printf("haptics: device %s, scene %s, %.0f Hz, %llu ticks in %.2f s (real-time priority: %s)\n",
              r.device.c_str(), r.scene.c_str(), r.rate_hz,
              static_cast<unsigned long long>(r.ticks), r.wall, s.realtime ? "yes" : "no");
  if (!r.replay) {
    const PeriodSummary& p = s.period;
    std::printf("  period: p50 %.1f us, p99 %.1f us, p99.9 %.1f us, max %.1f us, mean %.1f us\n", p.p50_us,
                p.p99_us, p.p999_us, p.max_us, p.mean_us);
    std::printf("  missed deadlines %llu, periods over 2 ms %llu, worst wake-up lateness %.1f us\n",
                static_cast<unsigned long long>(p.missed), static_cast<unsigned long long>(p.over_2ms),
                p.worst_lateness_us);
    std::printf("  tick work: p50 %.1f us, p99 %.1f us, max %.1f us\n", s.work.p50_us, s.work.p99_us,
                s.work.max_us);
  }
  std::printf("  force: max %.3f N; safety %s (clamped %llu, rate-limited %llu, non-finite %llu)\n",
              s.max_force_output, safety_phase_name(s.safety_phase),
              static_cast<unsigned long long>(s.safety.clamped),
              static_cast<unsigned long long>(s.safety.rate_limited),
              static_cast<unsigned long long>(s.safety.nonfinite));
  if (st.simulating) {
    std::printf("  physics%s: %lld steps, %.3f s simulated", r.async_physics ? " (own thread)" : "",
                static_cast<long long>(st.sim_steps), st.sim_time);
    if (!r.replay) std::printf(" in %.2f s (%.2f x real time), lag %.3f s", r.wall, st.sim_time / r.wall, st.lag);
    std::printf("; held vertex %d, %d pinned, %d contacts\n", st.held_vertex, st.pinned, st.contacts);
  }
  if (!r.record.empty())
    std::printf("  recorded %llu ticks to %s\n", static_cast<unsigned long long>(r.ticks),
                r.record.c_str());
  if (r.replay)
    std::printf("  replay: %llu forces compared with the recording, %llu differ%s\n",
                static_cast<unsigned long long>(r.replay->compared()),
                static_cast<unsigned long long>(r.replay->mismatches()),
                r.replay->mismatches() ? "" : " (bit-identical)");
  if (r.replay && r.legacy) {
    std::printf(
        "  (recorded with the rubber-band cloth of before the live simulation: it held a vertex without a\n"
        "   button and pulled it differently, so its forces cannot match and the replay does not fail on them");
    for (std::size_t i = 0; i < r.skipped_params.size(); ++i)
      std::printf("%s%s", i ? ", " : "; parameters not set: ", r.skipped_params[i].c_str());
    std::printf(")\n");
  }
  if (r.replay && r.recorded_async)
    std::printf(
        "  (recorded with --async-physics: the simulation's timing was not recorded, forces may differ)\n");
}

void run(const HapticsArgs& a) {
  const DeviceSpec spec = parse_device_spec(a.device);
  std::unique_ptr<Device> device = make_device(spec);
  HapticSceneChoice choice = a.scene;
  choice.collisions = !a.no_collisions;  // (a replay takes these from its recording)
  HapticLoopConfig cfg;
  cfg.rate_hz = a.rate;
  cfg.realtime_priority = !a.no_realtime;
  auto* replay = dynamic_cast<ReplayDevice*>(device.get());
  std::uint64_t replay_ticks = 0;
  bool recorded_async = false;  // the recording's cloth ran on its own thread: forces cannot match
  bool legacy = false;          // recorded with the older rubber-band cloth: forces cannot match
  std::vector<std::string> skipped_params;
  if (replay) {  // rebuild what was recorded: rate, scene, parameters
    const TrajectoryHeader& h = replay->trajectory().header;
    cfg.rate_hz = h.rate;
    choice.name = h.scene == "generated" ? "plane" : h.scene;
    legacy = is_legacy_cloth(h.scene);
    parse_setup(replay->trajectory().header.setup, choice);
    recorded_async = choice.async_physics;
    choice.async_physics = false;  // replays must be deterministic
    replay_ticks = replay->trajectory().ticks.size();
  }
  if (!(a.seconds > 0) || a.seconds > 24 * 3600) throw Error("--seconds must be in (0, 86400]");
  HapticSceneSetup setup = make_haptic_scene(choice);
  std::unique_ptr<HapticScene> scene = std::move(setup.scene);
  if (replay)
    for (const auto& [name, value] : replay->trajectory().header.params) {
      const int i = scene->find_param(name);
      if (i < 0 && legacy) {
        skipped_params.push_back(name);
        continue;
      }
      if (i < 0)
        throw Error("replay: the recording sets parameter '" + name + "' unknown to scene " + choice.name);
      scene->set_param(i, value);
    }
  const Vec3 start = setup.hand_start;
  const double press = setup.press;
  const bool holds = setup.held_vertex >= 0;  // the hand holds button 1 on a cloth vertex
  const bool is_arm = dynamic_cast<SimulatedArm*>(device.get()) != nullptr;
  if (auto* arm = dynamic_cast<SimulatedArm*>(device.get())) {
    arm->set_position(start);
    arm->set_hand_script([start, press](double t) { return demo_hand_path(t, start, press); });
  }
  const std::string scene_name(scene->name());
  HapticLoop loop(std::move(device), std::move(scene), cfg);
  if (!a.record.empty()) loop.record_to(a.record, format_setup(choice));
  // The simulated arm's button: held from the first tick, where the arm starts on the vertex.
  if (is_arm && holds) loop.set_pointer(start, 1u);

  const auto t0 = std::chrono::steady_clock::now();
  if (replay) {
    // Deterministic: every recorded tick through the same tick function, as fast as it goes.
    loop.run_ticks(replay_ticks);
  } else {
    loop.start();
    const bool drive_pointer = spec.kind == DeviceSpec::Kind::mouse;
    const auto end = t0 + std::chrono::duration<double>(a.seconds);
    while (std::chrono::steady_clock::now() < end) {
      if (drive_pointer) {  // a headless "user" moving the cursor, as the GUI would
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        // The button goes down once the proxy has reached the start (the path rests there 0.3 s) and
        // takes the vertex under it.
        loop.set_pointer(demo_hand_path(t, start, press), holds && t > 0.2 ? 1u : 0u);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    loop.stop();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  loop.finish_recording();
  HapticsRun r{to_string(spec), scene_name, a.record, cfg.rate_hz, wall, loop.ticks(), choice.async_physics,
               &loop.snapshot(), replay, recorded_async, legacy, skipped_params};
  if (a.json) print_json(r);
  else print_text(r);
  if (replay && replay->mismatches() > 0 && !recorded_async && !legacy) throw ExitStatus{2};
}

const CommandRegistrar kHaptics(
    "haptics", "run the haptic loop headless with a device and print its period statistics",
    [](CLI::App& sub) {
      auto a = std::make_shared<HapticsArgs>();
      sub.add_option("--device", a->device, kDeviceSpecHelp)->capture_default_str();
      sub.add_option("--seconds", a->seconds, "how long to run (live devices)")->capture_default_str();
      sub.add_option("--rate", a->rate, "servo rate, Hz")->capture_default_str();
      sub.add_option("--record", a->record, "record the device stream and forces to this file");
      sub.add_flag("--json", a->json, "print the statistics as JSON");
      sub.add_option("--scene", a->scene.name, kHapticSceneHelp)->capture_default_str();
      sub.add_option("--cloth-n", a->scene.cloth_n, "vertices per side of the 4D cloth")
          ->capture_default_str();
      sub.add_flag("--no-collisions", a->no_collisions, "cloth without collision avoidance");
      sub.add_flag("--async-physics", a->scene.async_physics,
                   "step the cloth's World on its own thread so a slow simulation cannot stall the loop");
      sub.add_flag("--no-realtime", a->no_realtime, "do not ask for SCHED_FIFO");
      sub.callback([a] { run(*a); });
    });

}  // namespace
}  // namespace s4d::cli
