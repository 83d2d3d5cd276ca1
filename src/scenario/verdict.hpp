// VerdictJudge: a scenario's outcome measured on a state — the line `shadow4d run` prints at the
// end, and the live verdict the window shows while a user plays or does the scenario by hand.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <optional>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "scenario/verdict_checks.hpp"

namespace s4d {

// The verdict's one quantity as the window shows it while a person works towards it:
// "shadow curves 3.88 -> 1.20, goal <= 0".
struct VerdictProgress {
  std::string what;
  double start = 0, now = 0, goal = 0;
  bool rising = true;  // the goal is reached from below (>=) or, false, from above (<=)
  // How far from start to goal, in [0, 1].
  double fraction() const;
};

struct VerdictResult {
  bool pass = false;
  std::string detail;                          // what was measured against what was needed
  std::optional<VerdictProgress> progress;
  nlohmann::ordered_json numbers = nlohmann::ordered_json::object();  // for metrics.json
};

class VerdictJudge {
 public:
  // first/count: each scene object's vertices in the world (-1/0 for curves); initial: every
  // vertex at the start (R^3 worlds with w = 0); tool: nv, 1 where the script holds a vertex.
  // Throws s4d::Error when the verdict cannot look at its object (a knot verdict on no grid).
  VerdictJudge(const Scenario& scenario, std::vector<int> first, std::vector<int> count,
               std::vector<Vec4> initial, std::vector<std::uint8_t> tool);

  // Called after each step that went from t0 to t1 (s): keeps the reference state the
  // "lifted" verdict measures rises from.
  void observe(double t0, double t1, std::span<const Vec4> x);
  // The verdict of state x (nv points), without the embedding check (the caller's).
  VerdictResult judge(std::span<const Vec4> x) const;

 private:
  Surface<4> object_surface(std::span<const Vec4> x) const;
  double number(const std::string& key, double fallback) const;

  const VerdictSpec verdict_;
  Shape object_;  // the verdict's object as placed (topology, grid)
  int v0_ = 0, v1_ = 0;
  std::vector<Vec4> initial_, reference_;
  std::vector<std::uint8_t> tool_;
  double reference_time_ = 0;
  ShadowCheck initial_shadow_;  // shadow-clean: the curves the scenario must clear
};

}  // namespace s4d
