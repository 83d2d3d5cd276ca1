// The curve explorer walks its own strand: once round a knot it has passed every crossing twice,
// once over and once under, in the order of the knot's Gauss code; at a crossing it never jumps
// to the other strand, however near the hand is to it.
#include "interact/live/curve_explorer.hpp"
#include "interact/live/curve_explorer_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "knots/knot_diagram.hpp"
#include "shape/knot_curves.hpp"

namespace s4d {
namespace {

// Gives the explorer the image of `k` through `f`.
void show(CurveExplorer& ex, const Curve<3>& k, const Frame<3>& f) {
  auto img = build_curve_image(k, f);
  ex.swap_image(*img);
}

// Walks the probe once round component 0 by aiming a little ahead along the image.
void walk_once_round(CurveExplorer& ex, const Curve<3>& curve, const Frame<3>& frame) {
  const auto& pts = curve.components[0].points;
  ASSERT_TRUE(ex.place(frame.shadow(pts[0])));
  for (std::size_t i = 1; i <= pts.size(); ++i) {
    const Vec2 ahead = frame.shadow(pts[i % pts.size()]);
    ex.move_to(ahead, static_cast<double>(i));
  }
}

TEST(CurveExplorer, OnceRoundTheTrefoilGivesItsGaussCode) {
  const Curve<3> k = torus_knot(2, 3, 240);
  const Frame<3> frame;
  CurveExplorer ex;
  show(ex, k, frame);
  ASSERT_EQ(ex.crossing_count(), 3);
  walk_once_round(ex, k, frame);
  EXPECT_EQ(ex.gauss_text(), diagram_from_curve(k, frame).gauss_code());
  int over = 0, under = 0;
  while (auto e = ex.pop_event()) (e->over ? over : under)++;
  EXPECT_EQ(over, 3);
  EXPECT_EQ(under, 3);
}

TEST(CurveExplorer, TheCinquefoilWalkedBackwardsGivesTheCodeReversed) {
  const Curve<3> k = torus_knot(2, 5, 300);
  const Frame<3> frame;
  CurveExplorer ex;
  show(ex, k, frame);
  const auto& pts = k.components[0].points;
  ASSERT_TRUE(ex.place(frame.shadow(pts[0])));
  for (std::size_t i = pts.size() - 1; i > 0; --i) ex.move_to(frame.shadow(pts[i]), 0);
  ex.move_to(frame.shadow(pts[0]), 0);
  const std::vector<int> back = ex.gauss_so_far();
  walk_once_round(ex, k, frame);
  const std::vector<int> fwd = ex.gauss_so_far();
  ASSERT_EQ(back.size(), 10u);
  ASSERT_EQ(fwd.size(), 10u);
  for (std::size_t i = 0; i < fwd.size(); ++i) EXPECT_EQ(back[i], fwd[fwd.size() - 1 - i]) << i;
}

// At every crossing, aim at a point of the other strand just past it: the probe stays on its own.
TEST(CurveExplorer, AtACrossingItStaysOnItsStrand) {
  const Curve<3> k = torus_knot(2, 3, 240);
  const Frame<3> frame;
  CurveExplorer ex;
  show(ex, k, frame);
  const auto& pts = k.components[0].points;
  const int n = static_cast<int>(pts.size());
  const auto seg_dist = [&](int a, int b) { return std::min(std::abs(a - b), n - std::abs(a - b)); };
  int tested = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 5; j < n; ++j) {
      // Segments i and j cross in the shadow: put the probe on i and aim along j.
      const Vec2 a = frame.shadow(pts[i]), b = frame.shadow(pts[(i + 1) % n]);
      const Vec2 c = frame.shadow(pts[j]), d = frame.shadow(pts[(j + 1) % n]);
      Eigen::Matrix2d m;
      m << b - a, c - d;
      if (std::abs(m.determinant()) < 1e-12) continue;
      const Vec2 st = m.inverse() * (c - a);
      if (st.x() < 0 || st.x() >= 1 || st.y() < 0 || st.y() >= 1) continue;  // half-open, as found
      ASSERT_TRUE(ex.place(a + st.x() * (b - a)));
      ASSERT_EQ(ex.probe().segment, i);
      const Vec2 along_other = frame.shadow(pts[(j + 3) % n]);
      ex.move_to(along_other, 0);
      EXPECT_LE(seg_dist(ex.probe().segment, i), 2) << "jumped from segment " << i << " to " << ex.probe().segment;
      ++tested;
    }
  EXPECT_EQ(tested, 3);
}

TEST(CurveExplorer, TheSpringPullsTheHandOntoTheStrandAndBadInputIsNoForce) {
  const Curve<3> k = torus_knot(2, 3, 240);
  const Frame<3> frame;
  CurveExplorer ex;
  show(ex, k, frame);
  const Vec2 on = frame.shadow(k.components[0].points[10]);
  ASSERT_TRUE(ex.place(on));
  const Vec2 hand = on + Vec2(0.05, 0.05);
  const Vec2 f = ex.update(hand, Vec2::Zero(), 1000, 0, DampedSpring{200, 1});
  EXPECT_GT(f.norm(), 0);
  EXPECT_GT((ex.probe_point() - hand).dot(f), 0) << "towards the probe";
  EXPECT_NEAR(f.norm(), 200 * (ex.probe_point() - hand).norm(), 1e-9);
  EXPECT_EQ(ex.update(Vec2(NAN, 0), Vec2::Zero(), 1000, 0, {}), Vec2::Zero());
  EXPECT_EQ(ex.update(hand, Vec2(INFINITY, 0), 1000, 0, {}), Vec2::Zero());
  EXPECT_EQ(ex.update(hand, Vec2::Zero(), 0, 0, {}), Vec2::Zero());
  EXPECT_FALSE(ex.place(Vec2(NAN, 1)));
  EXPECT_TRUE(std::isnan(ex.probe_point().x()));
}

TEST(CurveExplorer, ANewImageOfTheSameLayoutKeepsTheProbeAndAnotherLiftsIt) {
  const Curve<3> k = torus_knot(2, 3, 240);
  CurveExplorer ex;
  show(ex, k, Frame<3>());
  ASSERT_TRUE(ex.place(Vec2(1, 1)));
  const CurveProbe before = ex.probe();
  auto turned = build_curve_image(k, Frame<3>(Eigen::AngleAxisd(0.3, Vec3::UnitX()).toRotationMatrix()));
  ex.swap_image(*turned);
  EXPECT_EQ(ex.probe().segment, before.segment);
  auto other = build_curve_image(torus_knot(2, 3, 100), Frame<3>());
  ex.swap_image(*other);
  EXPECT_FALSE(ex.probe().valid());
  EXPECT_THROW(build_curve_image(Curve<3>{}, Frame<3>()), Error);
}

}  // namespace
}  // namespace s4d

namespace s4d {
namespace {

// The scene in device units: the hand a little off the strand is pulled onto it by the spring of K
// N/m; a hand that is not finite gets no force; a new image of a turned view is taken by the tick.
TEST(CurveExplorerScene, TheHandFeelsTheSpringInDeviceUnitsAndBadInputNoForce) {
  const Curve<3> k = torus_knot(2, 3, 240);
  const Frame<3> view;
  const DeviceMapping mapping = DeviceMapping::fit(Vec3::Zero(), 3.0, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.1));
  CurveExplorerScene scene(k, view, mapping);
  const Vec3 on = k.components[0].points[0];
  ASSERT_TRUE(scene.place(on));
  DeviceState d;
  d.position = mapping.to_device(on) + Vec3(0.002, 0, 0);  // 2 mm off, sideways in the image
  const ToolOutput out = scene.step(d, 1e-3);
  ASSERT_TRUE(out.engaged);
  ASSERT_TRUE(out.force.allFinite());
  const Vec3 to_probe = out.anchor - d.position;
  EXPECT_NEAR(out.force.norm(), 200 * Vec3(to_probe.x(), to_probe.y(), 0).norm(), 1e-6) << "K = 200 N/m";
  EXPECT_GT(out.force.dot(to_probe), 0);
  d.position = Vec3(NAN, 0, 0);
  EXPECT_EQ(scene.step(d, 1e-3).force, Vec3::Zero());
  scene.offer_image(build_curve_image(k, Frame<3>(Eigen::AngleAxisd(0.2, Vec3::UnitY()).toRotationMatrix())));
  d.position = mapping.to_device(on);
  scene.step(d, 1e-3);
  EXPECT_EQ(scene.stats().images_installed, 1u);
  EXPECT_TRUE(scene.navigation().explorer().probe().valid()) << "same layout: the probe keeps its place";
}

}  // namespace
}  // namespace s4d

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "audio/audio_measure.hpp"
#include "audio/cue_synth.hpp"
#include "audio/wav_file.hpp"
#include "haptics/haptic_loop.hpp"
#include "haptics/simulated_arm.hpp"

namespace s4d {
namespace {

double distance_to_image(const Curve<3>& k, const Vec2& q) {
  const auto& p = k.components[0].points;
  double best = HUGE_VAL;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 a = p[i].head<2>(), b = p[(i + 1) % p.size()].head<2>();
    const double t = std::clamp((q - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - q).norm());
  }
  return best;
}

struct PushedRun {
  std::vector<CurveCrossingEvent> events;
  double hand_off = 0, device_off = 0;  // m: the largest distance from the curve's image, at any tick
  bool left_component = false;
  double seconds = 0;
  std::string gauss;
};

// The simulated arm held by a hand model that traces the trefoil once round in 8 s, pushed off it
// sideways by up to `push` metres (five swings), through the real loop at 1 kHz, the navigation
// spring at `k` N/m.
PushedRun trace_pushed_off(double k, double push) {
  const Curve<3> knot = torus_knot(2, 3, 240);
  const Frame<3> view;
  auto arm = std::make_unique<SimulatedArm>();
  SimulatedArm& a = *arm;
  const DeviceCapabilities caps = arm->capabilities();
  double size = 0;
  for (const Vec3& p : knot.components[0].points) size = std::max(size, p.norm());
  const DeviceMapping mapping = DeviceMapping::fit(Vec3::Zero(), 1.1 * size, Mat<3>::Identity(), caps.workspace_centre(),
                                                   0.9 * 0.5 * (caps.workspace_max - caps.workspace_min));
  auto scene = std::make_unique<CurveExplorerScene>(knot, view, mapping);
  CurveExplorerScene& ex = *scene;
  ex.params()[CurveExplorerScene::kK].value = k;
  const auto& pts = knot.components[0].points;
  const double seconds = 8;
  auto hand = [&pts, mapping, seconds, push](double t) {
    const double s = std::clamp(t / seconds, 0.0, 1.0) * static_cast<double>(pts.size());
    const std::size_t i = static_cast<std::size_t>(s) % pts.size(), j = (i + 1) % pts.size();
    const Vec3 on = pts[i] + (s - std::floor(s)) * (pts[j] - pts[i]);
    const Vec2 tangent = (pts[j] - pts[(i + pts.size() - 1) % pts.size()]).head<2>().normalized();
    const double off = push / mapping.metres_per_unit * std::sin(2 * 3.141592653589793 * 5 * t / seconds);
    return mapping.to_device(Vec3(on.x() - off * tangent.y(), on.y() + off * tangent.x(), 0));
  };
  a.set_position(hand(0));
  a.set_hand_script(hand);
  EXPECT_TRUE(ex.place(Vec3(pts[0].x(), pts[0].y(), 0)));
  HapticLoopConfig cfg;
  cfg.realtime_priority = false;
  HapticLoop loop(std::move(arm), std::move(scene), cfg);
  PushedRun r;
  for (int tick = 0; tick < 1000 * seconds; ++tick) {
    loop.run_ticks(1);
    auto off = [&](const Vec3& device) { return distance_to_image(knot, mapping.to_shadow(device).head<2>()); };
    r.device_off = std::max(r.device_off, off(a.true_position()) * mapping.metres_per_unit);
    r.hand_off = std::max(r.hand_off, off(a.hand_target()) * mapping.metres_per_unit);
    while (auto e = ex.pop_event()) r.events.push_back(*e);
  }
  r.left_component = ex.stats().left_component;
  r.seconds = ex.stats().time;
  r.gauss = ex.navigation().explorer().gauss_text();
  return r;
}

// Navigation (4.3.1): however the hand pushes, the probe keeps to its strand through every crossing
// and the spring holds the stylus near the curve — a hand 4 mm off leaves it within 2 mm, where
// without the spring it would follow the hand all the way.
TEST(CurveExplorerScene, TheSpringHoldsAPushedHandNearTheCurveThroughEveryCrossing) {
  const Curve<3> knot = torus_knot(2, 3, 240);
  const PushedRun held = trace_pushed_off(600, 0.004);
  EXPECT_GT(held.hand_off, 0.0038) << "the hand model does push 4 mm off";
  EXPECT_LT(held.device_off, 0.5 * held.hand_off) << held.device_off;
  EXPECT_LT(held.device_off, 0.002);
  EXPECT_FALSE(held.left_component);
  EXPECT_EQ(held.gauss, diagram_from_curve(knot, Frame<3>()).gauss_code()) << "every crossing, in order";
  ASSERT_EQ(held.events.size(), 6u);
  const PushedRun free = trace_pushed_off(0, 0.004);
  EXPECT_GT(free.device_off, 0.85 * free.hand_off) << "without the spring the stylus goes where the hand goes";
  EXPECT_EQ(free.gauss, held.gauss) << "the probe keeps its strand either way";
}

// Sound (4.3.2): the exploration's cues written to a WAV and read back are heard in the order the
// crossings were passed — high pings over, low thuds under, as the knot's Gauss code has them.
TEST(CurveExplorerScene, TheExplorationsWavHoldsItsOverAndUnderCuesInOrder) {
  const Curve<3> knot = torus_knot(2, 3, 240);
  const PushedRun run = trace_pushed_off(600, 0.004);
  std::vector<CueEvent> cues;
  for (const auto& e : run.events)
    cues.push_back({e.time, e.over ? CueKind::crossing_over : CueKind::crossing_under, 1.0f});
  const auto path = std::filesystem::temp_directory_path() / "s4d_knot_explore_cues.wav";
  write_wav(path, render_cues(cues, {}, run.seconds), kAudioSampleRate);
  const WavData wav = read_wav(path);
  const std::vector<float> x = wav.samples();
  const int rate = wav.sample_rate;
  // The cues as the ear finds them: stretches of sound between silences, each called over or under
  // by where its energy is (the ping near 1.3 kHz, the thud near 200 Hz).
  std::vector<bool> heard_over;
  const std::size_t hop = static_cast<std::size_t>(rate / 200);  // 5 ms
  std::size_t quiet = 100;  // hops of silence before this one
  for (std::size_t i = 0; i + hop <= x.size(); i += hop) {
    double e = 0;
    for (std::size_t n = i; n < i + hop; ++n) e = std::max(e, double(std::abs(x[n])));
    if (e <= 1e-3) {
      ++quiet;
      continue;
    }
    if (quiet >= 4) {  // an onset after at least 20 ms of silence
      const std::span<const float> w(x.data() + i, std::min<std::size_t>(x.size() - i, rate / 20));
      heard_over.push_back(test::goertzel_power(w, 1318.5, rate) > test::goertzel_power(w, 196, rate));
    }
    quiet = 0;
  }
  std::vector<bool> expected;
  std::stringstream code(diagram_from_curve(knot, Frame<3>()).gauss_code());
  for (std::string item; std::getline(code, item, ',');) expected.push_back(std::stoi(item) > 0);
  ASSERT_EQ(expected.size(), 6u);
  EXPECT_EQ(heard_over, expected);
}

}  // namespace
}  // namespace s4d
