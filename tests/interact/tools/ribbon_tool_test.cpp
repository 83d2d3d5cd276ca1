// The ribbon tool on a headless Session: a stroke through a sphere's shadow, shift held on the
// way out, becomes a ribbon passing above then below in w, added to the scene and simulated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "interact/live/live_simulation.hpp"
#include "interact/tools/ribbon_tool.hpp"
#include "interact/session/session.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

void sphere_session(Session& s) {
  Document d;
  SceneObject o;
  o.name = "sphere";
  o.generator = GeneratorCall{"sphere", {{"n", 12}, {"radius", 0.5}}};
  o.shape = generate("sphere", o.generator->params);
  d.scene.objects.push_back(o);
  SessionOptions opt;
  opt.threaded = false;
  opt.async_physics = false;
  s.open(std::move(d), opt);

}

TEST(RibbonTool, AStrokeThroughASphereIsThreadedAboveThenBelow) {
  Session s;
  sphere_session(s);
  ASSERT_TRUE(s.simulating()) << s.physics_error();
  RibbonTool tool;
  tool.options.width = 0.1;
  ToolInput in;
  in.view.eye = Vec3(-1, 0.2, 5);
  in.view.ray = Vec3(0, 0, -1);
  in.view.centre = Vec3::Zero();
  in.view.window = Vec2(800, 600);
  in.view.pixel_size = 0.005;
  ASSERT_TRUE(tool.press(in, s));
  for (int i = 1; i <= 100; ++i) {
    in.view.eye = Vec3(-1 + 0.02 * i, 0.2, 5);
    in.time = 0.01 * i;
    in.shift = in.view.eye.x() > 0;  // below on the way out
    tool.drag(in, s);
  }
  tool.release(in, s);
  ASSERT_NE(tool.last(), nullptr) << tool.take_message();
  const SketchedRibbon& r = *tool.last();
  ASSERT_EQ(r.passages.size(), 2u);
  EXPECT_FALSE(r.passages[0].below);
  EXPECT_TRUE(r.passages[1].below);
  EXPECT_LT(r.passages[0].place.x(), 0);
  EXPECT_GT(r.passages[1].place.x(), 0);
  ASSERT_EQ(s.scene().objects.size(), 2u);
  EXPECT_EQ(s.scene().objects[1].name, "ribbon");
  EXPECT_TRUE(s.simulating()) << "the simulation restarted with the ribbon: " << s.physics_error();
  EXPECT_GE(s.first_vertex(1), 0) << "the ribbon is a body";
  EXPECT_NE(tool.take_message().find("1 above and 1 below"), std::string::npos);
}

TEST(RibbonTool, AClickIsNoRibbonAndBadStrokesSayWhy) {
  Session s;
  sphere_session(s);
  RibbonTool tool;
  ToolInput in;
  in.view.ray = Vec3(0, 0, -1);
  tool.press(in, s);
  tool.release(in, s);
  EXPECT_EQ(tool.last(), nullptr);
  EXPECT_NE(tool.take_message().find("a click is not a stroke"), std::string::npos);
  EXPECT_EQ(s.scene().objects.size(), 1u);
}

// Draws `stroke` (points on the plane z = 0, seen from +z) with the tool as the mouse would.
void draw(RibbonTool& tool, Session& s, const std::vector<RibbonStrokeSample>& stroke) {
  ToolInput in;
  in.view.ray = Vec3(0, 0, -1);
  in.view.window = Vec2(800, 600);
  in.view.pixel_size = 0.005;
  for (std::size_t i = 0; i < stroke.size(); ++i) {
    in.view.eye = Vec3(stroke[i].at.x(), stroke[i].at.y(), 5);
    in.time = stroke[i].time;
    if (i == 0) tool.press(in, s);
    else tool.drag(in, s);
  }
  tool.release(in, s);
}

// The rough hand-drawn loop of tests/interact/data (corners, a hook, tremor) comes back to its
// start: a loop, smoothed where it folded, made and simulated; the status says what was done.
TEST(RibbonTool, ARoughLoopIsSmoothedIntoARibbon) {
  Session s;
  sphere_session(s);
  RibbonTool tool;
  tool.options.width = 0.1;
  draw(tool, s, read_ribbon_stroke(std::string(S4D_SOURCE_DIR) + "/tests/interact/data/rough_loop_stroke.txt", 1.0 / 120));
  ASSERT_NE(tool.last(), nullptr) << tool.take_message();
  EXPECT_TRUE(tool.last()->surface.grid->wrap_i);
  EXPECT_GT(tool.last()->smoothing.rounds, 0);
  EXPECT_TRUE(tool.kept_stroke().empty());
  const std::string m = tool.take_message();
  EXPECT_NE(m.find("(a loop"), std::string::npos) << m;
  EXPECT_NE(m.find("smoothed the stroke"), std::string::npos) << m;
  EXPECT_TRUE(tool.take_finished());
  EXPECT_EQ(s.scene().objects.size(), 2u);
  EXPECT_TRUE(s.simulating()) << s.physics_error();
}

// A hairpin too tight for a ribbon 0.3 wide is refused, and the stroke is kept with the reason
// and the place drawn; [ narrows the ribbon, Enter tries the same stroke again; Esc drops it.
TEST(RibbonTool, AStrokeThatMakesNoRibbonIsKeptForAnotherTry) {
  Session s;
  sphere_session(s);
  RibbonTool tool;
  tool.options.width = 0.3;
  std::vector<RibbonStrokeSample> hairpin;
  // Along y = 1 (above the sphere), a half turn of radius 0.05, and back, ending well short of its
  // start (not a loop).
  for (int i = 0; i <= 240; ++i) {
    const double t = i / 240.0, a = std::numbers::pi * std::clamp((t - 0.4) / 0.2, 0.0, 1.0);
    const double x = t < 0.4 ? -1 + 2.5 * t : t > 0.6 ? 0.6 - t : 0;
    hairpin.push_back({Vec3(x + 0.05 * std::sin(a), 1.05 - 0.05 * std::cos(a), 0), i / 120.0, false});
  }
  draw(tool, s, hairpin);
  EXPECT_EQ(tool.last(), nullptr);
  EXPECT_FALSE(tool.take_finished());
  EXPECT_EQ(s.scene().objects.size(), 1u);
  ASSERT_FALSE(tool.kept_stroke().empty());
  const std::string m = tool.take_message();
  EXPECT_NE(m.find("folds onto itself near"), std::string::npos) << m;
  EXPECT_NE(m.find("or make the ribbon at most"), std::string::npos) << m;
  EXPECT_NE(m.find("The stroke is kept"), std::string::npos) << m;
  EXPECT_NE(tool.help().find("Enter tries it again"), std::string::npos);
  EXPECT_EQ(m.find(tool.refusal()), std::string("no ribbon: ").size()) << "the reason, whole, for the panel";
  const double widest = tool.suggested_width();
  EXPECT_GT(widest, 0);
  EXPECT_LT(widest, 0.15);
  // Drawn: the kept stroke and a ring where it folds.
  Overlay o;
  tool.overlay(o, s);
  EXPECT_GE(o.lines.size(), hairpin.size() - 1);
  ASSERT_EQ(o.dots.size(), 1u);
  EXPECT_LT(std::abs(o.dots[0].at.x()), 0.3) << m;
  // Enter with the same width: refused again, still kept.
  ToolInput in;
  EXPECT_TRUE(tool.key(ToolKey::kEnter, in, s));
  EXPECT_EQ(tool.last(), nullptr);
  EXPECT_FALSE(tool.kept_stroke().empty());
  // [ three times: 0.3 x 0.8^3 = 0.154, still too wide; then the width it named: made.
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(tool.key(ToolKey::kSmaller, in, s));
  EXPECT_NEAR(tool.options.width, 0.1536, 1e-9);
  EXPECT_NE(tool.take_message().find("Enter tries the kept stroke"), std::string::npos);
  tool.options.width = widest;
  EXPECT_TRUE(tool.key(ToolKey::kEnter, in, s));
  ASSERT_NE(tool.last(), nullptr) << tool.take_message();
  EXPECT_TRUE(tool.kept_stroke().empty());
  EXPECT_TRUE(tool.take_finished());
  EXPECT_EQ(s.scene().objects.size(), 2u);
  // Another refused stroke, dropped with Esc; Esc again is the window's (back to Touch).
  tool.options.width = 0.3;
  draw(tool, s, hairpin);
  ASSERT_FALSE(tool.kept_stroke().empty());
  EXPECT_TRUE(tool.key(ToolKey::kEscape, in, s));
  EXPECT_TRUE(tool.kept_stroke().empty());
  EXPECT_TRUE(tool.refusal().empty());
  EXPECT_FALSE(tool.key(ToolKey::kEscape, in, s));
  EXPECT_FALSE(tool.key(ToolKey::kEnter, in, s));
  EXPECT_EQ(s.scene().objects.size(), 2u);
}


// [Fig. 8] Building a 4D chain by hand from scenes/chain-start.json: a closed ribbon sketched round
// through both spheres, above in w where it enters each and below where it leaves, links them;
// with gravity on, lifting the top sphere by one vertex on the band lifts the loop and the bottom
// sphere. Sketched above everywhere, nothing links and the bottom sphere falls away.
struct ChainLift {
  std::vector<bool> below;  // the passages' choices, in order
  double top_rise = 0, bottom_rise = 0;  // of the spheres' centroids while the hand lifts
};

Vec4 centroid_of(const Session& s, int object) {
  const HapticSnapshot& snap = *s.snapshot();
  Vec4 c = Vec4::Zero();
  const int first = s.first_vertex(object), n = s.vertex_count(object);
  for (int v = first; v < first + n; ++v)
    for (int k = 0; k < 4; ++k) c[k] += snap.points[static_cast<std::size_t>(v) * 4 + static_cast<std::size_t>(k)];
  return c / n;
}

ChainLift build_and_lift(bool below_on_the_way_out) {
  Session s;
  SessionOptions opt;
  opt.threaded = false;
  opt.async_physics = false;
  s.open(load_document(std::string(S4D_SOURCE_DIR) + "/scenes/chain-start.json"), opt);
  EXPECT_TRUE(s.simulating()) << s.physics_error();
  EXPECT_FALSE(s.scene().instruction.empty()) << "the scene says what to do";
  RibbonTool tool;
  tool.options.width = 0.15;
  tool.options.closed = true;
  ToolInput in;
  in.view.ray = Vec3(0, 0, -1);
  in.view.window = Vec2(800, 600);
  in.view.pixel_size = 0.005;
  // Round an ellipse through both spheres' shadows (centres (0, ±0.8), radius 0.5), anticlockwise
  // from its right side: up into the top sphere, out on its left, down into the bottom one and out.
  const int n = 240;
  for (int i = 0; i < n; ++i) {  // closed: the ribbon joins the last sample to the first
    const double t = 2 * std::numbers::pi * i / n;
    in.view.eye = Vec3(0.3 * std::cos(t), 0.8 * std::sin(t), 5);
    in.time = 0.01 * i;
    // Shift held past each sphere's middle: the top one is left on its left, the bottom one on its right.
    const double x = in.view.eye.x(), y = in.view.eye.y();
    in.shift = below_on_the_way_out && ((y > 0 && x < 0) || (y < 0 && x > 0));
    if (i == 0) tool.press(in, s);
    else tool.drag(in, s);
  }
  tool.release(in, s);
  ChainLift out;
  if (!tool.last()) {
    ADD_FAILURE() << tool.take_message();
    return out;
  }
  for (const RibbonPassage& p : tool.last()->passages) out.below.push_back(p.below);
  EXPECT_EQ(s.scene().objects.size(), 3u);

  // Gravity on, the top sphere's top vertex held on the band and lifted by 1.5 over 2 s.
  PhysicsSettings physics = s.scene().physics;
  physics.gravity = Vec4(0, -9.81, 0, 0);
  s.scene().physics = physics;
  s.send(live::SetPhysics::from(physics));
  // The mouse's hand reaches 4 units from the centre: the lift stays within it.
  s.set_mapping(DeviceMapping::fit(Vec3::Zero(), 4.0, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.1)));
  s.loop()->run_ticks(1);
  s.refresh();
  int grip = s.first_vertex(0);
  for (int v = s.first_vertex(0); v < s.first_vertex(0) + s.vertex_count(0); ++v)
    if (s.vertex_shadow(v).y() > s.vertex_shadow(grip).y()) grip = v;
  const Vec3 hand = s.vertex_shadow(grip);
  s.set_hand(hand, true);
  s.send(live::Grab{grip, live::GrabMode::kShadow, live::point(hand)});
  s.loop()->run_ticks(300);  // settling on the hand
  s.refresh();
  const Vec4 top0 = centroid_of(s, 0), bottom0 = centroid_of(s, 1);
  for (int k = 1; k <= 200; ++k) {
    const double u = k / 200.0;
    s.set_hand(hand + Vec3(0, 1.5 * u * u * (3 - 2 * u), 0), true);
    s.loop()->run_ticks(10);
  }
  s.loop()->run_ticks(500);
  s.refresh();
  EXPECT_EQ(s.snapshot()->status.held_vertex, grip);
  out.top_rise = centroid_of(s, 0).y() - top0.y();
  out.bottom_rise = centroid_of(s, 1).y() - bottom0.y();
  EXPECT_EQ(s.checks().true_intersections, 0);
  return out;
}

TEST(RibbonTool, ARibbonSketchedThroughTwoSpheresMakesAChainThatLiftsTogether) {
  const ChainLift linked = build_and_lift(true);
  EXPECT_EQ(linked.below, (std::vector<bool>{false, true, false, true})) << "above in, below out, at each sphere";
  EXPECT_GT(linked.top_rise, 1.0) << "the hand lifted the top sphere";
  EXPECT_GT(linked.bottom_rise, 0.8) << "the loop carried the bottom sphere up with it";
  const ChainLift apart = build_and_lift(false);
  EXPECT_EQ(apart.below, (std::vector<bool>{false, false, false, false}));
  EXPECT_GT(apart.top_rise, 1.0);
  EXPECT_LT(apart.bottom_rise, -0.5) << "nothing linked: the bottom sphere falls away";
}
}  // namespace
}  // namespace s4d
