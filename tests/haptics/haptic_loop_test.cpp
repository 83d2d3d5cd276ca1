// The haptic loop: bit-identical replay of a recorded session, surviving a device that vanishes and
// comes back, the real-time thread (period statistics, commands, device swap, snapshots).
#include "haptics/haptic_loop.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <thread>

#include "core/error.hpp"
#include "haptics/mouse_device.hpp"
#include "haptics/replay_device.hpp"
#include "haptics/simulated_arm.hpp"
#include "haptics/sticky_plane_scene.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

std::unique_ptr<SimulatedArm> circling_arm() {
  auto arm = std::make_unique<SimulatedArm>();
  arm->set_position(Vec3(0.02, 0, 0));
  arm->set_hand_script([](double t) {
    return Vec3(0.02 * std::cos(3 * t), 0.02 * std::sin(3 * t), -0.002 + 0.004 * std::sin(7 * t));
  });
  return arm;
}

// A simulating scene for the loop's tests (the cloth itself is the interact layer's, tested there):
// a 10 g point on a lightly damped band to the device, which keeps swinging while the hand rests.
class BandedMass final : public HapticScene {
 public:
  enum Param { kK, kB, kParamCount };
  BandedMass() {
    params_[kK] = {"K", 100, 0, 1000, "N/m"};
    params_[kB] = {"B", 0.05, 0, 10, "N s/m"};
  }
  std::string_view name() const override { return "banded-mass"; }
  ToolOutput step(const DeviceState& d, double dt) override {
    const Vec3 f = params_[kK].value * (d.position - x_) + params_[kB].value * (d.velocity - v_);  // on the mass
    v_ += dt * f / kMass;
    x_ += dt * v_;
    ToolOutput out;
    out.force = -f;
    out.anchor = x_;
    out.engaged = true;
    return out;
  }
  void reset() override { x_ = v_ = Vec3::Zero(); }
  std::span<SceneParam> params() override { return params_; }
  int point_count() const override { return 1; }
  void copy_points(std::span<double> out) const override {
    for (int k = 0; k < 3; ++k) out[static_cast<std::size_t>(k)] = x_[k];
  }

 private:
  static constexpr double kMass = 0.01;  // kg
  std::array<SceneParam, kParamCount> params_;
  Vec3 x_ = Vec3::Zero(), v_ = Vec3::Zero();  // m, m/s
};

// Records a session with resets and an unplugged cable, then replays it through a fresh scene.
template <typename MakeScene>
void expect_bit_identical_replay(MakeScene make_scene, const std::string& name) {
  const fs::path file = fs::temp_directory_path() / ("s4d_haptics_" + name + ".traj");
  std::uint64_t ticks = 0;
  {
    auto arm = circling_arm();
    SimulatedArm* a = arm.get();
    HapticLoop loop(std::move(arm), make_scene());
    loop.record_to(file);
    loop.run_ticks(700);
    loop.reset_scene();
    loop.run_ticks(300);
    a->set_connected(false);
    loop.run_ticks(50);
    a->set_connected(true);
    loop.run_ticks(950);
    ticks = loop.ticks();
    loop.finish_recording();
  }
  Trajectory t = read_trajectory(file);
  ASSERT_EQ(t.ticks.size(), ticks);
  EXPECT_EQ(t.header.device, "sim");
  EXPECT_EQ(t.header.scene, name);
  std::uint64_t nonzero = 0;
  for (const auto& r : t.ticks) nonzero += r.force[0] != 0 || r.force[1] != 0 || r.force[2] != 0;
  EXPECT_GT(nonzero, ticks / 2) << "the session produced forces worth comparing";

  auto replay = std::make_unique<ReplayDevice>(t, true);
  ReplayDevice* rp = replay.get();
  HapticLoop again(std::move(replay), make_scene());
  again.run_ticks(ticks);
  EXPECT_EQ(rp->compared(), ticks - 50) << "every connected tick compared";
  EXPECT_EQ(rp->mismatches(), 0u) << "first mismatch at tick " << rp->first_mismatch_tick();

  // The comparison can fail: a different parameter gives different forces.
  auto replay2 = std::make_unique<ReplayDevice>(t, true);
  ReplayDevice* rp2 = replay2.get();
  HapticLoop changed(std::move(replay2), make_scene());
  changed.set_param(0, changed.scene().params()[0].value * 1.01);
  changed.run_ticks(ticks);
  EXPECT_GT(rp2->mismatches(), 0u);
}

TEST(HapticLoop, ReplayOfARecordingGivesBitIdenticalForcesStickyPlane) {
  expect_bit_identical_replay([] { return std::make_unique<StickyPlaneScene>(); }, "sticky-plane");
}

TEST(HapticLoop, ReplayOfARecordingGivesBitIdenticalForcesSimulatingScene) {
  expect_bit_identical_replay([] { return std::make_unique<BandedMass>(); }, "banded-mass");
}

TEST(HapticLoop, SurvivesTheDeviceVanishingAndComingBack) {
  auto arm = circling_arm();
  SimulatedArm* a = arm.get();
  HapticLoop loop(std::move(arm), std::make_unique<BandedMass>());
  loop.run_ticks(1000);
  ASSERT_GT(loop.safety().last_output().norm(), 0) << "forces on before the cable is pulled";
  const std::vector<double> before = loop.snapshot().points;
  a->set_connected(false);
  loop.run_ticks(1);
  EXPECT_EQ(loop.safety().last_output(), Vec3::Zero()) << "zero force the tick the device vanishes";
  loop.run_ticks(700);
  const HapticSnapshot& gone = loop.snapshot();
  EXPECT_FALSE(gone.device_connected);
  EXPECT_EQ(gone.tick, 1701u) << "the loop kept running";
  EXPECT_NE(gone.points, before) << "the simulation kept running (the mass moved)";
  EXPECT_EQ(gone.points.size(), before.size()) << "and the scene is still there";
  a->set_connected(true);
  loop.run_ticks(1);
  EXPECT_TRUE(loop.snapshot().device_connected);
  EXPECT_EQ(loop.snapshot().reconnects, 1u);
  EXPECT_LT(loop.safety().gain(), 0.01) << "fades in again instead of jumping";
  loop.run_ticks(1500);
  EXPECT_EQ(loop.safety().phase(), SafetyPhase::active);
  EXPECT_GT(loop.safety().last_output().norm(), 0);
}

// A recording's cable pulls are replayed as such: each counts as a loss, each return as a recovery.
TEST(HapticLoop, AReplayedDisconnectIsGoneAndBackAgain) {
  Trajectory t;
  t.header.caps.outputs_force = true;
  for (std::uint64_t i = 0; i < 100; ++i) {
    TickRecord r;
    r.tick = i;
    if ((i >= 20 && i < 30) || (i >= 60 && i < 65)) r.events = kEventDisconnected;
    t.ticks.push_back(r);
  }
  HapticLoop loop(std::make_unique<ReplayDevice>(t, false), std::make_unique<BandedMass>());
  loop.run_ticks(25);
  EXPECT_FALSE(loop.snapshot().device_connected);
  EXPECT_EQ(loop.snapshot().disconnects, 1u);
  EXPECT_EQ(loop.snapshot().reconnects, 0u);
  loop.run_ticks(75);
  EXPECT_TRUE(loop.snapshot().device_connected);
  EXPECT_EQ(loop.snapshot().disconnects, 2u);
  EXPECT_EQ(loop.snapshot().reconnects, 2u);
}

TEST(HapticLoop, ThreadRunsAtTheRateAndTakesCommands) {
  auto scene = std::make_unique<StickyPlaneScene>();
  HapticLoop loop(circling_arm(), std::move(scene));
  loop.start();
  EXPECT_THROW(loop.start(), Error);
  EXPECT_THROW(loop.run_ticks(1), Error);
  EXPECT_TRUE(loop.set_param(StickyPlaneScene::kH, 321));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  loop.replace_device(std::make_unique<MouseDevice>());
  loop.set_pointer(Vec3(0.01, 0.02, 0.0), 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const HapticSnapshot& s = loop.snapshot();
  EXPECT_TRUE(s.running);
  EXPECT_EQ(s.params[StickyPlaneScene::kH].value, 321);
  EXPECT_STREQ(s.device_name, "mouse");
  EXPECT_EQ(s.device.buttons, 1u) << "the pointer reached the mouse proxy";
  EXPECT_NEAR(s.device.target.x(), 0.01, 1e-12);
  loop.stop();
  const PeriodSummary p = loop.snapshot().period;
  // 0.6 s at 1 kHz; generous bounds, the build machine is shared and loaded.
  EXPECT_GT(loop.ticks(), 300u);
  EXPECT_LT(loop.ticks(), 700u);
  EXPECT_GT(p.ticks, 300u);
  EXPECT_GT(p.p50_us, 900);
  EXPECT_LT(p.p50_us, 1200);
  EXPECT_GE(p.max_us, p.p999_us);
  EXPECT_GE(p.p999_us, p.p99_us);
  EXPECT_FALSE(loop.snapshot().running);
  // Posting with the thread stopped applies at once.
  loop.reset_stats();
  EXPECT_EQ(loop.snapshot().period.ticks, 0u);
}

TEST(HapticLoop, RejectsBadConfiguration) {
  HapticLoopConfig cfg;
  cfg.rate_hz = 5;
  EXPECT_THROW(HapticLoop(std::make_unique<MouseDevice>(), std::make_unique<StickyPlaneScene>(), cfg), Error);
  EXPECT_THROW(HapticLoop(nullptr, std::make_unique<StickyPlaneScene>()), Error);
}

}  // namespace
}  // namespace s4d
