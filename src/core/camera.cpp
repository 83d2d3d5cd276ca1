// Camera matrices and the auto-fit distance (see camera.hpp).
#include "core/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace s4d {

namespace {
// The fitted sphere leaves this fraction of slack so silhouettes do not touch the image border.
constexpr double kFitMargin = 1.04;
}  // namespace

Vec3 Camera::eye() const { return target + orientation.normalized() * Vec3(0, 0, distance); }

Mat4 Camera::view() const {
  const Eigen::Matrix3d r = orientation.normalized().toRotationMatrix();
  Mat4 v = Mat4::Identity();
  v.topLeftCorner<3, 3>() = r.transpose();
  v.topRightCorner<3, 1>() = -r.transpose() * eye();
  return v;
}

Mat4 Camera::projection() const {
  const double f = 1.0 / std::tan(fov_y / 2);
  const double n = near_plane, fa = far_plane;
  Mat4 p = Mat4::Zero();
  p(0, 0) = f / aspect;
  p(1, 1) = f;
  p(2, 2) = (fa + n) / (n - fa);
  p(2, 3) = 2 * fa * n / (n - fa);
  p(3, 2) = -1;
  return p;
}

double Camera::view_depth(const Vec3& p) const {
  const Vec3 forward = orientation.normalized() * Vec3(0, 0, -1);
  return (p - eye()).dot(forward);
}

Vec2 Camera::ndc(const Vec3& p) const {
  const Eigen::Vector4d clip = projection() * view() * p.homogeneous();
  return clip.head<2>() / clip.w();
}

double fit_distance(double radius, double fov_y, double aspect) {
  // The sphere fits when the half-angle it subtends, asin(r/d), is at most the smaller half
  // field of view (horizontal half-angle is atan(aspect · tan(fov_y/2))).
  const double half_y = fov_y / 2;
  const double half_x = std::atan(aspect * std::tan(half_y));
  return radius / std::sin(std::min(half_x, half_y));
}

Camera make_camera(const BoundingSphere& sphere, const Eigen::Quaterniond& orientation,
                   double distance, double fov_deg, double aspect, double zoom) {
  Camera c;
  const bool q_ok = orientation.coeffs().allFinite() && orientation.norm() > 1e-12;
  c.orientation = q_ok ? orientation.normalized() : Eigen::Quaterniond::Identity();
  c.target = sphere.centre.allFinite() ? sphere.centre : Vec3::Zero();
  const double radius = sphere.radius > 0 && std::isfinite(sphere.radius) ? sphere.radius : 1.0;
  c.fov_y = std::clamp(std::isfinite(fov_deg) ? fov_deg : 35.0, 1.0, 170.0) * std::numbers::pi / 180;
  c.aspect = aspect > 0 && std::isfinite(aspect) ? aspect : 1.0;
  c.distance = distance > 0 && std::isfinite(distance)
                   ? distance
                   : kFitMargin * fit_distance(radius, c.fov_y, c.aspect);
  // Zoom (the GUI wheel) moves the eye along its line of sight; a bad value means no zoom.
  if (std::isfinite(zoom) && zoom > 0) c.distance /= std::clamp(zoom, 1e-3, 1e3);
  // Bracket the sphere; when the eye is inside it, keep a near plane small but not so small
  // that the depth buffer loses all precision.
  c.far_plane = c.distance + 1.5 * radius;
  c.near_plane = std::max(c.distance - 1.5 * radius, 1e-3 * c.far_plane);
  return c;
}

BoundingSphere bounding_sphere(const std::vector<Vec3>& points) {
  // Non-finite points (a broken edit) are ignored so one bad vertex cannot lose the camera.
  BoundingSphere s;
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = Vec3::Constant(-HUGE_VAL);
  for (const Vec3& p : points) {
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (!(lo.x() <= hi.x())) return s;
  s.centre = 0.5 * (lo + hi);
  double r2 = 0;
  for (const Vec3& p : points)
    if (p.allFinite()) r2 = std::max(r2, (p - s.centre).squaredNorm());
  s.radius = std::sqrt(r2);
  return s;
}

}  // namespace s4d
