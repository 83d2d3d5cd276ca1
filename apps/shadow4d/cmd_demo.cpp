// `shadow4d demo`: the headless main job. Renders the paper's objects (scenes/*.json) to PNG and
// prints, for each, where the picture is and the object's measured facts; then runs two of the
// paper's experiments (scenarios/*.json) and draws each as a contact sheet of frames, with the
// verdict `shadow4d run` would print.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "command.hpp"
#include "core/data_paths.hpp"
#include "core/error.hpp"
#include "core/plane.hpp"
#include "demo_report.hpp"
#include "io/image.hpp"
#include "io/scene.hpp"
#include "render/renderer.hpp"
#include "render/scene_geometry.hpp"
#include "scenario/scenario_run.hpp"
#include "view_options.hpp"

namespace s4d::cli {
namespace {

namespace fs = std::filesystem;

struct DemoArgs {
  std::string out = "shadow4d-demo";
  std::string scenes;     // empty: the program's examples (core/data_paths.hpp)
  std::string scenarios;  // the same
  std::string frame_size = "320x240";
  ViewOptions view;
};

// The paper's objects, in the order its figures show them.
constexpr const char* kDemoScenes[] = {
    "trefoil-knot",       // Fig. 1: a knot as a lit tube
    "trefoil-ribbon-3d",  // Fig. 10a: a knot tied in a 3D ribbon
    "trefoil-ribbon-4d",  // Fig. 10b: the same ribbon in R^4
    "spun-trefoil",       // Fig. 11: the knotted sphere
    "clifford-torus",     // Fig. 12: the flat torus and its pinch lines
    "cloth",              // Fig. 13: cloth
    "sphere-and-ribbon",  // Fig. 14: a ribbon linked with a sphere
    "chain",              // Fig. 8: a 4D chain
};

// The paper's experiments the demo runs to the end of their duration, each drawn as one contact
// sheet of kSheetFrames frames: evenly spaced from t = 0 to `frames_until` and the last at the
// end, or, with frames_until = 0, evenly spaced over the whole duration.
struct Experiment {
  const char* scenario;  // scenarios/<scenario>.json
  const char* sheet;     // the contact sheet's file name
  const char* figure;    // where the paper shows it
  // One camera for every frame, framing them all, so the motion shows as it is. Off for a shape
  // that grows many times over (the ribbon pulled straight is a thin line beside its knot): each
  // frame then fits its own shadow and its label gives its zoom against the first.
  bool shared_camera;
  double frames_until;  // s; where the change happens, when it is over well before the end
};
constexpr Experiment kExperiments[] = {
    {"spun-trefoil-tighten", "demo-spun-trefoil-pull.png", "Fig. 11a-b", true, 0},
    // The knot has fallen open by 2 s; the pull goes on to 3 s and the verdict is taken at 4 s.
    {"ribbon-falls-apart-4d", "demo-ribbon-falls-apart.png", "Fig. 10b", false, 2.0},
};
constexpr int kSheetFrames = 6;
// Steps between exact embedding checks: the sheet's frames are checked, and every state between
// them this often, so "never passes through itself" is measured, not only drawn.
constexpr long kCheckEvery = 10;

std::pair<int, int> parse_frame_size(const std::string& size) {
  int w = 0, h = 0;
  char extra = 0;
  if (std::sscanf(size.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 16 || h < 16 || w > 2048 || h > 2048)
    throw Error("--frame-size '" + size + "' should be WxH with 16..2048 pixels each, e.g. 320x240");
  return {w, h};
}

// A ball holding every one of `balls`, so that all the frames of a sheet share one camera and the
// motion shows (the renderer would otherwise fit each frame to its own shadow).
BoundingSphere enclosing(const std::vector<BoundingSphere>& balls) {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const BoundingSphere& b : balls) {
    lo = lo.cwiseMin(b.centre - Vec3::Constant(b.radius));
    hi = hi.cwiseMax(b.centre + Vec3::Constant(b.radius));
  }
  BoundingSphere all{0.5 * (lo + hi), 0};
  for (const BoundingSphere& b : balls)
    all.radius = std::max(all.radius, (b.centre - all.centre).norm() + b.radius);
  return all;
}

std::string fixed(double x, int decimals) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", decimals, x);
  return b;
}

struct ExperimentResult {
  RunFacts facts;
  Image sheet;
};

// Runs the scenario to its end, keeping kSheetFrames states drawn as the shadow its verdict
// judges; those and every kCheckEvery-th state are checked exactly (true intersections, gap).
ExperimentResult run_experiment(const Experiment& x, const fs::path& path, const ViewOptions& view,
                                int frame_w, int frame_h) {
  const Scenario sc = load_scenario(path);
  const auto run = ScenarioRun::make(sc);
  RunFacts facts;
  facts.name = sc.name;
  facts.steps = run->total_steps();
  std::vector<Scene> shots;
  std::vector<std::string> labels;
  auto check = [&] {
    const EmbeddingCheck c = run->check();
    ++facts.checks;
    facts.intersections += c.intersections;
    facts.min_gap = std::min(facts.min_gap, c.min_gap);
    return c;
  };
  auto keep = [&](const EmbeddingCheck& c) {
    Scene scene = run->current_scene();
    if (!sc.verdict.view.empty()) {
      scene.frame = Frame<4>();
      apply_rotations(scene.frame, parse_rotation_list(sc.verdict.view, 4));
    }
    view.apply(scene);
    shots.push_back(std::move(scene));
    labels.push_back("t = " + fixed(run->time(), 2) + " s" + (c.intersections ? ", MEETS ITSELF" : ""));
  };
  double step_ms = 0;
  // The step of each frame after the first.
  std::vector<long> at;
  const double dt = sc.scene.physics.time_step;
  const long until =
      x.frames_until > 0 ? std::min(facts.steps, std::lround(x.frames_until / dt)) : facts.steps;
  const int spaced = x.frames_until > 0 ? kSheetFrames - 2 : kSheetFrames - 1;
  for (int k = 1; k <= spaced; ++k) at.push_back(until * k / spaced);
  if (x.frames_until > 0) at.push_back(facts.steps);
  keep(check());
  for (const long step : at) {
    while (run->steps() < step) {
      const auto t0 = std::chrono::steady_clock::now();
      run->step();
      step_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      if (run->steps() % kCheckEvery == 0 && run->steps() != step) check();
    }
    keep(check());
  }
  facts.ms_per_step = step_ms / static_cast<double>(std::max(1L, facts.steps));
  facts.verdict = run->verdict();
  facts.model = run->facts();
  facts.warnings = run->warnings();

  std::vector<BoundingSphere> balls;
  const double aspect = static_cast<double>(frame_w) / frame_h;
  for (const Scene& s : shots) balls.push_back(build_scene_geometry(s, aspect).bounds);
  const BoundingSphere all = enclosing(balls);
  std::vector<Image> frames;
  for (std::size_t i = 0; i < shots.size(); ++i) {
    if (x.shared_camera) {
      shots[i].view.fit_centre = all.centre;
      shots[i].view.fit_radius = all.radius;
    } else if (i > 0 && balls[i].radius > 0) {
      labels[i] += ", zoom " + fixed(balls[0].radius / balls[i].radius, 2);
    }
    frames.push_back(render_offscreen(shots[i], frame_w, frame_h));
  }
  char gap[96];
  std::snprintf(gap, sizeof gap, "%d true intersections in %d states checked, min gap %.3g",
                facts.intersections, facts.checks, facts.min_gap);
  const std::string title = std::string(facts.pass() ? "PASS " : "FAIL ") + sc.name + ": " + sc.instruction +
                            "\n" + gap + "; " + facts.verdict.detail;
  return {facts, contact_sheet(frames, labels, title)};
}

const CommandRegistrar kDemo(
    "demo",
    "render the paper's objects to PNG files headless and print their metrics; run two of its "
    "experiments and draw each as a contact sheet of frames, with its verdict",
    [](CLI::App& sub) {
      auto args = std::make_shared<DemoArgs>();
      args->view.size = "800x600";
      sub.add_option("--out,-o", args->out, "folder for the PNG files")->capture_default_str();
      sub.add_option("--scenes", args->scenes, "folder holding the scene files (default: the installed examples)");
      sub.add_option("--scenarios", args->scenarios,
                     "folder holding the scenario files (default: the installed examples)");
      sub.add_option("--frame-size", args->frame_size,
                     "size WxH of each frame of the experiments' contact sheets")
          ->capture_default_str();
      args->view.add_to(sub);
      sub.callback([args] {
        const fs::path scenes = args->scenes.empty() ? data_dirs().scenes : fs::path(args->scenes);
        const fs::path scenarios = args->scenarios.empty() ? data_dirs().scenarios : fs::path(args->scenarios);
        fs::create_directories(args->out);
        const auto [w, h] = args->view.parsed_size();
        const auto [fw, fh] = parse_frame_size(args->frame_size);
        int failures = 0;
        for (const char* name : kDemoScenes) {
          const fs::path scene_path = scenes / (std::string(name) + ".json");
          const fs::path png = fs::path(args->out) / (std::string(name) + ".png");
          try {
            Scene scene = load_scene(scene_path);
            args->view.apply(scene);
            const auto t0 = std::chrono::steady_clock::now();
            const Image image = render_offscreen(scene, w, h);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            write_png(image, png);
            std::cout << png.string() << "\n" << describe_scene(scene, image, ms);
          } catch (const std::exception& e) {
            ++failures;
            std::cerr << "demo: " << name << ": " << e.what() << "\n";
          }
        }
        int passed = 0;
        for (const Experiment& x : kExperiments) {
          const fs::path png = fs::path(args->out) / x.sheet;
          try {
            const ExperimentResult r = run_experiment(
                x, scenarios / (std::string(x.scenario) + ".json"), args->view, fw, fh);
            write_png(r.sheet, png);
            std::cout << png.string() << "\n  " << x.scenario << " (paper " << x.figure
                      << "): " << kSheetFrames << " frames of " << fw << "x" << fh << " over "
                      << r.facts.steps << " steps, sheet " << r.sheet.width << "x" << r.sheet.height << "\n  "
                      << verdict_line(r.facts) << "\n";
            if (r.facts.pass()) ++passed;
          } catch (const std::exception& e) {
            std::cerr << "demo: " << x.scenario << ": " << e.what() << "\n";
          }
        }
        std::cout << "demo: " << (std::size(kDemoScenes) - failures) << " of " << std::size(kDemoScenes)
                  << " pictures and " << passed << " of " << std::size(kExperiments)
                  << " experiments (PASS) written to " << fs::absolute(args->out).string() << "\n";
        if (failures || passed < static_cast<int>(std::size(kExperiments))) throw ExitStatus{1};
      });
    });

}  // namespace
}  // namespace s4d::cli
