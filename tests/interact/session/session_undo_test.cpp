// Undo and redo on a headless Session: a drag, a pin, a created object and a physics change
// each come back as one step; the running simulation pauses at the restored state.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "interact/tools/grab_tool.hpp"
#include "interact/live/live_simulation.hpp"
#include "interact/tools/view_edit.hpp"
#include "knots/knot_identify.hpp"
#include "interact/session/session.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

Document cloth() {
  Document d;
  SceneObject o;
  o.name = "cloth";
  o.shape = generate("cloth", {{"n", 8}, {"size", 1}});
  d.scene.objects.push_back(o);
  d.scene.physics.stiffness = 200;
  return d;
}

std::vector<double> points(Session& s) {
  s.loop()->run_ticks(1);
  s.refresh();
  return s.snapshot()->points;
}

TEST(SessionUndo, ADragIsOneStepAndUndoPutsTheWorldBackPaused) {
  Session s;
  SessionOptions o;
  o.threaded = false;
  o.async_physics = false;
  s.open(cloth(), o);
  ASSERT_TRUE(s.simulating());
  s.set_mapping(DeviceMapping::fit(Vec3::Zero(), 1, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.1)));
  const std::vector<double> before = points(s);

  GrabTool tool;
  ToolInput in;
  in.view.eye = Vec3(0.07, 0.07, 5);
  in.view.ray = Vec3(0, 0, -1);
  ASSERT_TRUE(tool.press(in, s));
  for (int i = 1; i <= 50; ++i) {
    in.view.eye = Vec3(0.07, 0.07 + 0.006 * i, 5);
    tool.drag(in, s);
    s.loop()->run_ticks(10);
  }
  tool.release(in, s);
  const std::vector<double> dragged = points(s);
  EXPECT_NE(dragged, before);
  ASSERT_EQ(s.history().done_labels().size(), 1u) << "a 500-tick drag is one step";
  EXPECT_EQ(s.history().done_labels()[0].rfind("drag vertex", 0), 0u);

  ASSERT_TRUE(s.undo());
  s.loop()->run_ticks(5);
  s.refresh();
  EXPECT_FALSE(s.snapshot()->status.playing) << "paused at the restored state";
  const std::vector<double> undone = s.snapshot()->points;
  ASSERT_EQ(undone.size(), before.size());
  for (std::size_t i = 0; i < undone.size(); ++i) ASSERT_NEAR(undone[i], before[i], 1e-12) << i;
  ASSERT_TRUE(s.redo());
  const std::vector<double> redone = points(s);
  double moved = 0;
  for (std::size_t i = 0; i < redone.size(); ++i) moved = std::max(moved, std::abs(redone[i] - dragged[i]));
  EXPECT_LT(moved, 1e-9) << "redo puts the dragged state back";
  EXPECT_FALSE(s.redo());
}

TEST(SessionUndo, PinsObjectsAndSettingsComeBack) {
  Session s;
  SessionOptions o;
  o.threaded = false;
  o.async_physics = false;
  s.open(cloth(), o);
  points(s);
  s.record("pin vertex 3");
  s.send(live::Pin{3, live::PinAction::kPin});
  points(s);
  EXPECT_EQ(s.snapshot()->status.pinned, 1);
  ASSERT_TRUE(s.undo());
  points(s);
  EXPECT_EQ(s.snapshot()->status.pinned, 0);
  ASSERT_TRUE(s.redo());
  points(s);
  EXPECT_EQ(s.snapshot()->status.pinned, 1);

  // A created object: undo removes it and the simulation restarts without it.
  s.record("create sphere");
  SceneObject sphere;
  sphere.name = "sphere";
  Surface<4> sp = std::get<Surface<4>>(generate("sphere", {{"n", 6}, {"radius", 0.3}}));
  for (Vec4& p : sp.vertices) p.z() += 2;
  sphere.shape = sp;
  s.scene().objects.push_back(sphere);
  s.rebuild();
  const std::size_t with = points(s).size();
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(s.scene().objects.size(), 1u);
  EXPECT_LT(points(s).size(), with);
  EXPECT_EQ(s.snapshot()->status.pinned, 1) << "the pins of that state come back with it";

  // A physics change.
  s.record("change the physics");
  s.scene().physics.friction = 0;
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(s.scene().physics.friction, 0.3);
}

TEST(SessionUndo, TheViewComesBackThroughTheWindowsHooks) {
  Session s;
  SessionOptions o;
  o.threaded = false;
  s.open(cloth(), o);
  std::array<float, 6> angles{};
  s.capture_view = [&](DocumentState& d) { d.angles = angles; };
  s.restore_view = [&](const DocumentState& d) { angles = d.angles; };
  s.record("turn xw");
  angles[2] = 45;
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(angles[2], 0);
  ASSERT_TRUE(s.redo());
  EXPECT_EQ(angles[2], 45);
}


// As in the window: the loop and the physics on their own threads. Undo, redo and undo again as
// fast as keys go: until the simulation shows a handed-over state, the scene keeps it (refresh
// copies nothing over it), so each key acts on the state the one before made, and the last one
// lands whatever the threads' timing.
TEST(SessionUndo, QuickUndoRedoUndoOnRunningThreadsEndsWhereTheDragStarted) {
  Session s;
  SessionOptions o;
  o.realtime_priority = false;
  s.open(cloth(), o);
  ASSERT_TRUE(s.simulating());
  s.set_mapping(DeviceMapping::fit(Vec3::Zero(), 1, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.1)));
  const auto wait_for = [&](const auto& done) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    do {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      s.refresh();
    } while (!done() && std::chrono::steady_clock::now() < until);
    return done();
  };
  ASSERT_TRUE(wait_for([&] { return s.snapshot() && s.snapshot()->status.sim_steps > 20; }));
  s.send(live::Pause{});
  ASSERT_TRUE(wait_for([&] { return !s.snapshot()->status.playing; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  s.refresh();
  const std::vector<double> before = s.snapshot()->points;
  s.send(live::Play{});

  GrabTool tool;
  ToolInput in;
  in.view.eye = Vec3(0.07, 0.07, 5);
  in.view.ray = Vec3(0, 0, -1);
  ASSERT_TRUE(tool.press(in, s));
  for (int i = 1; i <= 30; ++i) {
    in.view.eye = Vec3(0.07, 0.07 + 0.01 * i, 5);
    tool.drag(in, s);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    s.refresh();
  }
  ASSERT_TRUE(wait_for([&] { return s.held(); }));
  tool.release(in, s);

  ASSERT_TRUE(s.undo());
  s.refresh();
  // Landed or not, the scene shows the undone shape (a stale snapshot is not copied over it).
  const auto scene_off = [&] {
    const auto& vs = std::get<Surface<4>>(s.scene().objects[0].shape).vertices;
    double off = 0;
    for (std::size_t i = 0; i < vs.size(); ++i)
      for (int k = 0; k < 4; ++k) off = std::max(off, std::abs(vs[i][k] - before[4 * i + static_cast<std::size_t>(k)]));
    return off;
  };
  EXPECT_LT(scene_off(), 0.02);
  ASSERT_TRUE(s.redo());
  s.refresh();
  ASSERT_TRUE(s.undo());
  ASSERT_TRUE(wait_for([&] { return !s.state_pending(); })) << "the state reached the simulation";
  EXPECT_FALSE(s.snapshot()->status.playing);
  EXPECT_LT(s.snapshot()->status.held_vertex, 0) << "the hand let go of the restored world";
  const std::vector<double> undone = s.snapshot()->points;
  ASSERT_EQ(undone.size(), before.size());
  double off = 0;
  for (std::size_t i = 0; i < undone.size(); ++i) off = std::max(off, std::abs(undone[i] - before[i]));
  EXPECT_LT(off, 0.02) << "back where the drag started";
  // The scene the window draws is the snapshot's again.
  s.refresh();
  EXPECT_EQ(s.save_state().simulation.positions, undone);
}

// [knots] A simulated knot is edited like clay: a drag is one step whose undo puts the knot back and
// leaves it editable (still playing); a crossing change reaches the World, which keeps it.
Document trefoil() {
  Document d;
  SceneObject o;
  o.name = "trefoil";
  o.shape = generate("torus-knot", {{"n", 160}});
  d.scene.objects.push_back(o);
  d.scene.physics.thickness = 0.2;
  return d;
}

// The session stepped by the test (no loop thread, the World in the tick).
void open_stepped(Session& s, Document d) {
  SessionOptions o;
  o.threaded = false;
  o.async_physics = false;
  s.open(std::move(d), o);
}

TEST(SessionUndo, AKnotsDragIsUndoneAndTheKnotStaysEditable) {
  Session s;
  open_stepped(s, trefoil());
  ASSERT_TRUE(s.simulating()) << s.physics_error();
  s.set_mapping(DeviceMapping::fit(Vec3::Zero(), 3, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.1)));
  const std::vector<double> before = points(s);
  const Vec3 p0(before[0], before[1], before[2]);
  s.record("drag vertex 0");
  s.send(live::Grab{0, live::GrabMode::kShadow, live::point(p0)});
  for (int i = 1; i <= 50; ++i) {
    s.set_hand(p0 + Vec3(0.02 * i, 0, 0), true);
    s.loop()->run_ticks(10);
  }
  s.send(live::Release{});
  s.set_hand(p0 + Vec3(1, 0, 0), false);
  const std::vector<double> dragged = points(s);
  EXPECT_GT(dragged[0] - before[0], 0.5) << "the point followed the hand";
  s.loop()->run_ticks(300);
  const std::vector<double> rested = points(s);
  EXPECT_NEAR(rested[0], dragged[0], 1e-3) << "released, it rests where it was left";

  ASSERT_TRUE(s.undo());
  s.loop()->run_ticks(5);
  s.refresh();
  EXPECT_TRUE(s.snapshot()->status.playing) << "a knot stays editable after an undo";
  const std::vector<double> undone = s.snapshot()->points;
  for (std::size_t i = 0; i < undone.size(); ++i) ASSERT_NEAR(undone[i], before[i], 1e-9) << i;
  s.loop()->run_ticks(300);
  EXPECT_NEAR(points(s)[0], before[0], 1e-6) << "and rests there: its springs took the restored shape";
}

TEST(SessionUndo, ACrossingChangeOfASimulatedKnotReachesTheWorld) {
  Session s;
  open_stepped(s, trefoil());
  ASSERT_TRUE(s.simulating()) << s.physics_error();
  points(s);
  ToolView view;
  view.camera.distance = 12;
  view.window = Vec2(400, 400);
  const ScreenCrossings c = screen_crossings(s.scene(), view.camera);
  ASSERT_EQ(c.crossings.size(), 3u);
  const Vec2 n = view.camera.ndc(c.crossings[0].over);
  view.cursor = Vec2((n.x() + 1) / 2 * 400, (1 - n.y()) / 2 * 400);
  std::string message;
  ASSERT_TRUE(change_crossing_under(view, s, message));
  EXPECT_EQ(message.rfind("changed a crossing", 0), 0u) << message;
  const Curve<3> edited = std::get<Curve<3>>(s.scene().objects[0].shape);
  EXPECT_EQ(identify_knot(edited).kind, KnotKind::kUnknot);
  s.refresh();  // the World has not taken the edit yet: the scene keeps showing it
  EXPECT_EQ(std::get<Curve<3>>(s.scene().objects[0].shape).components[0].points, edited.components[0].points);
  s.loop()->run_ticks(200);
  s.refresh();
  const Curve<3> now = std::get<Curve<3>>(s.scene().objects[0].shape);
  EXPECT_EQ(identify_knot(now).kind, KnotKind::kUnknot) << "the World runs the changed knot";
  double moved = 0;
  for (std::size_t i = 0; i < now.components[0].points.size(); ++i)
    moved = std::max(moved, (now.components[0].points[i] - edited.components[0].points[i]).norm());
  EXPECT_LT(moved, 1e-3) << "and rests in the edited shape";
  EXPECT_TRUE(s.snapshot()->status.playing);
}

}  // namespace
}  // namespace s4d
