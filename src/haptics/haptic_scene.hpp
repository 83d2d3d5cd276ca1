// HapticScene: what the haptic loop runs each tick (the active tool's force model plus any simulation
// steps). The loop only knows this interface, so it runs a sticky plane, a cloth or a test double.
#pragma once
#include <span>
#include <string_view>

#include "core/vec.hpp"
#include "haptics/device.hpp"

namespace s4d {

// One tunable parameter of a force model, shown as a slider and settable from scene files / commands.
struct SceneParam {
  const char* name = "";  // stable identifier, e.g. "H"
  double value = 0;
  double min = 0, max = 1;
  const char* unit = "";  // e.g. "N/m"
};

// Everything a scene computes in one tick.
struct ToolOutput {
  Vec3 force = Vec3::Zero();   // N, requested device force (before safety)
  Vec3 anchor = Vec3::Zero();  // m, the point the tool pulls towards (C', picked vertex): for the arrow
  bool engaged = false;        // the tool is attached (sticky contact, rubber band held)
};

class HapticScene {
 public:
  virtual ~HapticScene() = default;
  virtual std::string_view name() const = 0;

  // Loop thread, once per tick: runs the tool and the simulation for dt seconds with the device at
  // `device`. Must not allocate, block or throw; numerical trouble shows as a non-finite force,
  // which the safety layer rejects.
  virtual ToolOutput step(const DeviceState& device, double dt) = 0;

  // Loop thread: back to the initial state (same parameters).
  virtual void reset() = 0;

  // The tunable parameters; set_param clamps to [min, max] and ignores unknown indices and NaN.
  virtual std::span<SceneParam> params() = 0;
  virtual void set_param(int index, double value);
  // Index of the parameter called `name`, or -1.
  int find_param(std::string_view name);

  // Points the renderer may draw (simulation vertices), flattened point by point.
  virtual int point_count() const { return 0; }
  virtual int point_dimension() const { return 3; }
  // Copies point_count() * point_dimension() values into `out` (exactly that size). No allocation.
  virtual void copy_points(std::span<double> out) const {}
};

}  // namespace s4d
