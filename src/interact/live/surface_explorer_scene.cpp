// The explorer in the haptic loop: device units in and out, the view handover, the statistics.
#include "interact/live/surface_explorer_scene.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace s4d {

std::unique_ptr<ExploreView> make_explore_view(std::span<const Triangle> triangles, std::span<const Vec4> positions,
                                               const Frame<4>& frame, const DeviceMapping& mapping) {
  auto v = std::make_unique<ExploreView>();
  v->frame = frame;
  v->mapping = mapping;
  v->crossings = build_crossing_table(triangles, positions, frame);
  return v;
}

void shadow_box(std::span<const Vec4> positions, const Frame<4>& frame, Vec3& lo, Vec3& hi) {
  lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (const Vec4& p : positions) {
    const Vec3 q = frame.shadow(p);
    if (!q.allFinite()) continue;
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
}

DeviceMapping fit_shadow_box(const Vec3& lo, const Vec3& hi, const DeviceCapabilities& caps, double fill) {
  const Vec3 half = 0.5 * (caps.workspace_max - caps.workspace_min);
  const bool box_ok = lo.allFinite() && hi.allFinite() && (hi - lo).minCoeff() >= 0;
  const Vec3 centre = box_ok ? Vec3(0.5 * (lo + hi)) : Vec3::Zero();
  const double radius = box_ok ? 0.5 * (hi - lo).maxCoeff() : 1.0;
  const double f = std::isfinite(fill) && fill > 0 && fill <= 1 ? fill : 0.9;
  return DeviceMapping::fit(centre, radius, Mat<3>::Identity(), caps.workspace_centre(), f * half);
}

SurfaceExplorerScene::SurfaceExplorerScene(const Surface<4>& surface, const Frame<4>& frame,
                                           const DeviceMapping& mapping, const ExplorerSettings& settings)
    : positions_(surface.vertices),
      explorer_(surface.triangles, static_cast<int>(surface.vertices.size()), settings) {
  if (!(mapping.metres_per_unit > 0) || !std::isfinite(mapping.metres_per_unit))
    throw Error("explore: the device mapping needs a positive, finite scale (metres per scene unit)");
  view_.frame = frame;
  view_.mapping = mapping;
  explorer_.refresh_crossings(positions_, frame);
  params_[kK] = {"K", 200, 0, 1000, "N/m"};   // the navigation spring (4.3.1)
  params_[kB] = {"B", 1.0, 0, 10, "N s/m"};  // its damping along the spring
  // Device motion (mm) that separates two passes of one curve: below it the hand's tremor and the
  // encoder's step would ring a cue per jitter.
  params_[kRearm] = {"rearm", 1.0, 0, 10, "mm"};
}

SurfaceExplorerScene::~SurfaceExplorerScene() {
  delete pending_.exchange(nullptr);
  delete retired_.exchange(nullptr);
}

void SurfaceExplorerScene::copy_points(std::span<double> out) const {
  const std::size_t n = std::min(out.size() / 4, positions_.size());
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 4; ++k) out[4 * i + k] = positions_[i][k];
}

bool SurfaceExplorerScene::place(const Vec3& shadow_point) {
  if (!explorer_.place(positions_, view_.frame, shadow_point)) return false;
  home_ = explorer_.probe();
  reset();
  return true;
}

bool SurfaceExplorerScene::place_at(const ProbeLocation& location) {
  if (!explorer_.place_at(location)) return false;
  home_ = explorer_.probe();
  reset();
  return true;
}

void SurfaceExplorerScene::set_view(const Frame<4>& frame, const DeviceMapping& mapping) {
  view_.frame = frame;
  view_.mapping = mapping;
  explorer_.refresh_crossings(positions_, frame);
}

void SurfaceExplorerScene::reset() {
  if (home_.valid() && !(explorer_.probe().triangle == home_.triangle && explorer_.probe().b1 == home_.b1 &&
                         explorer_.probe().b2 == home_.b2))
    explorer_.place_at(home_);
  stats_ = {};
  stats_.start_component = home_.valid() ? explorer_.component(home_.triangle) : -1;
}

void SurfaceExplorerScene::offer_view(std::unique_ptr<ExploreView> view) {
  collect_retired();
  delete pending_.exchange(view.release());  // an offer the tick never took
}

std::optional<ExplorerEvent> SurfaceExplorerScene::pop_event() {
  collect_retired();
  return explorer_.pop_event();
}

void SurfaceExplorerScene::collect_retired() { delete retired_.exchange(nullptr); }

ToolOutput SurfaceExplorerScene::step(const DeviceState& device, double dt) {
  // A new view: swap it in (no allocation: vectors swap) and hand the old one back to the UI. Only
  // when the previous one was collected, so the tick never frees memory.
  if (retired_.load(std::memory_order_acquire) == nullptr) {
    if (ExploreView* v = pending_.exchange(nullptr, std::memory_order_acq_rel)) {
      std::swap(view_.frame, v->frame);
      std::swap(view_.mapping, v->mapping);
      explorer_.swap_crossings(v->crossings);
      retired_.store(v, std::memory_order_release);
      ++stats_.views_installed;
    }
  }
  ++stats_.ticks;
  const double h = std::isfinite(dt) && dt > 0 ? dt : 1e-3;
  stats_.time += h;

  const DeviceMapping& m = view_.mapping;
  const double mpu = m.metres_per_unit;
  const Vec3 c = m.to_shadow(device.position), v = m.vector_to_shadow(device.velocity);
  // The spring is felt in N/m at the device; in shadow units (force per unit, power preserved) its
  // constants scale by mpu², and the force maps back by A^T / mpu.
  const DampedSpring spring{params_[kK].value * mpu * mpu, params_[kB].value * mpu * mpu};
  explorer_.settings().rearm_distance = 1e-3 * params_[kRearm].value / mpu;
  const ExplorerStep s = explorer_.update(positions_, view_.frame, c, v, 1.0 / h, stats_.time, spring);

  ToolOutput out;
  if (!s.ok) {
    ++stats_.zero_force_ticks;
    out.anchor = s.probe.allFinite() ? m.to_device(s.probe) : device.position;
    if (!out.anchor.allFinite()) out.anchor = Vec3::Zero();
    return out;
  }
  out.force = m.vector_to_device(s.force) / (mpu * mpu);
  out.anchor = m.to_device(s.probe);
  out.engaged = true;
  stats_.device = c;
  stats_.probe = s.probe;
  stats_.probe_w = explorer_.probe_depth(positions_, view_.frame);
  stats_.max_distance = std::max(stats_.max_distance, (s.probe - c).norm());
  if (explorer_.component(explorer_.probe().triangle) != stats_.start_component) stats_.left_component = true;
  return out;
}

}  // namespace s4d
