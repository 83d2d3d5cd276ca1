// The safety layer: NaN rejection, magnitude and rate clamps, fade-in after a small force, fade-out on
// missed deadlines, resets and disconnects.
#include "haptics/force_safety.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace s4d {
namespace {

constexpr double kDt = 1e-3;

SafetyConfig test_config() {
  SafetyConfig c;
  c.max_force = 3.3;
  c.max_rate = 1000;
  c.fade_in_time = 0.1;
  c.fade_out_time = 0.02;
  c.enable_threshold = 0.3;
  c.miss_hold_time = 0.05;
  return c;
}

// Runs the safety layer until it reaches full force on a constant request.
void arm(ForceSafety& s, const Vec3& f, int ticks = 400) {
  s.apply(Vec3::Zero(), {}, kDt);  // forces enable only from a small request
  for (int i = 0; i < ticks; ++i) s.apply(f, {}, kDt);
}

TEST(ForceSafety, WaitsForASmallForceBeforeEnabling) {
  ForceSafety s(test_config());
  const Vec3 big(2, 0, 0);
  for (int i = 0; i < 500; ++i) EXPECT_EQ(s.apply(big, {}, kDt), Vec3::Zero());
  EXPECT_EQ(s.phase(), SafetyPhase::waiting);
  // The hand is back near the surface: the force is small, forces come on...
  s.apply(Vec3(0.1, 0, 0), {}, kDt);
  EXPECT_EQ(s.phase(), SafetyPhase::fading_in);
  // ...and ramp: after half the fade-in time about half the request.
  for (int i = 0; i < 49; ++i) s.apply(Vec3(1, 0, 0), {}, kDt);
  EXPECT_NEAR(s.gain(), 0.5, 1e-9);
  EXPECT_NEAR(s.last_output().x(), 0.5, 1e-9);
  arm(s, Vec3(1, 0, 0));
  EXPECT_EQ(s.phase(), SafetyPhase::active);
  EXPECT_EQ(s.apply(Vec3(1, 0, 0), {}, kDt), Vec3(1, 0, 0));
}

TEST(ForceSafety, RejectsNonFiniteValues) {
  ForceSafety s(test_config());
  arm(s, Vec3(0.2, 0, 0));
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const Vec3& bad : {Vec3(nan, 0, 0), Vec3(0, inf, 0), Vec3(0, 0, -inf)}) {
    const Vec3 out = s.apply(bad, {}, kDt);
    ASSERT_TRUE(out.allFinite());
    EXPECT_LE(out.norm(), 0.2 + 1e-12);
  }
  EXPECT_EQ(s.counters().nonfinite, 3u);
  // The simulation broke: it is disarmed and has to fade in again from zero.
  for (int i = 0; i < 100; ++i) s.apply(Vec3(0.2, 0, 0), {}, kDt);
  EXPECT_LT(s.gain(), 1.0);
  EXPECT_GE(s.counters().disarms, 1u);
}

TEST(ForceSafety, ClampsMagnitudeToTheDeviceLimit) {
  SafetyConfig c = test_config();
  c.max_rate = 1e9;
  ForceSafety s(c);
  arm(s, Vec3(0.1, 0, 0));
  const Vec3 out = s.apply(Vec3(30, 40, 0), {}, kDt);
  EXPECT_NEAR(out.norm(), 3.3, 1e-12);
  EXPECT_NEAR(out.normalized().dot(Vec3(0.6, 0.8, 0)), 1, 1e-12) << "direction kept";
  EXPECT_EQ(s.counters().clamped, 1u);
}

TEST(ForceSafety, LimitsTheRateOfChange) {
  ForceSafety s(test_config());
  arm(s, Vec3::Zero());
  // A 3 N step is spread over 3 ms at 1000 N/s: no tick changes by more than 1 N.
  Vec3 prev = Vec3::Zero();
  for (int i = 0; i < 5; ++i) {
    const Vec3 out = s.apply(Vec3(0, 3, 0), {}, kDt);
    EXPECT_LE((out - prev).norm(), 1.0 + 1e-12);
    prev = out;
  }
  EXPECT_NEAR(prev.y(), 3.0, 1e-12);
  EXPECT_GE(s.counters().rate_limited, 2u);
}

TEST(ForceSafety, FadesOutOnMissedDeadlinesAndRecovers) {
  ForceSafety s(test_config());
  arm(s, Vec3(1, 0, 0));
  SafetyEvents missed;
  missed.deadline_missed = true;
  s.apply(Vec3(1, 0, 0), missed, kDt);
  EXPECT_EQ(s.phase(), SafetyPhase::fading_out);
  for (int i = 0; i < 30; ++i) s.apply(Vec3(1, 0, 0), {}, kDt);
  EXPECT_EQ(s.last_output(), Vec3::Zero()) << "faded to zero within the fade-out time";
  // Clean ticks after the hold: the force returns by itself (no re-arming needed: the scene is intact).
  arm(s, Vec3(1, 0, 0));
  EXPECT_EQ(s.phase(), SafetyPhase::active);
  EXPECT_EQ(s.last_output(), Vec3(1, 0, 0));
}

TEST(ForceSafety, FadesOutOnResetAndWaitsForSmallForce) {
  ForceSafety s(test_config());
  arm(s, Vec3(1, 0, 0));
  SafetyEvents reset;
  reset.scene_reset = true;
  Vec3 out = s.apply(Vec3(1, 0, 0), reset, kDt);
  EXPECT_LT(out.norm(), 1.0) << "fading out right away";
  for (int i = 0; i < 200; ++i) out = s.apply(Vec3(2, 0, 0), {}, kDt);
  EXPECT_EQ(out, Vec3::Zero()) << "after a reset a large force stays off";
  EXPECT_EQ(s.phase(), SafetyPhase::waiting);
  s.apply(Vec3(0.05, 0, 0), {}, kDt);
  EXPECT_EQ(s.phase(), SafetyPhase::fading_in);
}

TEST(ForceSafety, DisconnectZeroesImmediatelyAndReconnectFadesIn) {
  ForceSafety s(test_config());
  arm(s, Vec3(1, 0, 0));
  SafetyEvents gone;
  gone.device_connected = false;
  EXPECT_EQ(s.apply(Vec3(1, 0, 0), gone, kDt), Vec3::Zero());
  EXPECT_EQ(s.gain(), 0);
  // Back, with the hand pressing hard somewhere: nothing until the request is small, then a ramp.
  EXPECT_EQ(s.apply(Vec3(3, 0, 0), {}, kDt), Vec3::Zero());
  s.apply(Vec3(0.1, 0, 0), {}, kDt);
  const Vec3 first = s.apply(Vec3(1, 0, 0), {}, kDt);
  EXPECT_GT(first.norm(), 0);
  EXPECT_LT(first.norm(), 0.05);
}

TEST(ForceSafety, NeverExceedsLimitsOnRandomInput) {
  ForceSafety s(test_config());
  std::uint64_t state = 12345;
  auto rnd = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / 9007199254740992.0 * 2 - 1;
  };
  Vec3 prev = Vec3::Zero();
  for (int i = 0; i < 20000; ++i) {
    SafetyEvents ev;
    ev.deadline_missed = rnd() > 0.98;
    ev.scene_reset = rnd() > 0.995;
    ev.device_connected = rnd() > -0.99;
    const Vec3 req(10 * rnd(), 10 * rnd(),
                   rnd() > 0.99 ? std::numeric_limits<double>::quiet_NaN() : 10 * rnd());
    const Vec3 out = s.apply(req, ev, kDt);
    ASSERT_TRUE(out.allFinite());
    ASSERT_LE(out.norm(), 3.3 + 1e-12);
    if (ev.device_connected) {
      ASSERT_LE((out - prev).norm(), 1.0 + 1e-9);
    }
    prev = out;
  }
}

TEST(ForceSafety, ConfigFromCapabilities) {
  DeviceCapabilities caps;
  caps.max_force = 3.3;
  caps.max_force_rate = 500;
  caps.outputs_force = true;
  const SafetyConfig c = SafetyConfig::for_device(caps);
  EXPECT_EQ(c.max_force, 3.3);
  EXPECT_EQ(c.max_rate, 500);
  caps.outputs_force = false;
  EXPECT_EQ(SafetyConfig::for_device(caps).max_force, 0);
}

}  // namespace
}  // namespace s4d
