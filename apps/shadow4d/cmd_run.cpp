// `shadow4d run <scenario.json>`: runs one of the paper's scenarios headless and prints its
// one-line verdict (exit code 0 on PASS, 3 on FAIL); saves PNG frames, final meshes and
// metrics.json along the way.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "command.hpp"
#include "demo_report.hpp"
#include "core/data_paths.hpp"
#include "core/error.hpp"
#include "core/plane.hpp"
#include "io/image.hpp"
#include "io/object_file.hpp"
#include "render/renderer.hpp"
#include "scenario/scenario_run.hpp"

namespace s4d::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

struct RunArgs {
  std::string scenario;
  std::string out = "scenario-out";
  int frames = -1;
  bool no_png = false;
  bool hash = false;
};

Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

// The scenario's file as given, else an example by path or by name ("spun-trefoil-tighten").
fs::path scenario_file(const std::string& spec) {
  const fs::path found = find_example(spec);
  if (fs::path(spec).has_extension() || fs::exists(found)) return found;
  const fs::path named = find_example(spec + ".json");
  return fs::exists(named) ? named : found;
}

void run(const RunArgs& args) {
  const Scenario sc = load_scenario(scenario_file(args.scenario));
  const auto run = ScenarioRun::make(sc);
  const int frames = args.frames > 0 ? args.frames : sc.frames;
  const fs::path out = args.out;
  fs::create_directories(out);
  bool png = !args.no_png;
  std::string png_error;
  Json frame_log = Json::array();
  int total_intersections = 0;
  double min_gap = std::numeric_limits<double>::infinity();

  auto save_frame = [&](int k) {
    const EmbeddingCheck c = run->check();
    total_intersections += c.intersections;
    min_gap = std::min(min_gap, c.min_gap);
    Json f{{"frame", k}, {"time", run->time()}, {"intersections", c.intersections}, {"min_gap", finite_or_null(c.min_gap)}};
    if (!png) {
      frame_log.push_back(f);
      return;
    }
    Scene scene = run->current_scene();
    // Show the shadow the verdict judges, when it names a view.
    if (!sc.verdict.view.empty()) {
      scene.frame = Frame<4>();
      apply_rotations(scene.frame, parse_rotation_list(sc.verdict.view, 4));
    }
    char name[32];
    std::snprintf(name, sizeof name, "frame_%03d.png", k);
    try {
      write_png(render_offscreen(scene, 480, 360), out / name);
      f["png"] = name;
    } catch (const Error& e) {
      png = false;  // no OpenGL here: keep simulating, say so in the metrics
      png_error = e.what();
    }
    frame_log.push_back(f);
  };

  const long steps = run->total_steps();
  const auto wall0 = std::chrono::steady_clock::now();
  save_frame(0);
  int next_frame = 1;
  for (long s = 1; s <= steps; ++s) {
    run->step();
    if (s * frames >= next_frame * steps) save_frame(next_frame++);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();

  const VerdictResult v = run->verdict();
  const bool embedded = total_intersections == 0 && min_gap > 0;
  const bool ok = v.pass && embedded;
  const Scene final_scene = run->current_scene();
  for (const SceneObject& o : final_scene.objects)
    if (is_surface(o.shape)) write_shape_file(o.shape, out / ("final_" + o.name + native_extension(o.shape)));
  const PhysicsWarnings& w = run->warnings();
  const ModelFacts m = run->facts();
  const double ms = 1e3 * wall / std::max<long>(1, steps);
  // Which view the frames are drawn in (the window opens a scenario in its own frame).
  const std::string view = sc.verdict.view.empty()
                               ? "the scenario's own frame (the window's first view)"
                               : "turned " + sc.verdict.view + " from the scenario's frame (the shadow its verdict judges)";
  Json metrics{{"scenario", sc.name}, {"dim", sc.dim}, {"pass", ok}, {"vertices", m.vertices},
               {"triangles", m.triangles}, {"springs", m.springs}, {"steps", steps}, {"time_step", m.time_step},
               {"wall_seconds", wall}, {"ms_per_step", ms}, {"contact_thickness", m.contact_thickness},
               {"hard_thickness", m.hard_thickness}, {"integrator", m.integrator},
               {"true_intersections", total_intersections}, {"min_gap", finite_or_null(min_gap)},
               {"state_hash", run->state_hash()},
               {"warnings", {{"rollbacks", w.rollbacks}, {"speed_clamps", w.speed_clamps},
                             {"ccd_freezes", w.ccd_freezes}, {"global_freezes", w.global_freezes}}},
               {"verdict", v.numbers}, {"frames", frame_log}};
  if (!png_error.empty()) metrics["png_error"] = png_error;
  metrics["view"] = view;
  std::ofstream(out / "metrics.json") << metrics.dump(2) << "\n";

  RunFacts facts;
  facts.name = sc.name;
  facts.verdict = v;
  facts.checks = static_cast<int>(frame_log.size());
  facts.intersections = total_intersections;
  facts.min_gap = min_gap;
  facts.model = m;
  facts.steps = steps;
  facts.ms_per_step = ms;
  facts.warnings = w;
  std::cout << verdict_line(facts) << std::endl;
  std::cout << "view: " << view << std::endl;
  if (args.hash) {
    char h[32];
    std::snprintf(h, sizeof h, "%016llx", static_cast<unsigned long long>(run->state_hash()));
    std::cout << "state hash after " << steps << " steps: " << h << std::endl;
  }
  if (!ok) throw ExitStatus{3};
}

const CommandRegistrar kRun(
    "run", "run a physics scenario (scenarios/*.json): PNG frames, final meshes, metrics, verdict",
    [](CLI::App& sub) {
      auto args = std::make_shared<RunArgs>();
      sub.add_option("scenario", args->scenario,
                     "scenario file, or the name of an installed one (spun-trefoil-tighten)")
          ->required();
      sub.add_option("--out,-o", args->out, "output directory (frames, final meshes, metrics.json)");
      sub.add_option("--frames", args->frames, "frames to save (default: the scenario's)")
          ->check(CLI::Range(1, 1000));
      sub.add_flag("--no-png", args->no_png, "skip rendering (checks and metrics still run per frame)");
      sub.add_flag("--hash", args->hash, "print the world's state hash at the end (determinism checks)");
      sub.callback([args] { run(*args); });
    });

}  // namespace
}  // namespace s4d::cli
