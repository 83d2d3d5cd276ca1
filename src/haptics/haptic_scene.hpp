// HapticScene: what the haptic loop runs each tick (the active tool's force model plus any simulation
// steps). The loop only knows this interface, so it runs a sticky plane, a cloth or a test double.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <type_traits>
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

// A request for the scene (a live simulation's tools and settings) copied through the loop's
// queue. The loop does not know the scene's request types: it carries one by value in a box of
// fixed size with a tag of its type, so that nothing allocates and a scene reads back only a type
// it knows (get<T>() is null for any other). The scene's own types say what a request means
// (interact/live/live_requests.hpp).
class SceneCommand {
 public:
  static constexpr std::size_t kCapacity = 192;  // bytes: the largest request of any scene fits

  SceneCommand() = default;
  template <class T>
  static SceneCommand of(const T& request) {
    static_assert(std::is_trivially_copyable_v<T>, "a scene's request crosses threads as bytes");
    static_assert(sizeof(T) <= kCapacity && alignof(T) <= alignof(std::max_align_t), "raise kCapacity");
    SceneCommand c;
    c.type_ = &kTag<T>;
    std::memcpy(c.bytes_, &request, sizeof(T));
    return c;
  }
  // The request when it is a T, else null.
  template <class T>
  const T* get() const {
    return type_ == &kTag<T> ? std::launder(reinterpret_cast<const T*>(bytes_)) : nullptr;
  }
  bool empty() const { return type_ == nullptr; }

 private:
  template <class T>
  static constexpr char kTag = 0;  // one address per type: the type's tag

  const void* type_ = nullptr;
  alignas(std::max_align_t) std::byte bytes_[kCapacity] = {};
};

// Something the hand met, for sound cues and marks (the explorer passing an intersection curve
// of the shadow above or below in w). `kind` is the scene's own code.
struct SceneEvent {
  double time = 0;         // s
  int kind = 0;
  double point[3] = {};    // shadow space
  double w_self = 0, w_other = 0;
  int label = 0;           // what was passed, when it has a number (a knot's crossing)
};

// What a simulating scene reports in every snapshot (zeros for scenes that do not simulate).
struct SceneStatus {
  static constexpr int kRecentEvents = 16;
  double sim_time = 0;          // s simulated
  std::int64_t sim_steps = 0;
  bool simulating = false;      // the scene runs a physics world
  bool playing = false;
  bool script_running = false;
  double script_time = 0;       // s since the script started
  int contacts = 0;             // pairs handled by repulsion in the last step
  std::int64_t rollbacks = 0, ccd_freezes = 0, global_freezes = 0, rejected_inputs = 0;
  int held_vertex = -1;         // the vertex on the rubber band, -1 when none
  int grab_mode = 0;            // 0: in the shadow, 1: along the shadow ray (w, or a knot's depth)
  int carry_rings = 0;          // the held vertex carries the patch of this many rings (0: on the band)
  Vec3 band_from = Vec3::Zero();  // shadow space: the hand's end of the rubber band
  Vec3 band_to = Vec3::Zero();    // shadow space: the held vertex
  double band_force = 0;        // N, what the band pulls the vertex with
  double lag = 0;               // s the simulation trails the haptic clock
  int pinned = 0;               // pinned vertices
  std::uint64_t settings_revision = 0;  // bumps when physics settings were applied
  std::uint64_t state_revision = 0;     // the revision of the last state put in place (an undo)
  char message[160] = {};       // the last request the scene refused, and why
  bool exploring = false;       // the probe walks the surface instead of the band pulling it
  bool relaxing = false;        // the knot-energy relaxation drives the curves
  Vec3 probe = Vec3::Zero();    // shadow space, where the probe is
  double probe_w = 0;           // its 4D depth
  std::uint64_t event_count = 0;              // events so far; event i is events[i % kRecentEvents]
  SceneEvent events[kRecentEvents] = {};
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

  // Loop thread: a request from the UI (see SceneCommand). Must not block or throw.
  virtual void command(const SceneCommand& cmd) {}
  // Loop thread, when publishing: the scene's status and one flag byte per point (bit 0: pinned).
  virtual void copy_status(SceneStatus& out) const {}
  virtual void copy_flags(std::span<std::uint8_t> out) const {}
  // Like copy_points, the vertices' velocities (zeros for scenes without them).
  virtual void copy_velocities(std::span<double> out) const {}
};

}  // namespace s4d
