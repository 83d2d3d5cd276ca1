// SurfaceExplorerScene: the explorer as a HapticScene, so the real HapticLoop runs it at 1 kHz (the
// thread, or run_ticks headless). The device's workspace (m) maps to the shadow space through a
// DeviceMapping; the navigation spring is felt in device units (N/m); crossing events reach the UI
// through the explorer's bounded buffer, a new view (frame + mapping + crossing table, built off the
// loop) through a one-slot handover that never blocks either side.
#pragma once
#include <array>
#include <atomic>
#include <memory>
#include <optional>
#include <vector>

#include "haptics/haptic_scene.hpp"
#include "interact/live/device_mapping.hpp"
#include "interact/live/surface_explorer.hpp"

namespace s4d {

// What the tick needs to see the surface from a new viewpoint.
struct ExploreView {
  Frame<4> frame;
  DeviceMapping mapping;
  CrossingTable crossings;  // for this frame (build_crossing_table)
};

// Heavy (the crossing table): for the UI thread, when the view turned or the surface moved.
std::unique_ptr<ExploreView> make_explore_view(std::span<const Triangle> triangles, std::span<const Vec4> positions,
                                               const Frame<4>& frame, const DeviceMapping& mapping);

// The mapping that fits the shadow's bounding box [lo, hi] into the device's workspace (with the
// workspace's smallest half extent times `fill` for the box's largest half extent), axes unturned.
DeviceMapping fit_shadow_box(const Vec3& lo, const Vec3& hi, const DeviceCapabilities& caps, double fill = 0.9);

// Bounding box of the shadow of `positions` (non-finite points skipped).
void shadow_box(std::span<const Vec4> positions, const Frame<4>& frame, Vec3& lo, Vec3& hi);

// What the scene measured since the last reset (loop thread; read when the loop is stopped).
struct ExploreStats {
  std::uint64_t ticks = 0;
  double time = 0;                  // s, ticks × dt
  double max_distance = 0;          // shadow units: the largest |probe - device point|
  Vec3 device = Vec3::Zero();       // shadow space, the device point at the last tick
  Vec3 probe = Vec3::Zero();        // shadow space, the probe at the last tick
  double probe_w = 0;               // 4D depth of the probe at the last tick
  std::uint64_t zero_force_ticks = 0;  // input rejected or geometry not finite: no force
  int start_component = -1;         // the mesh piece the probe was placed on
  bool left_component = false;      // true if it ever stood on another one (it must not)
  std::uint64_t views_installed = 0;
};

class SurfaceExplorerScene final : public HapticScene {
 public:
  enum Param { kK, kB, kRearm, kParamCount };

  // Copies the surface's vertices (the scene owns them; a simulation stepping in the same thread may
  // write them through positions()), builds the explorer and the crossing table for `frame`. Throws
  // Error for a mesh the explorer refuses.
  SurfaceExplorerScene(const Surface<4>& surface, const Frame<4>& frame, const DeviceMapping& mapping,
                       const ExplorerSettings& settings = {});
  ~SurfaceExplorerScene() override;

  std::string_view name() const override { return "explore"; }
  ToolOutput step(const DeviceState& device, double dt) override;
  void reset() override;  // the probe back where it was placed; clock and statistics to zero
  std::span<SceneParam> params() override { return params_; }
  int point_count() const override { return static_cast<int>(positions_.size()); }
  int point_dimension() const override { return 4; }
  void copy_points(std::span<double> out) const override;

  // --- Set-up, while the loop is not running ---
  // Places the probe nearest to `shadow_point` (brute force); it is also where reset() returns.
  bool place(const Vec3& shadow_point);
  bool place_at(const ProbeLocation& location);
  // Turns the view now (rebuilds the crossing table on this thread).
  void set_view(const Frame<4>& frame, const DeviceMapping& mapping);
  SurfaceExplorer& explorer() { return explorer_; }
  const SurfaceExplorer& explorer() const { return explorer_; }
  std::span<Vec4> positions() { return positions_; }
  std::span<const Vec4> positions() const { return positions_; }
  const Frame<4>& frame() const { return view_.frame; }
  const DeviceMapping& mapping() const { return view_.mapping; }
  const ExploreStats& stats() const { return stats_; }

  // --- UI thread while the loop runs ---
  // A new view for the tick to install (the latest offer wins; never blocks).
  void offer_view(std::unique_ptr<ExploreView> view);
  // The oldest crossing event not yet taken (also frees a view the tick has finished with).
  std::optional<ExplorerEvent> pop_event();

 private:
  void collect_retired();

  std::vector<Vec4> positions_;  // nv × 4
  SurfaceExplorer explorer_;
  ExploreView view_;             // the crossings live in the explorer; view_.crossings is unused
  ProbeLocation home_;
  std::array<SceneParam, kParamCount> params_;
  ExploreStats stats_;
  std::atomic<ExploreView*> pending_{nullptr};  // offered by the UI, taken by the tick
  std::atomic<ExploreView*> retired_{nullptr};  // given back by the tick, freed by the UI
};

}  // namespace s4d
