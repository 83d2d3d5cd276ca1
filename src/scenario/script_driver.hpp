// ScriptDriver<D>: plays a scenario's scripted tool on a World<D> — the same holds, moves and
// pulls whether `shadow4d run` steps it, a test does, or the window plays it live.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "scenario/scenario.hpp"
#include "scenario/world_builder.hpp"

namespace s4d {

// The world vertices a selection names, resolved at positions x (nv, world order); first/count
// give each scene object's vertices. Throws s4d::Error for a vertex out of range.
template <int D>
std::vector<int> selected_vertices(const Scenario& scenario, const std::vector<int>& first,
                                   const std::vector<int>& count, std::span<const Vec<D>> x,
                                   const VertexSelection& selection);

// Which of a scenario's actions a driver plays: the script (Play script, `shadow4d run`: all but
// the "only" ones), or the set-up kept when a person does it by hand (ByHand keep, until-grabbed
// and only).
enum class ScriptMode { kScript, kByHand };

template <int D>
class ScriptDriver {
 public:
  // Resolves the vertices of every action the mode plays at the world's current positions.
  // Throws s4d::Error for a selection out of range.
  ScriptDriver(const Scenario& scenario, const SceneWorld<D>& world, ScriptMode mode = ScriptMode::kScript);

  // Sets pins, targets and forces for the step that ends at time t (s, from the script's
  // start). Call before World::step. No allocation.
  void apply(World<D>& world, double t);
  // Lets go: unpins what the script pinned and clears its forces (a user stopping the script).
  void release(World<D>& world);
  // The user's hand took `vertex`: every "until-grabbed" action holding it lets go for good.
  // True when one did. No allocation.
  bool hand_takes(World<D>& world, int vertex);
  // Whether the driver plays any action at all.
  bool empty() const { return tools_.empty(); }

  // nv, 1 where some action holds the vertex (the "deforms" verdict looks at the others).
  const std::vector<std::uint8_t>& tool_vertices() const { return tool_; }

 private:
  struct Tool {
    std::size_t action = 0;  // index into actions_ (the driver may be moved)
    std::vector<int> vertices;
    std::vector<double> weights;  // how much of `by` each vertex moves (1 without a radius)
    std::vector<Vec<D>> start;    // positions when the tool engaged
    bool engaged = false;
    bool dropped = false;  // let go for good (the user's hand took over)
  };
  void let_go(World<D>& world, Tool& tool) const;

  std::vector<ScriptAction> actions_;
  std::vector<Tool> tools_;
  std::vector<std::uint8_t> tool_;
};

}  // namespace s4d
