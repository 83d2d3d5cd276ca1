#include "app/view_state.hpp"

#include <algorithm>
#include <cmath>

namespace s4d {

namespace {
constexpr double kDegPerViewport = 180.0;  // a drag across the whole viewport turns half a turn
constexpr int kXW = 2, kYW = 4, kZW = 5;   // indices into all_planes(4)

float wrap_degrees(double a) {
  a = std::fmod(a + 180.0, 360.0);
  if (a < 0) a += 360.0;
  return static_cast<float>(a - 180.0);
}
}  // namespace

void ViewState::reset(const Scene& scene) {
  base_frame_ = scene.frame;
  angles_.fill(0.0f);
  trackball_ = scene.view.trackball;
  zoom_ = scene.view.zoom;
  pan_ = Vec2::Zero();
}

void ViewState::pan_by(double dx, double dy) {
  if (!std::isfinite(dx) || !std::isfinite(dy)) return;
  pan_ = (pan_ + Vec2(dx, dy)).cwiseMax(-20.0).cwiseMin(20.0);  // never lost far from the objects
}

Vec3 ViewState::pan_offset(double radius) const {
  const Eigen::Quaterniond q = trackball_.normalized();
  return -radius * (pan_.x() * (q * Vec3::UnitX()) + pan_.y() * (q * Vec3::UnitY()));
}

void ViewState::drag(DragMode mode, double dx, double dy, double viewport_height) {
  if (!(viewport_height > 0) || !std::isfinite(dx) || !std::isfinite(dy)) return;
  const double sx = dx / viewport_height * kDegPerViewport;
  const double sy = dy / viewport_height * kDegPerViewport;
  switch (mode) {
    case DragMode::kTrackball: {
      const double deg = std::hypot(sx, sy);
      if (deg < 1e-9) return;
      // Screen y points down; turning about (dy, dx) makes the object follow the cursor.
      const Eigen::Vector3d axis = Eigen::Vector3d(sy, sx, 0).normalized();
      trackball_ = (Eigen::AngleAxisd(deg * M_PI / 180.0, axis) * trackball_).normalized();
      break;
    }
    case DragMode::kRotateW:
      angles_[kXW] = wrap_degrees(angles_[kXW] + sx);
      angles_[kYW] = wrap_degrees(angles_[kYW] + sy);
      break;
    case DragMode::kRotateZW:
      angles_[kZW] = wrap_degrees(angles_[kZW] + sx);
      break;
  }
}

void ViewState::turn_to_generic_view() {
  angles_[kXW] = 30.0f;
  angles_[kZW] = 20.0f;
}

void ViewState::scroll(double steps) {
  if (!std::isfinite(steps)) return;
  zoom_ = std::clamp(zoom_ * std::pow(1.1, steps), 0.05, 50.0);
}

Frame<4> ViewState::composed_frame() const {
  Frame<4> f = base_frame_;
  const auto planes = all_planes(4);
  for (std::size_t i = 0; i < planes.size(); ++i)
    if (angles_[i] != 0.0f) f.rotate(planes[i], angles_[i] * M_PI / 180.0);
  if (perspective_ > 0) f.set_perspective(perspective_);
  else f.set_orthographic();
  return f;
}

void ViewState::apply_to(Scene& scene) const {
  scene.frame = composed_frame();
  scene.view.trackball = trackball_;
  scene.view.zoom = zoom_;
}

}  // namespace s4d
