// Scenario files (scenarios/*.json): objects, physics, a scripted tool and the outcome to check.
// This is the data side of `shadow4d run`; scenario_run.cpp executes it.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "physics/model.hpp"
#include "shape/generators.hpp"

namespace s4d::scenario {

struct ObjectSpec {
  std::string name;
  GeneratorCall generator;
  double scale = 1;
  std::vector<double> matrix;                   // 16 numbers, row-major 4 × 4 linear map (optional)
  std::vector<int> mirror;                      // axes whose sign is flipped
  double w_by_row = 0;                          // D = 4: w += amount × (row/(rows-1) - ½)
  std::vector<double> offset;                   // D numbers, added last
  double mass = 0;                              // kg per vertex, 0 = physics.mass
};

// Which vertices of an object a tool acts on.
struct Selection {
  std::string object;
  bool all = false;
  std::vector<int> indices;                      // explicit local vertex indices (-1 = the last)
  int axis = 0;                                  // "extreme": the `count` vertices furthest
  bool max_side = true;                          //   along ±axis
  int count = 1;
};

// A tool as a user would drive it: "hold" pins; "move" pins and carries the vertices by `by`
// over [from, to] (smooth ramp); "pull" drags them through a force-limited spring to the same
// moving target (virtual coupling, what a haptic device feels).
struct Action {
  std::string kind;
  Selection select;
  double from = 0, to = 0;                      // s
  std::vector<double> by;                       // D numbers, m
  double stiffness = 50;                        // N/m per vertex, "pull"
  double max_force = 1;                         // N per vertex, "pull"
};

struct Verdict {
  std::string kind;  // untied | knotted | slides-off | lifted | deforms | shadow-clean
  std::map<std::string, double> numbers;        // thresholds, by name
  std::string object;                           // the object the verdict looks at
  std::vector<double> close_via;                // knotted/untied: direction to close the centre line
  std::string view;                             // shadow-clean: the 3D view, rotations "yw=30,xz=10"
};

struct ScenarioSpec {
  std::string name, description;
  std::filesystem::path file;
  int dim = 4;
  double duration = 1;                          // s of simulated time
  int frames = 4;                               // PNG frames saved (plus the initial one)
  PhysicsParams<4> physics;                     // gravity truncated to dim for D = 3
  std::vector<ObjectSpec> objects;
  std::vector<Action> script;
  Verdict verdict;
};

// Throws ParseError("file:line: message") on malformed input.
ScenarioSpec load_scenario(const std::filesystem::path& path);

}  // namespace s4d::scenario
