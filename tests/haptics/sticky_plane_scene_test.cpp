// Passivity and stability of the sticky shadow plane (Eq. 1 + Eq. 2) felt through the simulated Omni
// held by the model hand, run through the full loop (safety included).
#include "haptics/sticky_plane_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "haptics/haptic_loop.hpp"
#include "haptics/simulated_arm.hpp"

namespace s4d {
namespace {

struct PlaneRun {
  double max_energy = 0;       // J, arm + hand spring + plane spring
  double final_rms_speed = 0;  // m/s over the last 0.3 s (hand at rest)
  double max_tangent_force = 0;  // N
  double final_offset = 0;     // m, |z| of the stylus at the end
};

// The stylus starts on the plane; the hand presses 3 mm through it, draws a 2 cm circle for 2 s, then rests
// for 1.5 s.
PlaneRun run_sticky_plane(double h, double kd) {
  auto arm = std::make_unique<SimulatedArm>();
  SimulatedArm* a = arm.get();
  a->set_position(Vec3(0.02, 0, 0));
  a->set_hand_script([](double t) {
    const double r = 0.02, w = 2 * M_PI * 0.5;
    const double tt = std::clamp(t - 0.5, 0.0, 2.0);
    return Vec3(r * std::cos(w * tt), r * std::sin(w * tt), t < 0.2 ? 0.0 : -0.003);
  });
  auto scene = std::make_unique<StickyPlaneScene>();
  scene->set_param(StickyPlaneScene::kH, h);
  scene->set_param(StickyPlaneScene::kKd, kd);
  HapticLoopConfig cfg;
  cfg.publish_every = 1000;
  HapticLoop loop(std::move(arm), std::move(scene), cfg);
  PlaneRun r;
  double sum_v2 = 0;
  int n_v2 = 0;
  const int ticks = 4000;
  for (int i = 0; i < ticks; ++i) {
    loop.run_ticks(1);
    const double z = a->true_position().z();
    const double e = a->mechanical_energy() + 0.5 * h * z * z;
    r.max_energy = std::max(r.max_energy, e);
    r.max_tangent_force = std::max(r.max_tangent_force, a->motor_force().head<2>().norm());
    if (i >= ticks - 300) {
      sum_v2 += a->true_velocity().squaredNorm();
      ++n_v2;
    }
  }
  r.final_rms_speed = std::sqrt(sum_v2 / n_v2);
  r.final_offset = std::abs(a->true_position().z());
  return r;
}

TEST(StickyPlaneScene, ForceIsEquationOnePlusRadialDamping) {
  StickyPlaneScene scene;
  scene.set_param(StickyPlaneScene::kH, 800);
  scene.set_param(StickyPlaneScene::kKd, 2);
  DeviceState s;
  s.position = Vec3(0.01, -0.02, 0.004);
  s.velocity = Vec3(0.3, 0.1, -0.05);
  const ToolOutput out = scene.step(s, 1e-3);
  EXPECT_TRUE(out.engaged);
  EXPECT_EQ(out.anchor, Vec3(0.01, -0.02, 0));
  EXPECT_NEAR(out.force.x(), 0, 1e-15) << "tangential motion is force-free";
  EXPECT_NEAR(out.force.y(), 0, 1e-15);
  EXPECT_NEAR(out.force.z(), -800 * 0.004 + 2 * 0.05, 1e-12);
  EXPECT_EQ(scene.find_param("Kd"), StickyPlaneScene::kKd);
  scene.set_param(StickyPlaneScene::kH, 1e9);  // clamped to the slider range
  EXPECT_EQ(scene.params()[StickyPlaneScene::kH].value, 10000);
}

TEST(StickyPlaneScene, StableUpToTheOmniStiffness) {
  for (double h : {200.0, 500.0, 1000.0}) {
    const PlaneRun r = run_sticky_plane(h, 1.0);
    SCOPED_TRACE(h);
    EXPECT_LT(r.max_energy, 0.005) << "energy stays bounded";
    EXPECT_LT(r.final_rms_speed, 2e-3) << "no sustained oscillation once the hand rests";
    EXPECT_LT(r.max_tangent_force, 0.3) << "gliding along the plane is (almost) force-free";
    // At rest the hand (300 N/m, 3 mm through) and the plane balance: |z| = 300*0.003/(300+H).
    EXPECT_NEAR(r.final_offset, 300 * 0.003 / (300 + h), 3e-4);
  }
}

TEST(StickyPlaneScene, DetectorCatchesAnUnstableContact) {
  // Negative control: 5 and 10 N/mm without damping are far beyond what a 1 kHz Omni renders; the
  // sampled spring injects energy and the contact buzzes. The checks above must be able to see that.
  EXPECT_GT(run_sticky_plane(5000, 0.0).final_rms_speed, 2e-3) << "sustained oscillation";
  EXPECT_GT(run_sticky_plane(10000, 0.0).max_energy, 0.005) << "energy grows";
}

}  // namespace
}  // namespace s4d
