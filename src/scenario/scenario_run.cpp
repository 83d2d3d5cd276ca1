// ScenarioRun<D>: SceneWorld + ScriptDriver + VerdictJudge, stepped.
#include "scenario/scenario_run.hpp"

#include <cmath>
#include <limits>

#include "proximity/mesh_proximity.hpp"
#include "scenario/script_driver.hpp"
#include "scenario/world_builder.hpp"

namespace s4d {

namespace {

template <int D>
std::vector<Vec4> padded(std::span<const Vec<D>> x) {
  std::vector<Vec4> out(x.size(), Vec4::Zero());
  for (std::size_t i = 0; i < x.size(); ++i) out[i].head<D>() = x[i];
  return out;
}

template <int D>
class Run final : public ScenarioRun {
 public:
  explicit Run(const Scenario& sc)
      : ScenarioRun(sc),
        world_(build_world<D>(sc.scene)),
        script_(sc, world_),
        judge_(sc, world_.first, world_.count, padded<D>(world_.world.positions()), script_.tool_vertices()),
        cells_(world_.world.model().triangles.begin(), world_.world.model().triangles.end()) {
    Vec<D> lo = world_.world.positions()[0], hi = lo;
    for (const Vec<D>& p : world_.world.positions()) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    touch_ = 1e-9 * (hi - lo).norm();
  }

  void step() override {
    World<D>& w = world_.world;
    const double dt = w.model().params.time_step;
    const double t1 = (w.data().steps + 1) * dt, t0 = t1 - dt;
    script_.apply(w, t1);
    w.step();
    judge_.observe(t0, t1, padded<D>(w.positions()));
  }
  double time() const override { return world_.world.data().time; }
  long steps() const override { return static_cast<long>(world_.world.data().steps); }
  std::vector<Vec4> positions() const override { return padded<D>(world_.world.positions()); }
  Scene current_scene() const override {
    Scene s = scenario_.scene;
    copy_positions_into<D>(world_, world_.world.positions(), s);
    return s;
  }
  EmbeddingCheck check() const override {
    const auto x = world_.world.positions();
    EmbeddingCheck c;
    c.intersections = static_cast<int>(intersecting_pairs<D, 3>(x, cells_, touch_).size());
    c.min_gap = world_.world.min_separation(2 * world_.world.model().contact_thickness);
    return c;
  }
  std::uint64_t state_hash() const override { return world_.world.state_hash(); }
  VerdictResult verdict() const override { return judge_.judge(positions()); }
  const PhysicsWarnings& warnings() const override { return world_.world.data().warnings; }
  ModelFacts facts() const override {
    const Model<D>& m = world_.world.model();
    return {m.nv, static_cast<int>(m.triangles.size()), static_cast<int>(m.springs.size()), m.params.time_step,
            m.contact_thickness, m.hard_thickness, integrator_name(m.params.integrator)};
  }

 private:
  SceneWorld<D> world_;
  ScriptDriver<D> script_;
  VerdictJudge judge_;
  std::vector<Cell<3>> cells_;
  double touch_ = 0;
};

}  // namespace

long ScenarioRun::total_steps() const {
  return std::lround(scenario_.duration / scenario_.scene.physics.time_step);
}

std::unique_ptr<ScenarioRun> ScenarioRun::make(const Scenario& scenario) {
  if (scenario.dim == 3) return std::make_unique<Run<3>>(scenario);
  return std::make_unique<Run<4>>(scenario);
}

}  // namespace s4d
