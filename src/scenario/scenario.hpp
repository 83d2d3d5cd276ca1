// Scenario files (scenarios/*.json): a scene (objects, physics, frame, view — read by the one
// scene validator, io/scene) plus a "scenario" section: a one-line instruction for doing it by
// hand, a scripted tool, and the outcome the run must reach.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "io/scene.hpp"

namespace s4d {

// Which vertices of an object a scripted tool acts on.
struct VertexSelection {
  std::string object;
  bool all = false;
  std::vector<int> indices;  // explicit local vertex indices (-1 = the last)
  int axis = 0;              // "extreme": the `count` vertices furthest along ±axis
  bool max_side = true;
  int count = 1;
};

// What an action is when a person does the scenario by hand (Space plays it, the hand is theirs):
// the scripted hand's own moves are skipped, while the set-up its instruction assumes stays.
enum class ByHand {
  kSkip,          // "skip" (the default): the scripted hand's part; by hand the user does it instead
  kKeep,          // "keep": set-up, also in force by hand (the rod the cloth hangs on, held poles)
  kUntilGrabbed,  // "until-grabbed": set-up by hand until the user grabs one of its vertices (the
                  // scripted hand holding the chain up until the user's hand takes it over)
  kOnly,          // "only": by hand only, standing in for the user's other hand (the end held
                  // while the user pulls the other); Play script and `shadow4d run` skip it
};

// A tool as a user would drive it: "hold" pins; "move" pins and carries the vertices by `by`
// over [from, to] (smooth ramp); "pull" drags them through a force-limited spring to the same
// moving target (virtual coupling, what a haptic device feels). With `rings`, the action takes
// the patch of that many rings of mesh edges around the selected vertices (physics/patch.hpp,
// weighted), as the Touch tool's carry does: each vertex moves by its weight times `by`.
struct ScriptAction {
  std::string kind;
  ByHand by_hand = ByHand::kSkip;
  VertexSelection select;
  double from = 0, to = 0;   // s
  std::vector<double> by;    // D numbers, m
  int rings = 0;             // rings of mesh edges around them; 0: the selected vertices alone
  double stiffness = 50;     // N/m per vertex, "pull"
  double max_force = 1;      // N per vertex, "pull"
};

// A step of the scenario as a person does it by hand, for the window's markers and Show me: what
// to take (a numbered marker on those vertices) and where to take it (a target `by` away). Given in
// the file ("hints"), or else the script's moves and pulls that the person does instead of it.
struct Hint {
  VertexSelection select;
  std::vector<double> by;  // D numbers
  std::string say;         // one line ("carry the red rim outward"); may be empty
};

struct VerdictSpec {
  std::string kind;  // untied | knotted | slides-off | lifted | deforms | shadow-clean
  std::map<std::string, double> numbers;  // thresholds, by name
  std::string object;                     // the object the verdict looks at
  std::vector<double> close_via;          // knotted/untied: direction to close the centre line
  std::string view;                       // shadow-clean: the 3D view, rotations "yw=30,xz=10"
};

struct Scenario {
  Scene scene;                  // objects as placed, physics, frame, view
  std::filesystem::path file;
  std::string name, description;
  std::string instruction;      // one line: what to do by hand in the window
  std::string figure;           // the paper's figure it comes from ("Fig. 14"), for the start page
  std::string summary;          // one line of what it shows, for the start page
  int dim = 4;                  // of the simulation: 3 when every surface lies in R^3
  double duration = 1;          // s of simulated time
  int frames = 4;               // PNG frames `shadow4d run` saves (plus the initial one)
  std::vector<ScriptAction> script;
  std::vector<Hint> hints;
  VerdictSpec verdict;

  int object_index(const std::string& name) const;  // -1 when there is none
};

// Reads a scenario file. Throws ParseError("file: where: message") on malformed input, or when
// the file is a plain scene (no "scenario" section).
Scenario load_scenario(const std::filesystem::path& path);
// The scenario of a scene read by load_scene (its "scenario" section); `origin` names it in errors.
Scenario scenario_of_scene(Scene scene, const std::filesystem::path& origin);
// Whether a scene file carries a scenario section (without validating it).
inline bool is_scenario(const Scene& scene) { return !scene.scenario.empty(); }

}  // namespace s4d
