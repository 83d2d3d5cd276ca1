// ScenarioRun: a scenario stepped one physics step at a time — the world from the scene, the
// scripted tool, the exact embedding check and the verdict. `shadow4d run`, the tests and the
// demo drive the same object (the CLI adds PNG frames and metrics.json).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "physics/world.hpp"
#include "scenario/scenario.hpp"
#include "scenario/verdict.hpp"

namespace s4d {

struct ModelFacts {
  int vertices = 0, triangles = 0, springs = 0;
  double time_step = 0, contact_thickness = 0, hard_thickness = 0;
  const char* integrator = "";
};

// The exact check of a state: triangle pairs (sharing no vertex) that truly meet, and the
// smallest gap between such pairs within twice the contact layer (infinity beyond).
struct EmbeddingCheck {
  int intersections = 0;
  double min_gap = 0;
};

class ScenarioRun {
 public:
  // Throws s4d::Error when the scenario cannot be built (bad generator parameters, an
  // intersecting start, a selection out of range).
  static std::unique_ptr<ScenarioRun> make(const Scenario& scenario);
  virtual ~ScenarioRun() = default;

  const Scenario& scenario() const { return scenario_; }
  virtual void step() = 0;  // one time_step, the script applied first
  virtual double time() const = 0;  // s simulated
  long total_steps() const;  // the steps of the scenario's duration
  virtual long steps() const = 0;
  bool done() const { return steps() >= total_steps(); }

  virtual std::vector<Vec4> positions() const = 0;  // nv, R^3 worlds with w = 0
  // The scene with the objects' current positions (for drawing and saving).
  virtual Scene current_scene() const = 0;
  virtual EmbeddingCheck check() const = 0;
  virtual std::uint64_t state_hash() const = 0;
  virtual VerdictResult verdict() const = 0;
  virtual const PhysicsWarnings& warnings() const = 0;
  virtual ModelFacts facts() const = 0;

 protected:
  explicit ScenarioRun(const Scenario& scenario) : scenario_(scenario) {}
  Scenario scenario_;
};

}  // namespace s4d
