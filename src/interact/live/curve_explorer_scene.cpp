// The curve explorer's tick in device and shadow units, and its scene for the loop.
#include "interact/live/curve_explorer_scene.hpp"

#include <cmath>

#include "core/error.hpp"

namespace s4d {

Frame<3> camera_frame(const Vec3& right, const Vec3& up, const Vec3& toward_eye) {
  Mat<3> r;
  r.col(0) = right;
  r.col(1) = up;
  r.col(2) = toward_eye;
  return Frame<3>(r);
}

bool CurveNavigation::install() noexcept {
  CurveImage* img = pending_.take();
  if (!img) return false;
  explorer_.swap_image(*img);
  pending_.retire(img);
  return true;
}

bool CurveNavigation::place(const Vec3& at) noexcept {
  if (!at.allFinite()) return false;
  return explorer_.place(explorer_.image().frame.shadow(at));
}

Vec3 CurveNavigation::update(const Vec3& c, const Vec3& v, double rate_hz, double time,
                             const DampedSpring& spring) noexcept {
  const Frame<3>& f = explorer_.image().frame;
  const Vec2 f2 = explorer_.update(f.shadow(c), f.to_view(v).head<2>(), rate_hz, time, spring);
  const Vec3 out = f.matrix().leftCols<2>() * f2;
  return out.allFinite() ? out : Vec3::Zero();
}

Vec3 CurveNavigation::probe_at(const Vec3& c) const {
  const Frame<3>& f = explorer_.image().frame;
  const Vec2 p = explorer_.probe_point();
  if (!p.allFinite() || !c.allFinite()) return Vec3::Constant(NAN);
  return f.matrix() * Vec3(p.x(), p.y(), f.to_view(c).z());
}

CurveExplorerScene::CurveExplorerScene(const Curve<3>& curve, const Frame<3>& view, const DeviceMapping& mapping)
    : mapping_(mapping) {
  if (!(mapping.metres_per_unit > 0) || !std::isfinite(mapping.metres_per_unit))
    throw Error("explore: the device mapping needs a positive, finite scale (metres per scene unit)");
  nav_.offer(build_curve_image(curve, view));
  nav_.install();
  params_[kK] = {"K", 200, 0, 1000, "N/m"};   // the navigation spring (4.3.1)
  params_[kB] = {"B", 1.0, 0, 10, "N s/m"};  // its damping along the spring
  params_[kRearm] = {"rearm", 1.0, 0, 10, "mm"};  // device motion that separates two passes of a crossing
}

bool CurveExplorerScene::place(const Vec3& shadow_point) {
  if (!nav_.place(shadow_point)) return false;
  home_ = nav_.explorer().probe();
  reset();
  return true;
}

void CurveExplorerScene::reset() {
  stats_ = {};
  stats_.start_component = home_.component;
}

ToolOutput CurveExplorerScene::step(const DeviceState& device, double dt) {
  if (nav_.install()) ++stats_.images_installed;
  ++stats_.ticks;
  const double h = std::isfinite(dt) && dt > 0 ? dt : 1e-3;
  stats_.time += h;
  const double mpu = mapping_.metres_per_unit;
  const Vec3 c = mapping_.to_shadow(device.position), v = mapping_.vector_to_shadow(device.velocity);
  const DampedSpring spring{params_[kK].value * mpu * mpu, params_[kB].value * mpu * mpu};
  nav_.explorer().set_rearm_distance(1e-3 * params_[kRearm].value / mpu);
  ToolOutput out;
  const Vec3 f = nav_.update(c, v, 1.0 / h, stats_.time, spring);
  const Vec3 probe = nav_.probe_at(c);
  if (!probe.allFinite()) {
    out.anchor = device.position.allFinite() ? device.position : Vec3::Zero();
    return out;
  }
  out.force = mapping_.vector_to_device(f) / (mpu * mpu);
  out.anchor = mapping_.to_device(probe);
  out.engaged = true;
  stats_.max_distance = std::max(stats_.max_distance, (probe - c).norm());
  if (nav_.explorer().probe().component != stats_.start_component) stats_.left_component = true;
  return out;
}

}  // namespace s4d
