// The Session around the live simulation: adding a body keeps the others' motion and pins, and
// Reset returns them to their start; an object that would meet another is refused; the rates
// the panel shows never go negative across a reset.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core/error.hpp"
#include "interact/session/session.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

// A cloth in the xy plane falling along -z (as `shadow4d cloth:n=8` opens it, with gravity).
Document falling_cloth() {
  Document d = load_document("cloth:n=8,size=1");
  d.scene.physics.stiffness = 200;
  d.scene.physics.gravity = Vec4(0, 0, -9.81, 0);
  return d;
}

SceneObject sphere_at(const Vec4& at, const std::string& name) {
  SceneObject s;
  s.name = name;
  s.placement.offset = at;
  s.shape = placed(generate("sphere", {{"n", 8}, {"radius", 0.3}}), s.placement);
  return s;
}

SessionOptions headless() {
  SessionOptions o;
  o.threaded = false;
  o.async_physics = false;
  return o;
}

const HapticSnapshot& ticks(Session& s, int n) {
  s.loop()->run_ticks(n);
  s.refresh();
  return *s.snapshot();
}

TEST(Session, AddingABodyKeepsTheOthersMotionAndPinsAndResetGoesToTheStart) {
  Session s;
  const Document doc = falling_cloth();
  const auto& start = std::get<Surface<4>>(doc.scene.objects[0].shape).vertices;
  s.open(doc, headless());
  s.send(live::Pin{7, live::PinAction::kPin});
  const HapticSnapshot& before = ticks(s, 300);
  const double vz = before.velocities[30 * 4 + 2];
  const double z = before.points[30 * 4 + 2];
  ASSERT_LT(vz, -0.1) << "the cloth falls";

  s.add_object(sphere_at(Vec4(3, 0, 0, 0), "sphere"), "create sphere");
  ASSERT_EQ(s.scene().objects.size(), 2u);
  ASSERT_EQ(s.history().done_labels().back(), "create sphere");
  const HapticSnapshot& after = ticks(s, 1);
  ASSERT_TRUE(s.simulating());
  EXPECT_TRUE(after.status.playing) << "it plays on as it did";
  EXPECT_EQ(after.status.pinned, 1);
  EXPECT_EQ(after.flags[7], 1) << "the pin is kept";
  EXPECT_NEAR(after.velocities[30 * 4 + 2], vz, 0.02) << "so is the velocity (one more step of gravity)";
  EXPECT_NEAR(after.points[30 * 4 + 2], z + 1e-3 * after.velocities[30 * 4 + 2], 1e-6) << "and the position";
  const int sphere0 = s.first_vertex(1);
  ASSERT_GT(sphere0, 0);
  EXPECT_NEAR(after.velocities[static_cast<std::size_t>(sphere0) * 4 + 1], 0, 1e-9) << "the new body starts at rest";

  ticks(s, 200);  // the sphere falls too
  s.send(live::Reset{});
  const HapticSnapshot& reset = ticks(s, 1);
  EXPECT_LE(reset.status.sim_steps, 1);
  EXPECT_NEAR(reset.points[30 * 4 + 2], start[30].z(), 1e-3) << "the cloth is back at its start, not where the sphere came";
  const Vec4 added = std::get<Surface<4>>(sphere_at(Vec4(3, 0, 0, 0), "s").shape).vertices[0];
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(reset.points[static_cast<std::size_t>(sphere0) * 4 + static_cast<std::size_t>(k)], added[k], 1e-3)
        << "the sphere where it was added";
  EXPECT_EQ(reset.status.pinned, 0) << "the start had no pin";
}

TEST(Session, AnObjectThatWouldMeetAnotherIsRefusedAndNothingChanges) {
  Session s;
  s.open(falling_cloth(), headless());
  ticks(s, 1);
  try {
    s.add_object(sphere_at(Vec4(0, 0, 0, 0), "sphere"), "create sphere");
    FAIL() << "a sphere through the cloth was added";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot add sphere"), std::string::npos) << e.what();
  }
  EXPECT_EQ(s.scene().objects.size(), 1u);
  EXPECT_TRUE(s.history().done_labels().empty());
  EXPECT_TRUE(s.simulating());
}

// The panel's steps/s and real-time ratio are measured over a second of wall time; a reset in the
// middle of a second must not make them negative, nor a body added (whose state keeps the clock)
// make the ratio jump.
TEST(Session, TheRatesStayTrueAcrossAResetAndAnAddedBody) {
  Session s;
  s.open(falling_cloth(), SessionOptions{});  // the window's way: the loop and the physics on threads
  std::this_thread::sleep_for(std::chrono::milliseconds(1200));
  s.refresh();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  s.refresh();
  EXPECT_GT(s.rates().steps_per_second, 100) << "a second measured";
  double lowest_steps = 1e9, lowest_ratio = 1e9, highest_ratio = 0;
  auto watch = [&](int ms) {
    for (int t = 0; t < ms; t += 50) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      s.refresh();
      lowest_steps = std::min(lowest_steps, s.rates().steps_per_second);
      lowest_ratio = std::min(lowest_ratio, s.rates().real_time_ratio);
      highest_ratio = std::max(highest_ratio, s.rates().real_time_ratio);
    }
  };
  s.send(live::Reset{});
  watch(1500);
  EXPECT_GT(s.rates().steps_per_second, 100) << "measured again after the reset";
  s.add_object(sphere_at(Vec4(3, 0, 0, 0), "sphere"), "create sphere");
  watch(1500);
  EXPECT_GE(lowest_steps, 0);
  EXPECT_GE(lowest_ratio, 0);
  EXPECT_LE(highest_ratio, 1.5) << "a clock carried over is no burst of simulated time";
  EXPECT_GT(s.snapshot()->status.sim_time, 1.0) << "the added body's state kept the clock";
}

// Knots are the bodies when a scene has no surface: deleting one (the Scene panel's "x") keeps
// the other's state, as for surfaces, instead of refusing a state without the curves' points.
TEST(Session, DeletingAKnotKeepsTheOtherKnotsState) {
  Session s;
  s.open(load_document("torus-knot:p=2,q=3,n=120"), headless());
  SceneObject second;
  second.name = "figure eight";
  second.placement.offset = Vec4(12, 0, 0, 0);
  second.shape = placed(generate("figure-eight", {}), second.placement);
  s.add_object(second, "create figure eight");
  ASSERT_EQ(s.dimension(), 3);
  ticks(s, 1);  // the added body's state lands
  s.send(live::Pin{s.first_vertex(1) + 3, live::PinAction::kPin});
  ASSERT_EQ(ticks(s, 50).status.pinned, 1);
  const std::vector<double> before = s.snapshot()->points;
  const int kept0 = s.first_vertex(1);
  s.record("delete the trefoil");
  s.scene().objects.erase(s.scene().objects.begin());
  s.objects_changed();
  const HapticSnapshot& after = ticks(s, 1);
  EXPECT_STREQ(after.status.message, "") << "no state was refused";
  ASSERT_EQ(s.first_vertex(0), 0);
  EXPECT_EQ(after.status.pinned, 1) << "the figure eight's pin is kept";
  EXPECT_EQ(after.flags[3], 1);
  EXPECT_NEAR(after.points[3 * 3], before[static_cast<std::size_t>(kept0 + 3) * 3], 1e-6) << "where it was";
}

// "knot:NAME" opens a table entry as the curve `knot make NAME` draws; a wrong name is an error.
TEST(LoadDocument, KnotColonOpensATableKnotOrLink) {
  const Document d = load_document("knot:L6a4");
  ASSERT_EQ(d.scene.objects.size(), 1u);
  EXPECT_EQ(d.scene.objects[0].name, "L6a4");
  const auto* curve = std::get_if<Curve<3>>(&d.scene.objects[0].shape);
  ASSERT_NE(curve, nullptr);
  EXPECT_EQ(curve->components.size(), 3u) << "the Borromean rings";
  EXPECT_THROW(load_document("knot:not-a-knot"), Error);
}

}  // namespace
}  // namespace s4d
