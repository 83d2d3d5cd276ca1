// Camera tests: the auto-fit frustum contains the bounding sphere, matrices follow OpenGL's
// conventions, depth grows away from the eye, bad input still gives usable matrices.
#include "core/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace s4d {
namespace {

// Signed distances from the sphere centre to the six frustum planes (Gribb-Hartmann: rows of
// the clip matrix), positive inside.
std::array<double, 6> plane_distances(const Camera& c, const Vec3& p) {
  const Mat4 m = c.projection() * c.view();
  std::array<double, 6> d{};
  for (int k = 0; k < 6; ++k) {
    const Eigen::Vector4d plane = m.row(3) + (k % 2 == 0 ? 1.0 : -1.0) * m.row(k / 2);
    d[k] = (plane.head<3>().dot(p) + plane[3]) / plane.head<3>().norm();
  }
  return d;
}

TEST(Camera, FitContainsTheBoundingSphereForAnyAspectAndOrientation) {
  const Eigen::Quaterniond rotations[] = {
      Eigen::Quaterniond::Identity(),
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())),
      Eigen::Quaterniond(Eigen::AngleAxisd(2.5, Vec3(-1, 0.2, 0.4).normalized()))};
  for (double aspect : {0.5, 1.0, 4.0 / 3.0, 2.5})
    for (double fov : {20.0, 35.0, 90.0})
      for (const auto& q : rotations) {
        BoundingSphere s;
        s.centre = Vec3(1, -2, 0.5);
        s.radius = 3;
        const Camera c = make_camera(s, q, 0, fov, aspect);
        const auto d = plane_distances(c, s.centre);
        double tightest = 1e300;
        for (double x : d) {
          EXPECT_GE(x, s.radius * (1 - 1e-9)) << "aspect " << aspect << " fov " << fov;
          tightest = std::min(tightest, x);
        }
        // ...and fills the frame: the sphere nearly touches the narrower pair of planes.
        EXPECT_LT(tightest, s.radius * 1.1);
      }
}

TEST(Camera, ViewPutsEyeAtOriginAndTargetStraightAhead) {
  BoundingSphere s;
  s.centre = Vec3(0.5, 0.25, -1);
  s.radius = 1;
  const Eigen::Quaterniond q(Eigen::AngleAxisd(1.1, Vec3(0, 1, 1).normalized()));
  const Camera c = make_camera(s, q, 6, 35, 1.5);
  const Mat4 v = c.view();
  EXPECT_NEAR((v * c.eye().homogeneous()).head<3>().norm(), 0, 1e-12);
  EXPECT_NEAR(((v * s.centre.homogeneous()).head<3>() - Vec3(0, 0, -6)).norm(), 0, 1e-12);
  EXPECT_NEAR(c.view_depth(s.centre), 6, 1e-12);
  EXPECT_NEAR(
      (v.topLeftCorner<3, 3>() * v.topLeftCorner<3, 3>().transpose() - Eigen::Matrix3d::Identity()).norm(), 0,
      1e-12);
}

TEST(Camera, IdentityLooksDownMinusZSoLargerZIsNearer) {
  BoundingSphere s;
  s.radius = 1;
  const Camera c = make_camera(s, Eigen::Quaterniond::Identity(), 0, 35, 1);
  EXPECT_LT(c.view_depth(Vec3(0, 0, 0.5)), c.view_depth(Vec3(0, 0, -0.5)));
  // +x appears to the right and +y up in normalised device coordinates.
  const Mat4 m = c.projection() * c.view();
  const Eigen::Vector4d px = m * Eigen::Vector4d(0.5, 0, 0, 1), py = m * Eigen::Vector4d(0, 0.5, 0, 1);
  EXPECT_GT(px.x() / px.w(), 0);
  EXPECT_GT(py.y() / py.w(), 0);
}

TEST(Camera, NearAndFarPlanesMapToMinusOneAndOne) {
  BoundingSphere s;
  s.radius = 2;
  const Camera c = make_camera(s, Eigen::Quaterniond::Identity(), 0, 35, 1);
  EXPECT_GT(c.near_plane, 0);
  EXPECT_LT(c.near_plane, c.distance - s.radius);
  EXPECT_GT(c.far_plane, c.distance + s.radius);
  const Mat4 p = c.projection();
  const Eigen::Vector4d n = p * Eigen::Vector4d(0, 0, -c.near_plane, 1);
  const Eigen::Vector4d f = p * Eigen::Vector4d(0, 0, -c.far_plane, 1);
  EXPECT_NEAR(n.z() / n.w(), -1, 1e-9);
  EXPECT_NEAR(f.z() / f.w(), 1, 1e-9);
}

TEST(Camera, FitDistanceMatchesTheTangentCone) {
  // A sphere fits exactly when it is tangent to the narrower half-angle: r = d sin(half).
  const double fov = 0.6;
  EXPECT_NEAR(fit_distance(2, fov, 1), 2 / std::sin(0.3), 1e-12);
  // Portrait: the horizontal field is narrower and decides.
  const double half_x = std::atan(0.5 * std::tan(0.3));
  EXPECT_NEAR(fit_distance(2, fov, 0.5), 2 / std::sin(half_x), 1e-12);
}

TEST(Camera, ZoomMovesTheEyeAlongItsLineOfSight) {
  const BoundingSphere sphere{Vec3(1, 2, 3), 2.0};
  const Camera fitted = make_camera(sphere, Eigen::Quaterniond::Identity(), 0, 35, 1.5);
  const Camera closer = make_camera(sphere, Eigen::Quaterniond::Identity(), 0, 35, 1.5, 2.0);
  EXPECT_NEAR(closer.distance, fitted.distance / 2, 1e-12);
  const Camera ignored = make_camera(sphere, Eigen::Quaterniond::Identity(), 0, 35, 1.5, std::nan(""));
  EXPECT_DOUBLE_EQ(ignored.distance, fitted.distance);
}

TEST(Camera, BadInputStillGivesFiniteMatrices) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BoundingSphere s;
  s.centre = Vec3(nan, 0, 0);
  s.radius = nan;
  const Camera c = make_camera(s, Eigen::Quaterniond(0, 0, 0, 0), -3, nan, 0);
  EXPECT_TRUE(c.view().allFinite());
  EXPECT_TRUE(c.projection().allFinite());
  EXPECT_GT(c.distance, 0);
}

}  // namespace
}  // namespace s4d
