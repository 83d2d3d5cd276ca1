// The scripted tool of a scenario: selection, engagement, smooth ramps, virtual-coupling pulls.
#include "scenario/script_driver.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "physics/patch.hpp"

namespace s4d {

namespace {

template <int D>
Vec<D> head(const std::vector<double>& v) {
  Vec<D> r = Vec<D>::Zero();
  for (int k = 0; k < D && k < static_cast<int>(v.size()); ++k) r[k] = v[static_cast<std::size_t>(k)];
  return r;
}

}  // namespace

template <int D>
std::vector<int> selected_vertices(const Scenario& sc, const std::vector<int>& firsts, const std::vector<int>& counts,
                                   std::span<const Vec<D>> x, const VertexSelection& s) {
  const int o = sc.object_index(s.object);
  if (o < 0 || firsts[static_cast<std::size_t>(o)] < 0) throw Error("no surface named '" + s.object + "'");
  const int first = firsts[static_cast<std::size_t>(o)], n = counts[static_cast<std::size_t>(o)];
  std::vector<int> v(static_cast<std::size_t>(n));
  std::iota(v.begin(), v.end(), first);
  if (!s.indices.empty()) {
    v.clear();
    for (int i : s.indices) {
      const int local = i < 0 ? n + i : i;
      if (local < 0 || local >= n)
        throw Error(s.object + ": vertex " + std::to_string(i) + " out of range (it has " + std::to_string(n) + ")");
      v.push_back(first + local);
    }
  } else if (!s.all) {
    std::stable_sort(v.begin(), v.end(), [&](int a, int b) {
      return s.max_side ? x[a][s.axis] > x[b][s.axis] : x[a][s.axis] < x[b][s.axis];
    });
    v.resize(static_cast<std::size_t>(std::min(n, s.count)));
  }
  return v;
}

template <int D>
ScriptDriver<D>::ScriptDriver(const Scenario& scenario, const SceneWorld<D>& world, ScriptMode mode)
    : actions_(scenario.script), tool_(static_cast<std::size_t>(world.world.vertex_count()), 0) {
  for (std::size_t i = 0; i < actions_.size(); ++i) {
    const ScriptAction& a = actions_[i];
    const bool by_hand = a.by_hand != ByHand::kSkip;
    if (mode == ScriptMode::kScript ? a.by_hand == ByHand::kOnly : !by_hand) continue;
    Tool t;
    t.action = i;
    const std::vector<int> chosen =
        selected_vertices<D>(scenario, world.first, world.count, world.world.positions(), a.select);
    Patch patch;
    PatchScratch scratch;
    grow_patch<D>(world.world.model(), chosen, a.rings, patch, scratch);
    t.vertices = std::move(patch.vertices);
    t.weights = std::move(patch.weights);
    t.start.reserve(t.vertices.size());
    for (int v : t.vertices) tool_[static_cast<std::size_t>(v)] = 1;
    tools_.push_back(std::move(t));
  }
}

template <int D>
void ScriptDriver<D>::apply(World<D>& world, double t) {
  const Model<D>& model = world.model();
  for (Tool& tool : tools_) {
    const ScriptAction& a = actions_[tool.action];
    if (t < a.from || tool.dropped) continue;
    if (!tool.engaged) {
      tool.engaged = true;
      tool.start.clear();
      for (int v : tool.vertices) tool.start.push_back(world.positions()[v]);
      if (a.kind != "pull")
        for (int v : tool.vertices) world.pin(v);
    }
    const double u = a.to > a.from ? std::clamp((t - a.from) / (a.to - a.from), 0.0, 1.0) : 1.0;
    const double ramp = u * u * (3 - 2 * u);  // smooth start and stop, as a hand would move
    const Vec<D> by = head<D>(a.by);
    for (std::size_t i = 0; i < tool.vertices.size(); ++i) {
      const int v = tool.vertices[i];
      const Vec<D> target = tool.start[i] + (a.kind == "hold" ? 0.0 : ramp * tool.weights[i]) * by;
      if (a.kind == "pull") {
        // Virtual coupling: spring to the target, critically damped, force-limited.
        const double c = 2 * std::sqrt(a.stiffness * model.mass[static_cast<std::size_t>(v)]);
        Vec<D> f = a.stiffness * (target - world.positions()[v]) - c * world.velocities()[v];
        if (f.norm() > a.max_force) f *= a.max_force / f.norm();
        world.set_external_force(v, f);
      } else {
        world.set_target(v, target);
      }
    }
  }
}

template <int D>
void ScriptDriver<D>::let_go(World<D>& world, Tool& tool) const {
  if (!tool.engaged) return;
  const bool pull = actions_[tool.action].kind == "pull";
  for (int v : tool.vertices) {
    if (pull) world.set_external_force(v, Vec<D>::Zero());
    else world.unpin(v);
  }
  tool.engaged = false;
}

template <int D>
void ScriptDriver<D>::release(World<D>& world) {
  for (Tool& tool : tools_) let_go(world, tool);
}

template <int D>
bool ScriptDriver<D>::hand_takes(World<D>& world, int vertex) {
  bool took = false;
  for (Tool& tool : tools_) {
    if (tool.dropped || actions_[tool.action].by_hand != ByHand::kUntilGrabbed) continue;
    if (std::find(tool.vertices.begin(), tool.vertices.end(), vertex) == tool.vertices.end()) continue;
    let_go(world, tool);
    tool.dropped = true;
    took = true;
  }
  return took;
}

template class ScriptDriver<3>;
template class ScriptDriver<4>;
template std::vector<int> selected_vertices<3>(const Scenario&, const std::vector<int>&, const std::vector<int>&,
                                               std::span<const Vec<3>>, const VertexSelection&);
template std::vector<int> selected_vertices<4>(const Scenario&, const std::vector<int>&, const std::vector<int>&,
                                               std::span<const Vec<4>>, const VertexSelection&);

}  // namespace s4d
