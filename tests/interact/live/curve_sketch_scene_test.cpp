// The touch sketch: Eq. 3's repulsion at known distances, strands that stop a stroke without a
// choice and let it through with one (Gauss codes checked), closing, Backspace, a two-stroke link
// and a device that vanishes mid-stroke — driven through the haptic loop by replayed trajectories.
#include "interact/live/curve_sketch_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <sstream>

#include "core/error.hpp"
#include "haptics/haptic_loop.hpp"
#include "haptics/mouse_device.hpp"
#include "haptics/replay_device.hpp"
#include "haptics/simulated_arm.hpp"
#include "interact/live/touch_sketch_run.hpp"
#include "knots/knot_diagram.hpp"
#include "knots/knot_identify.hpp"

namespace s4d {
namespace {

DeviceState at(double x, double y, std::uint32_t buttons, const Vec3& v = Vec3::Zero()) {
  DeviceState s;
  s.position = s.target = Vec3(x, y, 0);
  s.velocity = v;
  s.buttons = buttons;
  return s;
}

// A sketch with one strand of the scene: the line x = 0.01 m.
void with_wall(CurveSketch& k) {
  k.begin(0);
  auto o = std::make_unique<SketchStrands>();
  FixedStrand f;
  f.points = {Vec2(0.01, -0.05), Vec2(0.01, 0.05)};
  f.depth = {0, 0};
  f.closed = false;
  o->strands.push_back(f);
  k.offer_obstacles(std::move(o));
}

TEST(CurveSketch, RepulsionFollowsEq3AwayFromTheStrandBoundedAndFinite) {
  CurveSketch k;
  with_wall(k);
  const RepulsionParams& p = k.settings().repulsion;
  k.step(at(-0.02, 0, kSketchDraw), 1e-3);  // the press
  const Vec3 towards(0.1, 0, 0);            // m/s, at the strand
  // With a choice held the head is not stopped (no wall): the force is the repulsion alone.
  auto force_at = [&](double s) { return k.step(at(0.01 - s, 0, kSketchDraw | kSketchOver, towards), 1e-3); };
  for (const double s : {0.010, 0.008, 0.005, 0.003, 0.002}) {
    const ToolOutput out = force_at(s);
    ASSERT_TRUE(out.force.allFinite());
    EXPECT_LT(out.force.x(), 0) << "pushes away from the strand at S = " << s;
    EXPECT_NEAR(out.force.norm(), p.h * std::pow(s, -1 - p.beta), 1e-9) << "Eq. 3 at S = " << s;
    EXPECT_NEAR(out.force.y(), 0, 1e-12);
  }
  // Halving S multiplies the force by 2^(1 + beta).
  const double f4 = force_at(0.004).force.norm(), f2 = force_at(0.002).force.norm();
  EXPECT_NEAR(f2 / f4, std::pow(2.0, 1 + p.beta), 1e-9);
  // Closer than s_min the force is capped; moving away (or standing) is free.
  EXPECT_NEAR(force_at(0.0002).force.norm(), p.max_force, 1e-9);
  EXPECT_NEAR(k.step(at(0.005, 0, kSketchDraw, -towards), 1e-3).force.norm(), 0, 1e-12);
  EXPECT_NEAR(k.step(at(-0.02, 0, kSketchDraw, towards), 1e-3).force.norm(), 0, 1e-12) << "beyond the range";
  // A non-finite velocity gives a finite force.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(k.step(at(0.005, 0, kSketchDraw, Vec3(nan, 0, 0)), 1e-3).force.allFinite());
  EXPECT_TRUE(k.step(at(nan, 0, kSketchDraw), 1e-3).force.allFinite());
}

TEST(CurveSketch, WithoutAChoiceTheHeadStopsBeforeTheStrandAndTheWallPullsBack) {
  CurveSketch k;
  with_wall(k);
  k.step(at(0.0, 0, kSketchDraw), 1e-3);
  for (int i = 1; i <= 40; ++i) k.step(at(0.0005 * i, 0, kSketchDraw), 1e-3);  // to x = 2 cm: through it
  const SketchPublished& p = k.latest();
  EXPECT_TRUE(p.blocked);
  EXPECT_LT(p.status.head.x(), 0.01 - 0.5 * k.settings().margin) << "the head stays before the strand";
  EXPECT_GE(p.status.crossings_refused, 1u);
  const ToolOutput out = k.step(at(0.02, 0, kSketchDraw), 1e-3);
  EXPECT_LT(out.force.x(), -1.0) << "the wall spring pulls the hand back";
  EXPECT_LE(out.force.norm(), k.settings().wall_max + k.settings().repulsion.max_force + 1e-9);
  // With shift (under) held, the same move goes through.
  CurveSketch c;
  with_wall(c);
  c.step(at(0.0, 0, kSketchDraw), 1e-3);
  for (int i = 1; i <= 40; ++i) c.step(at(0.0005 * i, 0, kSketchDraw | kSketchUnder), 1e-3);
  EXPECT_FALSE(c.latest().blocked);
  EXPECT_NEAR(c.latest().status.head.x(), 0.02, 0.002) << "through (published within 4 ticks)";
  ASSERT_EQ(c.latest().crossing_count, 1);
  EXPECT_EQ(c.latest().crossings[0].choice, CrossChoice::kUnder);
}

// The device's force passes the safety layer: finite and within the device's limits, always.
TEST(CurveSketch, ForcesThroughTheLoopAreFiniteAndClamped) {
  auto scene = std::make_unique<CurveSketchScene>();
  CurveSketch& k = scene->curve_sketch();
  with_wall(k);
  MouseProxyConfig mc;
  auto mouse = std::make_unique<MouseDevice>(mc);
  const double limit = mouse->capabilities().max_force;
  HapticLoopConfig cfg;
  cfg.realtime_priority = false;
  HapticLoop loop(std::move(mouse), std::move(scene), cfg);
  double worst = 0;
  for (int i = 0; i < 3000; ++i) {
    const double x = -0.02 + 0.04 * std::min(1.0, i / 2000.0);  // the cursor drives through the strand
    loop.set_pointer(Vec3(x, 0.001 * std::sin(i * 0.01), i % 500 == 7 ? 0.03 : 0), kSketchDraw);
    loop.run_ticks(1);
    const HapticSnapshot& s = loop.snapshot();
    ASSERT_TRUE(s.force_output.allFinite());
    worst = std::max(worst, s.force_output.norm());
  }
  EXPECT_LE(worst, limit + 1e-9);
  EXPECT_GT(worst, 0.5) << "the wall was felt";
  const SketchPublished& p = k.latest();
  EXPECT_LT(p.status.head.x(), 0.01) << "the stroke never got across";
  EXPECT_GT(p.status.max_lag_near, 0.002) << "the proxy lagged behind the cursor at the strand";
}

// [SECTION] replayed trajectories
constexpr double kTwoPi = 2 * std::numbers::pi;

// The trefoil's shadow (scale in m) traced in `seconds`, with the buttons `choose(t)` holds.
Trajectory trefoil(double scale, double seconds, const std::function<std::uint32_t(double)>& choose, double turns = 1.02) {
  Trajectory tr;
  tr.header.scene = "curve-sketch";
  const int n = static_cast<int>(seconds * 1000);
  Vec3 last = Vec3::Zero();
  for (int i = 0; i <= n; ++i) {
    const double t = kTwoPi * turns * i / n;
    const Vec3 p(scale * (std::sin(t) + 2 * std::sin(2 * t)), scale * (std::cos(t) - 2 * std::cos(2 * t)), 0);
    TickRecord r;
    r.tick = static_cast<std::uint64_t>(i);
    DeviceState s;
    s.position = s.target = p;
    s.velocity = i > 0 ? Vec3((p - last) * 1000.0) : Vec3::Zero();
    s.buttons = choose(t);
    r.set_state(s);
    tr.ticks.push_back(r);
    last = p;
  }
  return tr;
}

TouchSketchResult replay(Trajectory t) {
  return run_touch_sketch(std::make_unique<ReplayDevice>(std::move(t), false), {}, TouchSketchOptions{});
}

std::vector<int> gauss_numbers(const std::string& code) {
  std::vector<int> v;
  std::string s = code;
  for (char& c : s)
    if (c == ',' || c == '|') c = ' ';
  std::istringstream in(s);
  int k = 0;
  while (in >> k) v.push_back(k);
  return v;
}

// Fig. 4: under, over, under ... — the alternating choice at every crossing the stroke makes.
std::uint32_t alternating(double t) { return kSketchDraw | (-std::sin(3 * t) < 0 ? kSketchUnder : kSketchOver); }

TEST(TouchSketch, AReplayedTrefoilWithItsChoicesIsTheTrefoil) {
  const TouchSketchResult r = replay(trefoil(0.012, 4.0, alternating));
  ASSERT_EQ(r.strokes.component_count, 1);
  EXPECT_EQ(r.strokes.closed[0], 1) << "it closed near its start";
  EXPECT_EQ(r.link.crossings, 3);
  const std::vector<int> g = gauss_numbers(r.gauss);
  ASSERT_EQ(g.size(), 6u) << r.gauss;
  for (std::size_t i = 1; i < g.size(); ++i) EXPECT_LT(g[i] * g[i - 1], 0) << "over and under alternate: " << r.gauss;
  EXPECT_EQ(identify_knot(r.link.curve).name.rfind("3_1", 0), 0u);
  EXPECT_GT(r.strokes.status.max_repulsion, 0.05) << "the strands were felt on the way";
  EXPECT_EQ(r.strokes.status.crossings_refused, 0u);
}

TEST(TouchSketch, ChoicesDecideOverAndUnder) {
  // Every later passage under: a descending diagram, the unknot, with its three crossings.
  const TouchSketchResult r = replay(trefoil(0.012, 4.0, [](double) { return kSketchDraw | kSketchUnder; }));
  ASSERT_EQ(r.link.crossings, 3);
  const std::vector<int> g = gauss_numbers(r.gauss);
  ASSERT_EQ(g.size(), 6u);
  // Each crossing is met first over (the earlier strand) and then under (the later one).
  std::vector<int> seen(4, 0);
  for (int k : g) {
    const int c = std::abs(k);
    if (seen[c]++ == 0) EXPECT_GT(k, 0) << r.gauss;
    else EXPECT_LT(k, 0) << r.gauss;
  }
  EXPECT_EQ(identify_knot(r.link.curve).name, "unknot");
}

TEST(TouchSketch, WithoutAChoiceTheStrokeDoesNotCross) {
  const TouchSketchResult r = replay(trefoil(0.012, 4.0, [](double) { return kSketchDraw; }));
  EXPECT_LT(r.link.crossings, 3) << "fewer crossings than the free stroke: " << r.gauss;
  EXPECT_GE(r.strokes.status.crossings_refused, 1u);
  EXPECT_GT(r.strokes.status.blocked_ticks, 0u);
}

Trajectory circles(const std::vector<std::pair<Vec2, std::function<std::uint32_t(double)>>>& strokes, double r,
                   double seconds_each) {
  Trajectory tr;
  std::uint64_t tick = 0;
  Vec3 last = Vec3::Zero();
  for (const auto& [c, choose] : strokes) {
    const int n = static_cast<int>(seconds_each * 1000);
    for (int i = -200; i <= n + 200; ++i) {  // pen up before and after each
      const double a = kTwoPi * 1.05 * std::clamp(i, 0, n) / n;
      const Vec3 p(c.x() + r * std::cos(a), c.y() + r * std::sin(a), 0);
      TickRecord rec;
      rec.tick = tick++;
      DeviceState s;
      s.position = s.target = p;
      s.velocity = (p - last) * 1000.0;
      s.buttons = i >= 0 && i <= n ? choose(a) : 0u;
      rec.set_state(s);
      tr.ticks.push_back(rec);
      last = p;
    }
  }
  return tr;
}

TEST(TouchSketch, ClosingNearTheStartClosesTheComponent) {
  const TouchSketchResult r = replay(circles({{Vec2(0, 0), [](double) { return kSketchDraw; }}}, 0.02, 2.0));
  ASSERT_EQ(r.strokes.component_count, 1);
  EXPECT_EQ(r.strokes.closed[0], 1);
  // Nothing was drawn past the closing: about one circumference of points.
  const double circumference = kTwoPi * 0.02;
  EXPECT_LT(r.strokes.point_count, circumference / TouchSketchOptions{}.settings.spacing * 1.02);
  EXPECT_EQ(r.link.crossings, 0);
  EXPECT_EQ(identify_knot(r.link.curve).name, "unknot");
}

TEST(TouchSketch, TwoStrokesMakeALinkWithItsLinkingNumber) {
  // The second circle crosses the first twice: under then over links them, over twice does not.
  auto under_then_over = [](double a) { return kSketchDraw | (a < std::numbers::pi ? kSketchUnder : kSketchOver); };
  const TouchSketchResult hopf = replay(
      circles({{Vec2(-0.012, 0), [](double) { return kSketchDraw; }}, {Vec2(0.012, 0), under_then_over}}, 0.02, 2.0));
  ASSERT_EQ(hopf.link.curve.components.size(), 2u);
  EXPECT_EQ(hopf.link.crossings, 2);
  const auto lk = diagram_from_curve(hopf.link.curve, Frame<3>()).linking_numbers();
  EXPECT_EQ(std::abs(lk[0][1]), 1);
  const TouchSketchResult apart = replay(circles(
      {{Vec2(-0.012, 0), [](double) { return kSketchDraw; }}, {Vec2(0.012, 0), [](double) { return kSketchDraw | kSketchOver; }}},
      0.02, 2.0));
  ASSERT_EQ(apart.link.curve.components.size(), 2u);
  EXPECT_EQ(diagram_from_curve(apart.link.curve, Frame<3>()).linking_numbers()[0][1], 0);
}

TEST(CurveSketch, BackspaceRemovesTheLastSegment) {
  CurveSketch k;
  k.begin(0);
  auto stroke = [&](double x0, double x1) {
    for (int i = 0; i <= 200; ++i) k.step(at(x0 + (x1 - x0) * i / 200.0, 0.001 * i * (200 - i) / 100.0, kSketchDraw), 1e-3);
    for (int i = 0; i < 5; ++i) k.step(at(x1, 0, 0), 1e-3);
  };
  stroke(-0.03, -0.01);
  const int first = k.latest().point_count;
  ASSERT_GT(first, 5);
  stroke(-0.01 + 0.0005, 0.01);  // pressed near the end: the same component goes on
  ASSERT_EQ(k.latest().component_count, 1);
  ASSERT_GT(k.latest().point_count, first + 5);
  k.backspace();
  EXPECT_EQ(k.latest().point_count, first);
  EXPECT_EQ(k.latest().component_count, 1);
  // While drawing: the segment being drawn goes, and drawing waits for the button's release.
  for (int i = 0; i <= 100; ++i) k.step(at(-0.01 + 0.0002 * i, 0.0001 * i, kSketchDraw), 1e-3);
  ASSERT_TRUE(k.latest().drawing);
  k.backspace();
  EXPECT_EQ(k.latest().point_count, first);
  for (int i = 0; i <= 50; ++i) k.step(at(0.01, 0.0002 * i, kSketchDraw), 1e-3);
  EXPECT_EQ(k.latest().point_count, first) << "nothing is drawn until the button is pressed again";
  k.backspace();
  EXPECT_EQ(k.latest().point_count, 0);
  EXPECT_EQ(k.latest().component_count, 0);
  k.backspace();  // nothing left: no harm
  EXPECT_EQ(k.latest().point_count, 0);
}

TEST(TouchSketch, ADeviceThatVanishesMidStrokeLosesNothing) {
  const auto draw = [](double) { return kSketchDraw; };
  const Trajectory whole = circles({{Vec2(0, 0), draw}}, 0.02, 2.0);
  Trajectory gap = whole;
  for (std::size_t i = 900; i < 1300; ++i) gap.ticks[i].events |= kEventDisconnected;
  const TouchSketchResult a = replay(whole), b = replay(gap);
  EXPECT_EQ(b.disconnected_ticks, 400u);
  ASSERT_EQ(b.strokes.component_count, 1);
  EXPECT_EQ(b.strokes.closed[0], 1) << "the stroke went on once the device was back";
  // Every point drawn before the device went is still there, unchanged.
  const int before = 20;  // points drawn well within the first 700 ms (of 2 s for the circle)
  ASSERT_GT(a.strokes.point_count, before);
  ASSERT_GT(b.strokes.point_count, before);
  for (int i = 0; i < before; ++i) EXPECT_EQ(a.strokes.points[i], b.strokes.points[i]) << i;
  // Gone for good mid-stroke: what was drawn is kept and still makes its curve.
  Trajectory lost = whole;
  for (std::size_t i = 1200; i < lost.ticks.size(); ++i) lost.ticks[i].events |= kEventDisconnected;
  const TouchSketchResult c = replay(lost);
  EXPECT_GT(c.strokes.point_count, before);
  EXPECT_EQ(c.link.curve.components.size(), 1u);
  EXPECT_EQ(c.safety_nonfinite, 0u);
}

TEST(TouchSketch, BadInputIsRefusedClearly) {
  EXPECT_THROW(run_touch_sketch(nullptr, {}, {}), Error);
  TouchSketchOptions o;
  o.plane_z = std::numeric_limits<double>::infinity();
  EXPECT_THROW(run_touch_sketch(std::make_unique<MouseDevice>(), {}, o), Error);
  EXPECT_THROW(hand_from_stroke({Vec3(0, 0, 0), Vec3(1, 1, 7)}, 0.01, 1000, Vec3::Zero(), Vec2(0.05, 0.05)), Error);
  EXPECT_THROW(hand_from_stroke({Vec3(0, 0, 0), Vec3(0, 0, 0)}, 0.01, 1000, Vec3::Zero(), Vec2(0.05, 0.05)), Error);
  // Nothing drawn: no knot, and it says why.
  Trajectory idle = circles({{Vec2(0, 0), [](double) { return 0u; }}}, 0.02, 0.5);
  try {
    replay(idle);
    FAIL() << "an idle device made a knot";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nothing was sketched"), std::string::npos) << e.what();
  }
}

TEST(TouchSketch, TheSimulatedArmFollowsAStrokeAndItsRecordingReplaysTheSame) {
  std::vector<Vec3> samples;
  for (int i = 0; i <= 480; ++i) {
    const double t = kTwoPi * 1.02 * i / 480;
    samples.emplace_back(std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t),
                         -std::sin(3 * t) < 0 ? 1.0 : 2.0);
  }
  auto arm = std::make_unique<SimulatedArm>();
  const DeviceCapabilities caps = arm->capabilities();
  const Vec3 half = 0.5 * (caps.workspace_max - caps.workspace_min);
  const std::vector<HandSample> hand =
      hand_from_stroke(samples, 1.0 / 120, 1000, caps.workspace_centre(), 0.8 * Vec2(half.x(), half.y()));
  TouchSketchOptions o;
  o.record = std::filesystem::temp_directory_path() / "s4d_touch_sketch_sim.traj";
  const TouchSketchResult r = run_touch_sketch(std::move(arm), hand, o);
  EXPECT_EQ(identify_knot(r.link.curve).name.rfind("3_1", 0), 0u) << r.gauss;
  EXPECT_LE(r.max_force, caps.max_force + 1e-9);
  // The recording, replayed through the same scene, gives the same knot and the same forces.
  Trajectory t = read_trajectory(o.record);
  EXPECT_EQ(sketch_plane_of_setup(t.header.setup, 99), 0.0);
  const TouchSketchResult back = run_touch_sketch(std::make_unique<ReplayDevice>(std::move(t), true), {}, TouchSketchOptions{});
  EXPECT_EQ(back.gauss, r.gauss);
  EXPECT_EQ(back.replay_mismatches, 0u);
}

}  // namespace
}  // namespace s4d
