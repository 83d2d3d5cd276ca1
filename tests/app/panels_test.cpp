// The panels' pure helpers, without a window.
#include "app/panels.hpp"

#include <gtest/gtest.h>

namespace s4d {
namespace {

// The depth tone follows the probe from the far side of the view's ball (0) to the near side (1).
TEST(ProbeDepthFraction, AKnotsDepthIsTowardsTheEyeAndASurfacesIsW) {
  Scene scene;
  ViewFit fit;
  fit.centre = Vec4(1, 2, 3, 0.5);
  fit.radius = 2;
  const Vec3 eye = Vec3::UnitZ();
  EXPECT_DOUBLE_EQ(probe_depth_fraction(scene, fit, eye, true, 3), 0.5);   // at the centre's depth
  EXPECT_DOUBLE_EQ(probe_depth_fraction(scene, fit, eye, true, 5), 1.0);   // nearest
  EXPECT_DOUBLE_EQ(probe_depth_fraction(scene, fit, eye, true, 1), 0.0);   // farthest
  EXPECT_DOUBLE_EQ(probe_depth_fraction(scene, fit, eye, true, 40), 1.0);  // clamped
  EXPECT_DOUBLE_EQ(probe_depth_fraction(scene, fit, Vec3::UnitX(), true, 2), 0.75);
  // a surface of R^4: w through the frame
  EXPECT_DOUBLE_EQ(probe_depth_fraction(scene, fit, eye, false, 1.5), 0.75);
  scene.frame.rotate(Plane{0, 3}, 3.141592653589793 / 2);  // xw: w now sees the old x
  EXPECT_NEAR(probe_depth_fraction(scene, fit, eye, false, scene.frame.to_view(fit.centre)(3)), 0.5, 1e-12);
  // nothing to follow: the middle
  EXPECT_DOUBLE_EQ(probe_depth_fraction(scene, fit, eye, true, NAN), 0.5);
  fit.radius = 0;
  EXPECT_DOUBLE_EQ(probe_depth_fraction(scene, fit, eye, true, 3), 0.5);
}

}  // namespace
}  // namespace s4d
