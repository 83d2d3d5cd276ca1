// The simulated Omni's published limits and the mouse proxy's virtual coupling.
#include "haptics/simulated_arm.hpp"

#include <gtest/gtest.h>

#include "haptics/mouse_device.hpp"

namespace s4d {
namespace {

TEST(SimulatedArm, SaturatesAtThePeakForceAndDeratesWhenHot) {
  SimulatedArm arm;
  DeviceState s;
  arm.write_force(Vec3(10, 0, 0));
  EXPECT_NEAR(arm.motor_force().norm(), 3.3, 1e-12);
  // Ask for 2 N (above the 0.88 N continuous rating) for 30 s: once hot, the RMS settles at the rating.
  double sum2 = 0;
  bool limited = false;
  for (int i = 0; i < 30000; ++i) {
    arm.write_force(Vec3(0, 0, 2));
    arm.read({1e-3}, s);
    limited = limited || arm.thermally_limited();
    if (i >= 20000) sum2 += arm.motor_force().squaredNorm();
  }
  EXPECT_TRUE(limited);
  EXPECT_NEAR(std::sqrt(sum2 / 10000), 0.88, 0.1);
}

TEST(SimulatedArm, HandPullsTheStylusAndEncodersQuantise) {
  SimulatedArm arm;
  arm.set_hand_script([](double) { return Vec3(0.01, 0, 0); });
  DeviceState s;
  for (int i = 0; i < 2000; ++i) arm.read({1e-3}, s);
  EXPECT_NEAR(arm.true_position().x(), 0.01, 1e-5) << "the hand spring brings the stylus to rest there";
  EXPECT_NEAR(s.position.x(), 0.01, 5.5e-5);
  const double steps = s.position.x() / 5.5e-5;
  EXPECT_NEAR(steps, std::round(steps), 1e-6) << "reported on the encoder grid";
  EXPECT_LT(s.velocity.norm(), 1e-3);
}

TEST(SimulatedArm, EndStopsHoldTheWorkspace) {
  SimulatedArm arm;
  arm.set_hand_script([](double) { return Vec3(0, 0, 0.5); });  // aims half a metre away
  DeviceState s;
  for (int i = 0; i < 3000; ++i) arm.read({1e-3}, s);
  EXPECT_LT(arm.true_position().z(), 0.035 + 0.5 * 300 / 5000.0 + 1e-3);
  EXPECT_GT(arm.true_position().z(), 0.035);
}

TEST(SimulatedArm, UnpluggedReportsDisconnected) {
  SimulatedArm arm;
  DeviceState s;
  EXPECT_EQ(arm.read({1e-3}, s), DeviceStatus::ok);
  arm.set_connected(false);
  EXPECT_EQ(arm.read({1e-3}, s), DeviceStatus::disconnected);
  EXPECT_FALSE(arm.reconnect());
  arm.set_connected(true);
  EXPECT_TRUE(arm.reconnect());
}

TEST(MouseDevice, ProxyFollowsTheCursorAndLagsByForceOverStiffness) {
  MouseDevice mouse;
  DeviceInput in;
  in.pointer_target = Vec3(0.02, -0.01, 0.005);
  in.pointer_valid = true;
  in.pointer_buttons = 3;
  DeviceState s;
  for (int i = 0; i < 2000; ++i) mouse.read(in, s);
  EXPECT_LT((s.position - in.pointer_target).norm(), 1e-6);
  EXPECT_EQ(s.buttons, 3u);
  EXPECT_EQ(s.target, in.pointer_target);
  // A steady 0.6 N from the scene: the proxy settles 0.6 / 300 = 2 mm behind the cursor.
  mouse.write_force(Vec3(0, 0.6, 0));
  for (int i = 0; i < 3000; ++i) mouse.read(in, s);
  EXPECT_NEAR(s.position.y() - in.pointer_target.y(), 0.6 / 300, 1e-7);
  // The cursor outside the box: the target is clamped to the workspace.
  in.pointer_target = Vec3(1, 0, 0);
  mouse.write_force(Vec3::Zero());
  for (int i = 0; i < 3000; ++i) mouse.read(in, s);
  EXPECT_NEAR(s.position.x(), 0.08, 1e-9);
}

}  // namespace
}  // namespace s4d
