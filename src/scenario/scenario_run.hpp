// Runs a scenario: builds the world, drives the scripted tool, saves frames, final meshes and
// metrics, checks every saved frame for true intersections, and computes the verdict.
#pragma once
#include <filesystem>
#include <string>

#include "scenario_spec.hpp"

namespace s4d::scenario {

struct RunOptions {
  std::filesystem::path out_dir = "scenario-out";
  int frames = -1;        // -1: the scenario's own count
  bool png = true;        // render PNG frames (needs EGL / llvmpipe)
  int png_width = 480, png_height = 360;
};

struct RunResult {
  bool pass = false;
  std::string line;       // the one-line verdict, starting with PASS or FAIL
};

// Throws s4d::Error for scenarios that cannot be built (bad generator parameters, intersecting
// start); a scenario that runs but misses its outcome returns pass = false.
RunResult run_scenario(const ScenarioSpec& spec, const RunOptions& options);

}  // namespace s4d::scenario
