// `shadow4d run <scenario.json>`: runs one of the paper's scenarios headless and prints its
// one-line verdict (exit code 0 on PASS, 3 on FAIL).
#include <iostream>

#include "command.hpp"
#include "scenario_run.hpp"
#include "scenario_spec.hpp"

namespace s4d::cli {
namespace {

struct RunArgs {
  std::string scenario;
  std::string out = "scenario-out";
  int frames = -1;
  bool no_png = false;
};

const CommandRegistrar kRun(
    "run", "run a physics scenario (scenarios/*.json): PNG frames, final meshes, metrics, verdict",
    [](CLI::App& sub) {
      auto args = std::make_shared<RunArgs>();
      sub.add_option("scenario", args->scenario, "scenario file (see scenarios/)")->required();
      sub.add_option("--out,-o", args->out, "output directory (frames, final meshes, metrics.json)");
      sub.add_option("--frames", args->frames, "frames to save (default: the scenario's)")
          ->check(CLI::Range(1, 1000));
      sub.add_flag("--no-png", args->no_png, "skip rendering (checks and metrics still run per frame)");
      sub.callback([args] {
        const scenario::ScenarioSpec spec = scenario::load_scenario(args->scenario);
        scenario::RunOptions opt;
        opt.out_dir = args->out;
        opt.frames = args->frames;
        opt.png = !args->no_png;
        const scenario::RunResult r = scenario::run_scenario(spec, opt);
        std::cout << r.line << std::endl;
        if (!r.pass) throw ExitStatus{3};
      });
    });

}  // namespace
}  // namespace s4d::cli
