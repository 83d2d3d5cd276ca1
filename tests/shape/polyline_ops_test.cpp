// Arc-length resampling (at D = 2, 3, 4) and rotation-minimising normals.
#include "shape/polyline_ops.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace s4d {
namespace {

template <int D>
void check_open_resample() {
  // An L-shaped path of length 3 along axes 0 and D-1.
  Vec<D> a = Vec<D>::Zero(), b = Vec<D>::Zero(), c = Vec<D>::Zero();
  b[0] = 2;
  c[0] = 2;
  c[D - 1] = 1;
  const auto out = resample_by_arc_length<D>({a, b, c}, 7, false);
  ASSERT_EQ(out.size(), 7u);
  EXPECT_TRUE(out.front().isApprox(a));
  EXPECT_TRUE(out.back().isApprox(c));
  for (std::size_t i = 0; i + 1 < out.size(); ++i) EXPECT_NEAR((out[i + 1] - out[i]).norm(), 0.5, 1e-12);
}

TEST(Resample, OpenPolylineEvenSpacingAtEveryDimension) {
  check_open_resample<2>();
  check_open_resample<3>();
  check_open_resample<4>();
}

TEST(Resample, ClosedSquare) {
  const std::vector<Vec2> sq{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  const auto out = resample_by_arc_length<2>(sq, 8, true);
  ASSERT_EQ(out.size(), 8u);
  for (std::size_t i = 0; i < out.size(); ++i)
    EXPECT_NEAR((out[(i + 1) % 8] - out[i]).norm(), 0.5, 1e-12);
}

TEST(Resample, RejectsBadInput) {
  EXPECT_THROW(resample_by_arc_length<3>({Vec3::Zero()}, 5, false), Error);
  EXPECT_THROW(resample_by_arc_length<3>({Vec3::Zero(), Vec3::Zero()}, 5, false), Error);
}

TEST(RotationMinimisingNormals, HelixFrameHasTheKnownTwist) {
  // On a helix of radius a, pitch 2πb, the RMF turns relative to the Frenet normal at the rate
  // of the torsion τ = b / (a² + b²) per unit length; the normals must stay unit and
  // perpendicular to the tangent, and their angle to the Frenet normal must grow like τ s.
  const double a = 1.0, b = 0.5;
  const int n = 4000;
  const double turns = 2.0;
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * turns * i / (n - 1);
    pts.emplace_back(a * std::cos(t), a * std::sin(t), b * t);
  }
  const auto r = rotation_minimising_normals(pts, false, Vec3(-1, 0, 0));  // Frenet normal at t=0
  const auto tan = polyline_tangents(pts, false);
  const double speed = std::sqrt(a * a + b * b), tau = b / (a * a + b * b);
  for (int i = 0; i < n; i += 397) {
    EXPECT_NEAR(r[i].norm(), 1.0, 1e-12);
    EXPECT_NEAR(r[i].dot(tan[i]), 0.0, 1e-12);
    const double t = 2 * std::numbers::pi * turns * i / (n - 1);
    const Vec3 frenet(-std::cos(t), -std::sin(t), 0);
    const double angle = std::acos(std::clamp(r[i].dot(frenet), -1.0, 1.0));
    const double expected = std::fmod(tau * speed * t, 2 * std::numbers::pi);
    const double wrapped = std::min(expected, 2 * std::numbers::pi - expected);
    EXPECT_NEAR(angle, wrapped, 2e-3) << "at t = " << t;
  }
}

TEST(RotationMinimisingNormals, PlanarCurveKeepsItsNormalOutOfPlane) {
  // For a plane curve the binormal is rotation-minimising: starting along it, it stays.
  std::vector<Vec3> pts;
  for (int i = 0; i < 300; ++i) {
    const double t = 0.02 * i;
    pts.emplace_back(t, std::sin(3 * t), 0.0);
  }
  const auto r = rotation_minimising_normals(pts, false, Vec3(0, 0, 1));
  for (const Vec3& v : r) EXPECT_NEAR(v.z(), 1.0, 1e-9);
  // An initial normal along the first tangent defines no frame.
  EXPECT_THROW(rotation_minimising_normals(pts, false, pts[1] - pts[0]), Error);
}

}  // namespace
}  // namespace s4d
