// The GUI's mouse and slider logic, without a window.
#include "app/view_state.hpp"

#include <gtest/gtest.h>

namespace s4d {
namespace {

TEST(ViewState, ShiftDragTurnsTheWPlanes) {
  Scene scene;
  ViewState v;
  v.reset(scene);
  v.drag(DragMode::kRotateW, 100, 0, 600);  // horizontal: xw only
  EXPECT_NEAR(v.plane_angles()[2], 30.0f, 1e-4);
  EXPECT_EQ(v.plane_angles()[4], 0.0f);
  v.drag(DragMode::kRotateW, 0, -200, 600);  // vertical: yw only
  EXPECT_NEAR(v.plane_angles()[4], -60.0f, 1e-4);
  // The composed frame mixes x and w: the x axis gains depth sin(30°) from xw, and yw's
  // cos(60°) scales what the w axis keeps of it.
  v.apply_to(scene);
  EXPECT_NEAR(std::abs(scene.frame.depth(Vec4::UnitX())), 0.25, 1e-6);
}

TEST(ViewState, AnglesWrapIntoHalfTurns) {
  ViewState v;
  v.reset(Scene{});
  for (int i = 0; i < 20; ++i) v.drag(DragMode::kRotateZW, 600, 0, 600);  // 20 × 180°
  EXPECT_LE(std::abs(v.plane_angles()[5]), 180.0f);
  EXPECT_NEAR(std::abs(v.plane_angles()[5]), 0.0f, 1e-3);
}

TEST(ViewState, TrackballDragKeepsFrameAndTurnsCamera) {
  Scene scene;
  ViewState v;
  v.reset(scene);
  v.drag(DragMode::kTrackball, 300, 0, 600);  // 90° about the screen's vertical axis
  v.apply_to(scene);
  EXPECT_TRUE(scene.frame.matrix().isIdentity());
  const Eigen::Vector3d x = scene.view.trackball * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(std::abs(x.z()), 1.0, 1e-9);
}

TEST(ViewState, StartsFromTheScenesFrameAndIgnoresGarbage) {
  Scene scene;
  scene.frame.rotate({0, 3}, 0.5);
  ViewState v;
  v.reset(scene);
  v.drag(DragMode::kRotateW, std::nan(""), 5, 600);
  v.drag(DragMode::kTrackball, 5, 5, 0);
  v.scroll(std::numeric_limits<double>::infinity());
  Scene out;
  v.apply_to(out);
  EXPECT_TRUE(out.frame.matrix().isApprox(scene.frame.matrix()));
  EXPECT_DOUBLE_EQ(out.view.zoom, 1.0);
  v.scroll(1000);
  v.apply_to(out);
  EXPECT_LE(out.view.zoom, 50.0);
}

}  // namespace
}  // namespace s4d

namespace s4d {
namespace {

TEST(ViewState, GenericViewTurnsTheSlidersAndUnfoldsTheShadow) {
  Scene scene;
  ViewState v;
  v.reset(scene);
  v.turn_to_generic_view();
  EXPECT_FLOAT_EQ(v.plane_angles()[2], 30.0f);  // xw
  EXPECT_FLOAT_EQ(v.plane_angles()[5], 20.0f);  // zw
  v.apply_to(scene);
  // Points differing only in w no longer share a shadow point.
  EXPECT_GT((scene.frame.shadow(Vec4::UnitW()) - scene.frame.shadow(Vec4::Zero())).norm(), 0.3);
}

}  // namespace
}  // namespace s4d
