// The curve explorer in the haptic loop. CurveNavigation is the tick's part, shared by the
// standalone CurveExplorerScene (`shadow4d explore KNOT`) and the live simulation's explore mode:
// the hand's point in shadow space is seen through the image's view, walks the strand, and the
// navigation spring comes back as a force in shadow space. New images (the curve moved or the
// view turned) are built off the loop and handed over without either side waiting.
#pragma once
#include <array>
#include <memory>
#include <optional>

#include "haptics/haptic_scene.hpp"
#include "interact/live/curve_explorer.hpp"
#include "interact/live/device_mapping.hpp"
#include "interact/live/handover.hpp"

namespace s4d {

// The view a curve of R^3 is seen through by a camera with these axes (shadow space): the image
// is (right, up), the depth towards the eye (larger = nearer).
Frame<3> camera_frame(const Vec3& right, const Vec3& up, const Vec3& toward_eye);

class CurveNavigation {
 public:
  // UI thread: the latest image wins (never blocks).
  void offer(std::unique_ptr<CurveImage> image) { pending_.offer(std::move(image)); }
  // Loop thread, set-up or tick: installs an offered image (no allocation); true when it did.
  bool install() noexcept;
  // Puts the probe where the image is nearest the shadow point `at`.
  bool place(const Vec3& at) noexcept;
  // The tick: hand at `c` moving at `v` (shadow units); the force (shadow units) towards the probe.
  Vec3 update(const Vec3& c, const Vec3& v, double rate_hz, double time, const DampedSpring& spring) noexcept;
  // The probe in shadow space: on the curve's image, at the depth of the hand's plane `c`.
  Vec3 probe_at(const Vec3& c) const;
  CurveExplorer& explorer() { return explorer_; }
  const CurveExplorer& explorer() const { return explorer_; }

 private:
  CurveExplorer explorer_;
  Handover<CurveImage> pending_;
};

// What the scene measured (loop thread; read when the loop is stopped).
struct CurveExploreStats {
  std::uint64_t ticks = 0;
  double time = 0;
  double max_distance = 0;  // shadow units: the largest |probe - hand| in the image
  int start_component = -1;
  bool left_component = false;  // it must never walk onto another component
  std::uint64_t images_installed = 0;
};

class CurveExplorerScene final : public HapticScene {
 public:
  enum Param { kK, kB, kRearm, kParamCount };

  // Throws s4d::Error for a curve the explorer refuses or a bad mapping.
  CurveExplorerScene(const Curve<3>& curve, const Frame<3>& view, const DeviceMapping& mapping);

  std::string_view name() const override { return "explore-curve"; }
  ToolOutput step(const DeviceState& device, double dt) override;
  void reset() override;
  std::span<SceneParam> params() override { return params_; }

  bool place(const Vec3& shadow_point);
  void offer_image(std::unique_ptr<CurveImage> image) { nav_.offer(std::move(image)); }
  std::optional<CurveCrossingEvent> pop_event() { return nav_.explorer().pop_event(); }
  const CurveNavigation& navigation() const { return nav_; }
  const CurveExploreStats& stats() const { return stats_; }
  const DeviceMapping& mapping() const { return mapping_; }

 private:
  CurveNavigation nav_;
  DeviceMapping mapping_;
  CurveProbe home_;
  std::array<SceneParam, kParamCount> params_;
  CurveExploreStats stats_;
};

}  // namespace s4d
