// The metrics the demo prints for a rendered scene: per object its size and topology, and the
// picture's coverage, so a reader can tell at a glance that the right thing was drawn; and for
// an experiment (a scenario run) the verdict line `shadow4d run` prints.
#pragma once
#include <limits>
#include <string>

#include "io/image.hpp"
#include "io/scene.hpp"
#include "scenario/scenario_run.hpp"

namespace s4d::cli {

std::string describe_scene(const Scene& scene, const Image& image, double render_ms);
// Fraction of pixels that differ from the top-left (background) pixel.
double coverage(const Image& image);

// What a scenario run measured: its verdict, and the exact embedding check of the states
// looked at (intersections summed over them, the smallest gap among them).
struct RunFacts {
  std::string name;
  VerdictResult verdict;
  int checks = 0;         // states checked
  int intersections = 0;  // true intersections, summed over the states checked
  double min_gap = std::numeric_limits<double>::infinity();
  ModelFacts model;
  long steps = 0;
  double ms_per_step = 0;  // ms of wall time a physics step (checks and drawing left out)
  PhysicsWarnings warnings;
  // PASS needs the verdict, no true intersection and a positive gap, as `shadow4d run` says.
  bool pass() const { return verdict.pass && intersections == 0 && min_gap > 0; }
};
// "PASS name: detail; 0 true intersections in 201 states checked (min gap 0.03, hard layer
// 0.0075); ...": the line `shadow4d run` (which checks its saved frames) and the demo print.
std::string verdict_line(const RunFacts& facts);

}  // namespace s4d::cli
