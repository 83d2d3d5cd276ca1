// The haptic Device interface every backend implements (mouse proxy, replay, SpaceMouse, OpenHaptics,
// simulated arm), its plain capability struct, and the per-tick input the loop hands it.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

#include "core/vec.hpp"

namespace s4d {

// What a device can do. Units are SI; millimetre devices convert at their own boundary.
struct DeviceCapabilities {
  Vec3 workspace_min = Vec3::Constant(-0.08);  // m, corner of the usable box in device coordinates
  Vec3 workspace_max = Vec3::Constant(0.08);   // m
  double max_force = 0;                        // N, peak force the safety layer never exceeds
  double max_continuous_force = 0;             // N, what the motors sustain without overheating
  double max_stiffness = 0;                    // N/m, stiffest spring the device renders stably
  double max_force_rate = 0;                   // N/s, fastest change of force the safety layer passes
  bool outputs_force = false;                  // false: input-only (SpaceMouse, replay)
  double nominal_rate = 1000;                  // Hz, the servo rate the device expects
  Vec3 workspace_centre() const { return 0.5 * (workspace_min + workspace_max); }
  Vec3 clamp(const Vec3& p) const { return p.cwiseMax(workspace_min).cwiseMin(workspace_max); }
};

// One reading of the device, in its workspace.
struct DeviceState {
  Vec3 position = Vec3::Zero();  // m, the point that feels the force (for the mouse: the proxy)
  Vec3 velocity = Vec3::Zero();  // m/s
  Vec3 target = Vec3::Zero();    // m, where the user's hand is heading (mouse cursor, simulated hand);
                                 //    equals position for a real arm. Its lag behind shows the force.
  std::uint32_t buttons = 0;     // bit i = button i held
};

// What the loop gives a device each tick: the nominal step (fixed, so simulated devices are
// deterministic whatever the jitter) and the GUI pointer, which the mouse proxy and the simulated
// hand follow.
struct DeviceInput {
  double dt = 1e-3;                         // s
  Vec3 pointer_target = Vec3::Zero();       // m, in the device workspace
  std::uint32_t pointer_buttons = 0;
  bool pointer_valid = false;               // false until the GUI has set a pointer
};

enum class DeviceStatus { ok, disconnected };

// Loop events a replay reproduces so that safety fades happen at the same ticks as when recorded.
inline constexpr std::uint32_t kEventDeadlineMissed = 1u << 0;
inline constexpr std::uint32_t kEventSceneReset = 1u << 1;
inline constexpr std::uint32_t kEventDisconnected = 1u << 2;

// A haptic device. read/write_force/reconnect are called from the haptic loop thread only and must
// not throw or block for long; construction and destruction happen on the UI thread.
class Device {
 public:
  virtual ~Device() = default;
  virtual std::string_view name() const = 0;
  virtual const DeviceCapabilities& capabilities() const = 0;
  // Fills `out` with the current state; returns disconnected when the device has gone away.
  virtual DeviceStatus read(const DeviceInput& in, DeviceState& out) = 0;
  // The force (N, device coordinates) to render until the next call; it has passed the safety layer.
  virtual void write_force(const Vec3& force) = 0;
  // Called at a low rate while disconnected; true when the device is back.
  virtual bool reconnect() { return false; }
  // A replay returns the loop events recorded for the tick it just read; live devices return none.
  virtual std::optional<std::uint32_t> scripted_events() const { return std::nullopt; }
};

}  // namespace s4d
