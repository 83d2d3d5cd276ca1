// The live simulation through the real haptic loop (run_ticks, so deterministic): a device's
// pull moves the held vertex and the body follows; along w moves w only; pins, pause, step,
// reset, live settings; the scenario's script played in the loop matches `shadow4d run`.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "haptics/haptic_loop.hpp"
#include "haptics/mouse_device.hpp"
#include "haptics/replay_device.hpp"
#include "interact/live/live_simulation.hpp"
#include "core/plane.hpp"
#include "shape/mesh_checks.hpp"
#include "scenario/scenario_run.hpp"
#include "shape/chain.hpp"
#include "shape/generators.hpp"
#include "shape/surfaces_4d.hpp"
#include "shape/knot_curves.hpp"
#include "interact/live/curve_explorer.hpp"
#include "knots/knot_diagram.hpp"
#include "io/scene.hpp"
#include "knots/knot_identify.hpp"
#include "physics/test_curves.hpp"
#include "knots/slice_naming.hpp"
#include "view/scene_slice.hpp"

namespace s4d {
namespace {

// A cloth square in the xy plane; gravity, when on, pulls it out of its plane (along -z).
Scene cloth_scene(int n, bool gravity) {
  Scene s;
  SceneObject o;
  o.name = "cloth";
  o.generator = GeneratorCall{"cloth", {{"n", n}, {"size", 1}}};
  o.shape = generate("cloth", o.generator->params);
  s.objects.push_back(o);
  s.physics.stiffness = 200;
  s.physics.gravity = gravity ? Vec4(0, 0, -9.81, 0) : Vec4::Zero();
  return s;
}

DeviceMapping unit_mapping() {
  return DeviceMapping::fit(Vec3::Zero(), 1.0, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.08));
}

// A device that stays at `from` for `rest` ticks, then with `buttons` held moves to `to` over
// `move` ticks and stays there.
Trajectory pull(const Vec3& from, const Vec3& to, std::uint32_t buttons, int rest, int move, int hold) {
  Trajectory t;
  t.header.device = "test hand";
  t.header.caps.max_force = 3.3;
  t.header.caps.max_continuous_force = 3.3;
  t.header.caps.max_stiffness = 1000;
  t.header.caps.max_force_rate = 1000;
  t.header.caps.outputs_force = true;
  const int n = rest + move + hold;
  for (int i = 0; i < n; ++i) {
    TickRecord r;
    r.tick = static_cast<std::uint64_t>(i);
    const double u = i < rest ? 0.0 : std::min(1.0, static_cast<double>(i - rest) / move);
    const Vec3 p = from + u * (to - from);
    const Vec3 v = i >= rest && i < rest + move ? Vec3((to - from) * 1000.0 / move) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      r.position[k] = p[k];
      r.velocity[k] = v[k];
      r.target[k] = p[k];
    }
    r.buttons = i < rest ? 0 : buttons;
    t.ticks.push_back(r);
  }
  return t;
}

std::vector<Vec4> positions(const HapticSnapshot& s) {
  std::vector<Vec4> x(s.points.size() / 4);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < 4; ++k) x[i][k] = s.points[4 * i + static_cast<std::size_t>(k)];
  return x;
}

// The test-only checker that shares no code with the engine (tests/shape/mesh_checks.hpp), on
// the cloth as it is now.
int true_intersections(const std::vector<Vec4>& x, const Scene& scene) {
  Surface<4> now = std::get<Surface<4>>(scene.objects[0].shape);
  now.vertices = x;
  return test::self_intersections<4>(now).intersecting_pairs;
}

struct Rig {
  Scene scene;
  std::unique_ptr<HapticLoop> loop;
  Rig(Scene s, std::unique_ptr<Device> device, LiveOptions o = {}) : scene(std::move(s)) {
    o.mapping = unit_mapping();
    loop = std::make_unique<HapticLoop>(std::move(device), make_live_simulation(scene, nullptr, o));
  }
  const HapticSnapshot& snap() { return loop->snapshot(); }
};

TEST(LiveSimulation, ADevicePullMovesTheHeldVertexAndTheBodyFollows) {
  const Scene scene = cloth_scene(12, false);
  const auto& start = std::get<Surface<4>>(scene.objects[0].shape).vertices;
  const int v = 5 * 12 + 6;  // near the middle
  const DeviceMapping m = unit_mapping();
  const Vec3 d0 = m.to_device(start[v].head<3>());
  const Vec3 d1 = d0 + Vec3(0, 0, 0.02);  // 0.25 scene units toward the eye: out of the cloth's plane
  Rig rig(scene, std::make_unique<ReplayDevice>(pull(d0, d1, 1, 50, 500, 1500), false));
  rig.loop->run_ticks(1200);
  EXPECT_EQ(rig.snap().status.held_vertex, v) << "the button took the vertex at the device's point";
  rig.loop->run_ticks(800);
  const std::vector<Vec4> x = positions(rig.snap());
  const double moved = x[v].z() - start[v].z();
  EXPECT_GT(moved, 0.7 * 0.25) << "the held vertex follows the hand";
  EXPECT_LT(moved, 1.05 * 0.25);
  const int neighbour = v + 1, corner = 0;
  EXPECT_GT(x[neighbour].z() - start[neighbour].z(), 0.3 * moved) << "its neighbours follow";
  EXPECT_LT(std::abs(x[corner].z() - start[corner].z()), moved) << "far away less";
  EXPECT_EQ(true_intersections(x, scene), 0);
  EXPECT_LE(rig.snap().max_force_output, 3.3 + 1e-12) << "the device's limit";
  EXPECT_GT(rig.snap().max_force_output, 0) << "the hand felt the band";
  EXPECT_EQ(rig.snap().safety.nonfinite, 0u);
}

TEST(LiveSimulation, AlongWTheVertexMovesInWAndKeepsItsShadow) {
  const Scene scene = cloth_scene(12, false);
  const auto& start = std::get<Surface<4>>(scene.objects[0].shape).vertices;
  const int v = 5 * 12 + 6;
  const DeviceMapping m = unit_mapping();
  const Vec3 d0 = m.to_device(start[v].head<3>());
  // Button 2 with the first: along the shadow ray; the device's y carries w.
  Rig rig(scene, std::make_unique<ReplayDevice>(pull(d0, d0 + Vec3(0, 0.02, 0), 3, 50, 500, 1500), false));
  rig.loop->run_ticks(2000);
  EXPECT_EQ(rig.snap().status.grab_mode, 1);
  const std::vector<Vec4> x = positions(rig.snap());
  EXPECT_GT(x[v].w() - start[v].w(), 0.7 * 0.25) << "w follows the hand's y";
  EXPECT_LT((x[v].head<3>() - start[v].head<3>()).norm(), 0.02) << "the shadow stays where it was";
  EXPECT_EQ(true_intersections(x, scene), 0);
}

TEST(LiveSimulation, PinsHoldAgainstGravityUntilCleared) {
  Rig rig(cloth_scene(8, true), std::make_unique<MouseDevice>());
  const auto& start = std::get<Surface<4>>(rig.scene.objects[0].shape).vertices;
  rig.loop->send(live::command(live::Pin{7, live::PinAction::kPin}));
  rig.loop->send(live::command(live::Pin{63, live::PinAction::kToggle}));
  rig.loop->run_ticks(300);
  std::vector<Vec4> x = positions(rig.snap());
  EXPECT_EQ(rig.snap().status.pinned, 2);
  EXPECT_EQ(rig.snap().flags[7], 1);
  EXPECT_EQ(rig.snap().flags[8], 0);
  EXPECT_EQ(x[7], start[7]);
  EXPECT_EQ(x[63], start[63]);
  EXPECT_LT(x[30].z(), start[30].z() - 0.05) << "the rest falls";
  rig.loop->send(live::command(live::Pin{63, live::PinAction::kToggle}));
  rig.loop->send(live::command(live::ClearPins{}));
  rig.loop->run_ticks(100);
  x = positions(rig.snap());
  EXPECT_EQ(rig.snap().status.pinned, 0);
  EXPECT_LT(x[7].z(), start[7].z()) << "let go, it falls";
}

TEST(LiveSimulation, PauseStepAndReset) {
  Rig rig(cloth_scene(6, true), std::make_unique<MouseDevice>());
  rig.loop->run_ticks(100);
  EXPECT_EQ(rig.snap().status.sim_steps, 100) << "one World step a 1 ms tick";
  rig.loop->send(live::command(live::Pause{}));
  rig.loop->run_ticks(50);
  EXPECT_EQ(rig.snap().status.sim_steps, 100);
  EXPECT_FALSE(rig.snap().status.playing);
  rig.loop->send(live::command(live::StepOnce{}));
  rig.loop->run_ticks(10);
  EXPECT_EQ(rig.snap().status.sim_steps, 101);
  rig.loop->send(live::command(live::SetTimeScale{0.5}));
  rig.loop->send(live::command(live::Play{}));
  rig.loop->run_ticks(100);
  EXPECT_EQ(rig.snap().status.sim_steps, 151) << "half speed: a step every other tick";
  rig.loop->send(live::command(live::Reset{}));
  rig.loop->run_ticks(1);
  EXPECT_LE(rig.snap().status.sim_steps, 1);
  EXPECT_EQ(positions(rig.snap())[20].x(), std::get<Surface<4>>(rig.scene.objects[0].shape).vertices[20].x());
}

TEST(LiveSimulation, SettingsApplyLiveAndBadOnesAreRefusedWithAReason) {
  Rig rig(cloth_scene(6, false), std::make_unique<MouseDevice>());
  rig.loop->run_ticks(50);
  const std::vector<Vec4> before = positions(rig.snap());
  EXPECT_LT((before[10] - std::get<Surface<4>>(rig.scene.objects[0].shape).vertices[10]).norm(), 1e-9)
      << "no gravity: at rest";
  PhysicsSettings p = rig.scene.physics;
  p.gravity = Vec4(0, 0, 0, -5);  // falling in w: the shadow does not show it
  rig.loop->send(live::command(live::SetPhysics::from(p)));
  rig.loop->run_ticks(200);
  const std::vector<Vec4> after = positions(rig.snap());
  EXPECT_LT(after[10].w(), before[10].w() - 0.02);
  EXPECT_EQ(rig.snap().status.settings_revision, 1u);
  p.thickness = std::numeric_limits<double>::quiet_NaN();
  rig.loop->send(live::command(live::SetPhysics::from(p)));
  p.thickness = 0.02;
  p.integrator = "paper-euler";
  p.stiffness = -3;
  rig.loop->send(live::command(live::SetPhysics::from(p)));
  rig.loop->run_ticks(1);
  EXPECT_EQ(rig.snap().status.settings_revision, 1u);
  EXPECT_NE(std::string(rig.snap().status.message).find("stiffness"), std::string::npos) << rig.snap().status.message;
}

TEST(LiveSimulation, TheScriptPlayedInTheLoopIsTheScenarioRun) {
  const Scenario sc = load_scenario(std::filesystem::path(S4D_SOURCE_DIR) / "scenarios" / "spun-trefoil-tighten.json");
  LiveOptions o;
  o.start_playing = false;
  HapticLoop loop(std::make_unique<MouseDevice>(), make_live_simulation(sc.scene, &sc, o));
  loop.run_ticks(20);
  EXPECT_EQ(loop.snapshot().status.sim_steps, 0) << "a scenario opens paused";
  loop.send(live::command(live::PlayScript{}));
  loop.run_ticks(300);
  EXPECT_TRUE(loop.snapshot().status.script_running);
  const auto run = ScenarioRun::make(sc);
  for (int i = 0; i < 300; ++i) run->step();
  const std::vector<Vec4> expected = run->positions(), got = positions(loop.snapshot());
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) ASSERT_EQ(got[i], expected[i]) << "vertex " << i;
  loop.send(live::command(live::StopScript{}));
  loop.run_ticks(1);
  EXPECT_FALSE(loop.snapshot().status.script_running);
}

TEST(LiveSimulation, OnItsOwnThreadThePhysicsFollowsTheHapticClock) {
  LiveOptions o;
  o.async_physics = true;
  Rig rig(cloth_scene(8, true), std::make_unique<MouseDevice>(), o);
  for (int i = 0; i < 300; ++i) {  // 0.3 s of haptic time, about as fast as the wall clock
    rig.loop->run_ticks(1);
    std::this_thread::sleep_for(std::chrono::microseconds(1000));
  }
  double t = 0;
  for (int i = 0; i < 200 && t < 0.2995; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    rig.loop->run_ticks(0);  // publishes the physics thread's newest state
    t = rig.snap().status.sim_time;
  }
  EXPECT_GT(t, 0.2995) << "it catches up with the clock";
  EXPECT_LT(t, 0.3 + 1e-9) << "and never runs ahead of it";
  EXPECT_LT(positions(rig.snap())[30].z(), std::get<Surface<4>>(rig.scene.objects[0].shape).vertices[30].z());
  // A clock that jumps 2 s ahead (a stalled physics) is owed at most 0.1 s: the rest is dropped
  // and the simulation goes on in slow motion instead of racing to catch up.
  rig.loop->run_ticks(2000);
  for (int i = 0; i < 100; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    rig.loop->run_ticks(0);
  }
  EXPECT_LT(rig.snap().status.sim_time, 1.0);
}

TEST(LiveSimulation, AnEmptySceneHasNothingToSimulateAKnotIsAChain) {
  EXPECT_THROW(make_live_simulation(Scene{}, nullptr, {}), Error);
  Scene s;
  SceneObject o;
  o.shape = generate("torus-knot", {{"n", 120}});
  s.objects.push_back(o);
  const auto live = make_live_simulation(s, nullptr, {});
  EXPECT_EQ(live->point_count(), 120) << "its points are the World's vertices";
  EXPECT_EQ(live->point_dimension(), 3);
}

// In R^3 the live simulation's explore walks the knot image the UI offered: a hand traced once
// round the trefoil passes each crossing twice, over then under, as its Gauss code says.
TEST(LiveSimulation, InR3ExploreWalksTheOfferedKnotImage) {
  Scene s;
  SceneObject o;
  o.name = "ribbon";
  o.shape = generate("trefoil-ribbon-3d", {});
  s.objects.push_back(o);
  LiveOptions lo;
  lo.mapping = unit_mapping();
  auto live = make_live_simulation(s, nullptr, lo);
  auto* handover = dynamic_cast<LiveHandover*>(live.get());
  ASSERT_NE(handover, nullptr);
  const Curve<3> knot = torus_knot(2, 3, 240);
  handover->offer_curve_image(build_curve_image(knot, Frame<3>()));
  const auto& pts = knot.components[0].points;
  live->command(live::command(live::StartExploring{live::point(pts[0])}));
  DeviceState d;
  double max_force = 0;
  for (std::size_t i = 0; i <= pts.size() * 8; ++i) {
    const double u = static_cast<double>(i) / 8.0;
    const std::size_t a = static_cast<std::size_t>(u) % pts.size(), b = (a + 1) % pts.size();
    const Vec3 hand = pts[a] + (u - std::floor(u)) * (pts[b] - pts[a]);
    d.position = lo.mapping.to_device(hand);
    const ToolOutput out = live->step(d, 1e-3);
    ASSERT_TRUE(out.force.allFinite());
    max_force = std::max(max_force, out.force.norm());
  }
  SceneStatus st;
  live->copy_status(st);
  EXPECT_TRUE(st.exploring);
  std::string code;
  for (std::uint64_t e = 0; e < st.event_count; ++e) {
    const SceneEvent& ev = st.events[e % SceneStatus::kRecentEvents];
    ASSERT_TRUE(ev.kind == kEventCrossedOver || ev.kind == kEventCrossedUnder);
    code += (code.empty() ? "" : ", ") + std::to_string(ev.kind == kEventCrossedOver ? ev.label : -ev.label);
  }
  EXPECT_EQ(code, diagram_from_curve(knot, Frame<3>()).gauss_code());
  EXPECT_GT(max_force, 0);
}

// [knots] A knot is a chain in World<3>, dragged through the same loop by a device's button: the
// view is the mapping's (identity here: the shadow is the xy plane, the depth z toward the eye).
Scene knot_scene(const Curve<3>& curve) {
  Scene s;
  SceneObject o;
  o.name = "knot";
  o.shape = curve;
  s.objects.push_back(o);
  s.physics.thickness = 0.1;
  s.physics.damping = 0.05;
  return s;
}

// The sum of the turning angles at its points: 2π for a round circle, more the more it winds.
double total_curvature(const Curve<3>& c) {
  const auto& p = c.components[0].points;
  const std::size_t n = p.size();
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = p[i] - p[(i + n - 1) % n], b = p[(i + 1) % n] - p[i];
    sum += std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0));
  }
  return sum;
}

Curve<3> knot_of(const HapticSnapshot& snap, const Curve<3>& like) {
  Curve<3> c = like;
  std::size_t i = 0;
  for (auto& comp : c.components)
    for (Vec3& p : comp.points) {
      for (int k = 0; k < 3; ++k) p[k] = snap.points[3 * i + static_cast<std::size_t>(k)];
      ++i;
    }
  return c;
}

// The smallest distance of the knot's segments more than ten apart along it, by trying every pair
// (a check that shares no code with the engine: each segment sampled at nine points).
double brute_force_gap(const Curve<3>& c) {
  const auto& p = c.components[0].points;
  const int n = static_cast<int>(p.size());
  double best = INFINITY;
  for (int i = 0; i < n; ++i)
    for (int j = i + 10; j < n; ++j) {
      if (j + 10 > n + i) continue;  // near along the chain: kept apart by the chain itself
      // Sampled densely: fine enough against a gap of the thickness (0.1), with no shared kernel.
      for (int a = 0; a <= 8; ++a)
        for (int b = 0; b <= 8; ++b) {
          const Vec3 x = p[i] + (a / 8.0) * (p[(i + 1) % n] - p[i]);
          const Vec3 y = p[j] + (b / 8.0) * (p[(j + 1) % n] - p[j]);
          best = std::min(best, (x - y).norm());
        }
    }
  return best;
}

// The under strand of the unknot's turned crossing, pushed by the hand straight up through the
// strand over it: it cannot pass, it pushes that strand ahead of it, and the knot is still the
// unknot (had it passed, the knot would be the trefoil).
TEST(LiveSimulation, AStrandDraggedStraightThroughAnotherIsStoppedAndTheNameStays) {
  const Curve<3> unknot = test::braid_closure({true, true, false}, 240);
  ASSERT_EQ(identify_knot(unknot).kind, KnotKind::kUnknot);
  const auto& pts = unknot.components[0].points;
  const int first = static_cast<int>(std::lround(2.5 / 3 * 120)), second = first + 120;
  const int under = pts[first].z() < pts[second].z() ? first : second;
  const DeviceMapping m = unit_mapping();
  const Vec3 d0 = m.to_device(pts[under]);
  Rig rig(knot_scene(unknot), std::make_unique<ReplayDevice>(pull(d0, d0 + Vec3(0, 0, 0.1), 1, 50, 1500, 1000), false));
  rig.loop->run_ticks(400);
  EXPECT_EQ(rig.snap().status.held_vertex, under) << "the button took the strand at the device's point";
  const int over = under == first ? second : first;
  double gap = INFINITY, beneath = INFINITY;
  for (int t = 0; t < 2100; t += 300) {
    rig.loop->run_ticks(300);
    gap = std::min(gap, brute_force_gap(knot_of(rig.snap(), unknot)));
    const auto& x = rig.snap().points;
    beneath = std::min(beneath, x[3 * over + 2] - x[3 * under + 2]);
  }
  EXPECT_GT(gap, 0.05) << "the strands never met";
  EXPECT_GT(beneath, 0) << "the pulled strand stayed beneath the other: it pushed it, never passed it";
  EXPECT_GT(rig.snap().points[3 * over + 2] - pts[over].z(), 0.3) << "the strand over it gave way instead";
  const KnotIdentification after = identify_knot(knot_of(rig.snap(), unknot));
  EXPECT_EQ(after.kind, KnotKind::kUnknot) << after.name;
  EXPECT_EQ(rig.snap().safety.nonfinite, 0u);
}

// Button 2 holds the shadow: the device's y moves the held point along the depth axis only.
TEST(LiveSimulation, AlongTheRayAKnotsPointChangesDepthOnly) {
  const Curve<3> trefoil = test::braid_closure({true, true, true}, 240);
  const auto& pts = trefoil.components[0].points;
  const int v = 20;  // between two crossings: nothing over or under it near
  const DeviceMapping m = unit_mapping();
  const Vec3 d0 = m.to_device(pts[v]);
  Rig rig(knot_scene(trefoil), std::make_unique<ReplayDevice>(pull(d0, d0 + Vec3(0, 0.02, 0), 3, 50, 500, 1500), false));
  rig.loop->run_ticks(2000);
  EXPECT_EQ(rig.snap().status.grab_mode, 1);
  EXPECT_EQ(rig.snap().status.held_vertex, v);
  const Vec3 now(rig.snap().points[3 * v], rig.snap().points[3 * v + 1], rig.snap().points[3 * v + 2]);
  EXPECT_GT(now.z() - pts[v].z(), 0.7 * 0.25) << "its depth follows the hand's y";
  EXPECT_LT((now.head<2>() - pts[v].head<2>()).norm(), 0.02) << "its shadow stays where it was";
  EXPECT_EQ(identify_knot(knot_of(rig.snap(), trefoil)).name, identify_knot(trefoil).name);
}

// Relax drives the knot by its energy in the same World: the messy unknot comes apart, crossing
// after crossing, without ever passing through itself; stopping leaves it resting as it is.
TEST(LiveSimulation, RelaxUntanglesTheUnknotLiveAndStops) {
  const Curve<3> unknot = test::braid_closure({true, false, true, true, false, true, false}, 280);
  ASSERT_EQ(identify_knot(unknot).kind, KnotKind::kUnknot);
  const int before = diagram_from_curve(unknot, Frame<3>()).crossing_count();
  ASSERT_EQ(before, 7);
  Rig rig(knot_scene(unknot), std::make_unique<MouseDevice>());
  rig.loop->send(live::command(live::StartRelaxing{}));
  rig.loop->run_ticks(10);
  EXPECT_TRUE(rig.snap().status.relaxing) << rig.snap().status.message;
  double gap = INFINITY;
  for (int t = 0; t < 16; ++t) {
    rig.loop->run_ticks(500);
    gap = std::min(gap, brute_force_gap(knot_of(rig.snap(), unknot)));
  }
  const Curve<3> relaxed = knot_of(rig.snap(), unknot);
  EXPECT_GT(gap, 0.1) << "strands far apart along the knot never came near";
  EXPECT_LT(diagram_from_curve(relaxed, Frame<3>()).crossing_count(), before);
  EXPECT_LT(total_curvature(relaxed), 0.6 * total_curvature(unknot)) << "smoother: it winds less";
  EXPECT_EQ(identify_knot(relaxed).kind, KnotKind::kUnknot);
  rig.loop->send(live::command(live::StopRelaxing{}));
  rig.loop->run_ticks(10);
  EXPECT_FALSE(rig.snap().status.relaxing);
  const std::vector<double> stopped = rig.snap().points;
  rig.loop->run_ticks(300);
  double moved = 0;
  for (std::size_t i = 0; i < stopped.size(); ++i) moved = std::max(moved, std::abs(rig.snap().points[i] - stopped[i]));
  EXPECT_LT(moved, 1e-3) << "stopped, it rests";
}

// The Fig. 15 exercise done by hand through the live simulation, as a device (or the mouse's
// proxy) does it: grab, drag, let go. The tangle's lens between two crossings where one strand is
// over at both is removed by dragging that strand's middle across the other (a Reidemeister II
// move): 8 crossings, then 6, 4, 2 and none; the knot reads 'unknot' after every drag, never
// passing through itself.
struct Hand {
  explicit Hand(std::unique_ptr<HapticScene> scene) : live(std::move(scene)) {}
  std::unique_ptr<HapticScene> live;
  DeviceMapping mapping = unit_mapping();
  DeviceState device;
  std::vector<double> points() const {
    std::vector<double> x(static_cast<std::size_t>(live->point_count()) * 3);
    live->copy_points(x);
    return x;
  }
  Vec3 at(int v) const {
    const auto x = points();
    return Vec3(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
  }
  void ticks(int n) {
    for (int i = 0; i < n; ++i) live->step(device, 1e-3);
  }
  // Takes point v with the button and moves it to `to` (shadow) over `move` ticks, then lets go.
  void drag(int v, const Vec3& to, int move = 1500) {
    const Vec3 from = mapping.to_device(at(v)), end = mapping.to_device(to);
    device.position = from;
    device.buttons = 0;
    ticks(20);
    device.buttons = 1;
    ticks(20);
    for (int i = 1; i <= move; ++i) {
      device.position = from + (static_cast<double>(i) / move) * (end - from);
      ticks(1);
    }
    ticks(600);
    device.buttons = 0;
    ticks(300);
  }
};

Curve<3> curve_of(const std::vector<double>& x, const Curve<3>& like) {
  Curve<3> c = like;
  std::size_t i = 0;
  for (auto& comp : c.components)
    for (Vec3& p : comp.points) {
      p = Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
      ++i;
    }
  return c;
}

TEST(LiveSimulation, TheFig15TangleComesApartByHand) {
  const Scene scene = load_scene(std::string(S4D_SOURCE_DIR) + "/scenes/fig15-tangled-unknot.json");
  const Curve<3>& start = std::get<Curve<3>>(scene.objects[0].shape);
  const int q = 8;
  ASSERT_EQ(diagram_from_curve(start, Frame<3>()).crossing_count(), q);
  LiveOptions lo;
  lo.mapping = unit_mapping();
  Hand hand(make_live_simulation(scene, nullptr, lo));
  // The point of the knot nearest p in the picture.
  const auto nearest = [&](const Vec2& p) {
    const std::vector<double> x = hand.points();
    int best = 0;
    for (int i = 1; i < static_cast<int>(x.size()) / 3; ++i)
      if ((Vec2(x[3 * i], x[3 * i + 1]) - p).norm() < (Vec2(x[3 * best], x[3 * best + 1]) - p).norm()) best = i;
    return best;
  };
  std::vector<int> counts{q};
  // Its band (tools/fig15_tangled_unknot.py) winds 300° round a circle of radius 2, its strands 0.6
  // either side of it where they are farthest apart: there, between crossings 2k and 2k + 1, lies
  // each pair's lens.
  for (const int k : {0, 2, 4, 6}) {
    const double phi = 300.0 / 180 * std::numbers::pi * (k + 1.0) / q;
    const Vec2 dir(std::cos(phi), std::sin(phi));
    const int a = nearest(2.6 * dir), b = nearest(1.4 * dir);
    const int over = hand.at(a).z() > hand.at(b).z() ? a : b, under = over == a ? b : a;
    // Across the other strand in the picture, radially, 0.8 beyond it.
    const Vec3 o = hand.at(over), u = hand.at(under);
    const double to = u.head<2>().norm() + (u.head<2>().norm() > o.head<2>().norm() ? 0.8 : -0.8);
    hand.drag(over, Vec3(dir.x() * to, dir.y() * to, o.z()));
    const Curve<3> now = curve_of(hand.points(), start);
    counts.push_back(diagram_from_curve(now, Frame<3>()).crossing_count());
    EXPECT_EQ(identify_knot(now).kind, KnotKind::kUnknot) << "after the drag at crossings " << k << "-" << k + 1;
    EXPECT_GT(brute_force_gap(now), 0.05);
  }
  EXPECT_EQ(counts, (std::vector<int>{8, 6, 4, 2, 0})) << "each drag took a lens away; none is left";
}

TEST(LiveSimulation, RelaxIsRefusedForSurfacesWithAReason) {
  Rig rig(cloth_scene(6, false), std::make_unique<MouseDevice>());
  rig.loop->send(live::command(live::StartRelaxing{}));
  rig.loop->run_ticks(5);
  EXPECT_FALSE(rig.snap().status.relaxing);
  EXPECT_NE(std::string(rig.snap().status.message).find("relax works on knots"), std::string::npos);
}


// [By hand] A scenario opened in the window runs, when played with Space, with the set-up its
// instruction assumes (scenario.hpp ByHand) and the user's hand in place of the scripted one.
Scenario shipped(const std::string& name) {
  return load_scenario(std::filesystem::path(S4D_SOURCE_DIR) / "scenarios" / (name + ".json"));
}

// The scenario's live simulation, opened paused as the window opens it, with a mapping that lays
// a ball of `radius` about the origin onto the test hand's ±8 cm.
struct ScenarioRig {
  Scenario sc;
  DeviceMapping mapping;
  std::unique_ptr<HapticLoop> loop;
  ScenarioRig(const std::string& name, std::unique_ptr<Device> device, double radius) : sc(shipped(name)) {
    mapping = DeviceMapping::fit(Vec3::Zero(), radius, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.08));
    LiveOptions o;
    o.start_playing = false;
    o.mapping = mapping;
    o.frame = sc.scene.frame;
    loop = std::make_unique<HapticLoop>(std::move(device), make_live_simulation(sc.scene, &sc, o));
  }
  const HapticSnapshot& snap() { return loop->snapshot(); }
  Vec3 shadow(const Vec4& p) const { return sc.scene.frame.shadow(p); }
};

// The mean of vertices [first, first + n) at x.
Vec4 centroid(const std::vector<Vec4>& x, int first, int n) {
  Vec4 c = Vec4::Zero();
  for (int i = first; i < first + n; ++i) c += x[static_cast<std::size_t>(i)];
  return c / n;
}

TEST(ByHand, TheClothSlidesOffTheRibbonThatStaysHeld) {
  ScenarioRig rig("cloth-slides-off-ribbon", std::make_unique<MouseDevice>(), 1.0);
  rig.loop->run_ticks(20);
  EXPECT_EQ(rig.snap().status.sim_steps, 0) << "opens paused";
  EXPECT_EQ(rig.snap().status.pinned, 16) << "the ribbon is held from the start (its 16 vertices)";
  const std::vector<Vec4> x0 = positions(rig.snap());
  rig.loop->send(live::command(live::Play{}));  // Space
  rig.loop->run_ticks(2500);
  const std::vector<Vec4> x = positions(rig.snap());
  double ribbon_moved = 0, cloth_top = -1e9;
  for (int v = 0; v < 16; ++v) ribbon_moved = std::max(ribbon_moved, (x[v] - x0[v]).norm());
  for (std::size_t v = 16; v < x.size(); ++v) cloth_top = std::max(cloth_top, x[v].y());
  EXPECT_EQ(ribbon_moved, 0) << "the ribbon stays where it is held";
  EXPECT_LT(cloth_top, -0.1) << "the whole cloth slid off and fell below the ribbon (y = 0)";
  EXPECT_EQ(true_intersections(x, rig.sc.scene), 0);
}

// Lifting by one vertex on the rubber band with its default settings, as a person does the
// scenario: played (Space), the set-up's hold carries the body until the device's button takes
// its top vertex (the hold then lets go) and lifts it by `lift` over 2.5 s.
struct HandLift {
  int top = -1, held = -1, pinned_at_start = 0, pinned_held = 0;
  double top_rise = 0, carried_rise = 0;  // of the held vertex, of the carried part's centroid
  double most_force = 0, felt = 0;        // N: the band on the vertex, the device's output
  std::uint64_t nonfinite = 0;
  int true_intersections = -1;
};

HandLift lift_by_hand(const std::string& name, double lift, int carried_first, int carried_count) {
  const Scenario sc = shipped(name);
  const Surface<4>& body = std::get<Surface<4>>(sc.scene.objects[0].shape);
  HandLift out;
  out.top = 0;
  for (int v = 0; v < static_cast<int>(body.vertices.size()); ++v)
    if (body.vertices[v].y() > body.vertices[out.top].y()) out.top = v;
  const DeviceMapping m = DeviceMapping::fit(Vec3::Zero(), 4.0, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.08));
  const Vec3 d0 = m.to_device(sc.scene.frame.shadow(body.vertices[out.top]));
  // At rest for 1 s (the body settles on its hold), the button grabs and lifts, holds 1.5 s.
  ScenarioRig rig(name, std::make_unique<ReplayDevice>(pull(d0, d0 + Vec3(0, lift * m.metres_per_unit, 0), 1, 1000, 2500, 1500), false), 4.0);
  rig.loop->run_ticks(5);
  EXPECT_EQ(rig.snap().status.sim_steps, 0) << "opens paused";
  out.pinned_at_start = rig.snap().status.pinned;
  rig.loop->send(live::command(live::Play{}));
  rig.loop->run_ticks(995);
  const std::vector<Vec4> settled = positions(rig.snap());
  rig.loop->run_ticks(20);
  out.held = rig.snap().status.held_vertex;
  out.pinned_held = rig.snap().status.pinned;
  for (int k = 0; k < 40; ++k) {
    rig.loop->run_ticks(100);
    out.most_force = std::max(out.most_force, rig.snap().status.band_force);
  }
  const std::vector<Vec4> x = positions(rig.snap());
  out.top_rise = x[out.top].y() - settled[out.top].y();
  out.carried_rise = centroid(x, carried_first, carried_count).y() - centroid(settled, carried_first, carried_count).y();
  out.felt = rig.snap().max_force_output;
  out.nonfinite = rig.snap().safety.nonfinite;
  out.true_intersections = true_intersections(x, rig.sc.scene);
  return out;
}

void expect_lifted(const HandLift& r, int hold, double lift, double min_carried_rise) {
  EXPECT_EQ(r.pinned_at_start, hold) << "the hold is in force while paused, as pins";
  EXPECT_EQ(r.held, r.top) << "the button took the top vertex";
  EXPECT_EQ(r.pinned_held, 0) << "the hold let go: the hand holds it now";
  EXPECT_GT(r.top_rise, 0.9 * lift) << "the held vertex followed the hand";
  EXPECT_GT(r.carried_rise, min_carried_rise) << "what hangs on rose with it: linked in R^4";
  EXPECT_LE(r.most_force, 5.0 + 1e-9) << "never more than the band's default limit";
  EXPECT_LE(r.felt, 3.3 + 1e-9) << "what the hand felt passed the device's limit";
  EXPECT_EQ(r.nonfinite, 0u);
  EXPECT_EQ(r.true_intersections, 0);
}

// Fig. 8: the chain (sphere, loop, sphere; the bottom sphere is the last 114 vertices), 2.9 N.
TEST(ByHand, OneVertexOnTheDefaultBandLiftsTheChain) {
  const int ns = static_cast<int>(uv_sphere<4>(16, kChainSphereRadius, Vec4::Zero()).vertices.size());
  const int nv = static_cast<int>(std::get<Surface<4>>(shipped("chain-4d").scene.objects[0].shape).vertices.size());
  const HandLift r = lift_by_hand("chain-4d", 3.0, nv - ns, ns);
  expect_lifted(r, 17, 3.0, 1.0);
  EXPECT_GT(r.most_force, 2.5) << "the band carried the chain's weight";
}

// Fig. 14: the loop held at its top, the sphere (its first 114 vertices, mirrored below) hanging.
TEST(ByHand, OneVertexOnTheDefaultBandLiftsTheSphereByItsLoop) {
  const int ns = static_cast<int>(uv_sphere<4>(16, kChainSphereRadius, Vec4::Zero()).vertices.size());
  const HandLift r = lift_by_hand("ribbon-lifts-sphere", 2.0, 0, ns);
  expect_lifted(r, 8, 2.0, 0.8);
  EXPECT_GT(r.most_force, 1.5) << "the band carried the loop and the sphere (about 1.75 N)";
}

// Tightening by hand: one pole is held by the set-up, the user pulls the other on the band.
TEST(ByHand, OnePoleHeldTheOtherPulledTheSpunTrefoilStretches) {
  const Scenario sc = shipped("spun-trefoil-tighten");
  const Surface<4>& sphere = std::get<Surface<4>>(sc.scene.objects[0].shape);
  const int last = static_cast<int>(sphere.vertices.size()) - 1;
  const DeviceMapping m = DeviceMapping::fit(Vec3::Zero(), 3.0, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.08));
  const Vec3 d0 = m.to_device(sc.scene.frame.shadow(sphere.vertices[0]));
  const Vec3 away = (sc.scene.frame.shadow(sphere.vertices[0]) - sc.scene.frame.shadow(sphere.vertices[last])).normalized();
  ScenarioRig rig("spun-trefoil-tighten", std::make_unique<ReplayDevice>(pull(d0, d0 + 1.5 * m.metres_per_unit * away, 1, 100, 1500, 500), false), 3.0);
  rig.loop->send(live::command(live::Play{}));
  rig.loop->run_ticks(2100);
  EXPECT_EQ(rig.snap().status.held_vertex, 0);
  EXPECT_EQ(rig.snap().flags[static_cast<std::size_t>(last)], 1) << "the other pole is held (by hand only)";
  const std::vector<Vec4> x = positions(rig.snap());
  EXPECT_EQ(x[last], sphere.vertices[last]);
  EXPECT_GT((x[0] - sphere.vertices[0]).norm(), 1.0) << "the pulled pole went with the hand";
  EXPECT_EQ(true_intersections(x, rig.sc.scene), 0);
  // Play script is the scenario's run: the by-hand-only hold is not part of it.
  rig.loop->send(live::command(live::PlayScript{}));
  rig.loop->run_ticks(2);
  EXPECT_EQ(rig.snap().status.pinned, 0) << "the script pulls both poles, holding neither";
}

// Slices while pulling: the spun trefoil seen in the frame of its spinning plane (level w = 0 is
// that plane: the square knot), one pole held, the other pulled by hand in the shadow. The level
// stays regular (the hand moves no vertex in w, and w's critical levels are far from 0), and no
// pass-through can change a slice's knot type, so the name stays through the whole pull.
TEST(ByHand, TheSpunTrefoilsSliceKeepsItsNameWhilePulled) {
  Scenario sc = shipped("spun-trefoil-tighten");
  sc.scene.frame = Frame<4>{};
  const Surface<4>& sphere = std::get<Surface<4>>(sc.scene.objects[0].shape);
  const int last = static_cast<int>(sphere.vertices.size()) - 1;
  const DeviceMapping m = DeviceMapping::fit(Vec3::Zero(), 3.0, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.08));
  const Vec3 d0 = m.to_device(sphere.vertices[0].head<3>());
  const Vec3 away = (sphere.vertices[0] - sphere.vertices[last]).head<3>().normalized();
  LiveOptions o;
  o.start_playing = false;
  o.mapping = m;
  HapticLoop loop(std::make_unique<ReplayDevice>(pull(d0, d0 + 1.2 * m.metres_per_unit * away, 1, 100, 1500, 400), false),
                  make_live_simulation(sc.scene, &sc, o));
  loop.send(live::command(live::Play{}));
  const auto slice_now = [&] {
    Scene now = sc.scene;
    std::get<Surface<4>>(now.objects[0].shape).vertices = positions(loop.snapshot());
    return name_slice(scene_slice(now, 0.0).curve, 0.0);
  };
  const SliceNaming at_rest = slice_now();
  ASSERT_EQ(at_rest.name, "3_1 # 3_1 mirror") << at_rest.headline();
  double pulled = 0;
  for (int k = 0; k < 5; ++k) {
    loop.run_ticks(400);
    const SliceNaming n = slice_now();
    EXPECT_EQ(n.name, at_rest.name) << "after " << 400 * (k + 1) << " ticks: " << n.headline();
    EXPECT_EQ(n.components, 1);
    const int held = loop.snapshot().status.held_vertex;  // at the pole (its shadow meets the first ring's)
    ASSERT_GE(held, 0);
    pulled = (positions(loop.snapshot())[static_cast<std::size_t>(held)] - sphere.vertices[static_cast<std::size_t>(held)]).norm();
  }
  EXPECT_GT(pulled, 0.8) << "the pole went with the hand";
  EXPECT_EQ(true_intersections(positions(loop.snapshot()), sc.scene), 0);
}

// Stopping the script hands the scenario over: the set-up goes on holding where things are.
TEST(ByHand, StoppingTheScriptKeepsTheSetUp) {
  ScenarioRig rig("cloth-slides-off-ribbon", std::make_unique<MouseDevice>(), 1.0);
  rig.loop->send(live::command(live::PlayScript{}));
  rig.loop->run_ticks(300);
  rig.loop->send(live::command(live::StopScript{}));
  rig.loop->run_ticks(300);
  EXPECT_FALSE(rig.snap().status.script_running);
  EXPECT_EQ(rig.snap().status.pinned, 16) << "the ribbon is still held";
  rig.loop->send(live::command(live::Reset{}));
  rig.loop->run_ticks(1);
  EXPECT_EQ(rig.snap().status.pinned, 16) << "and again after a reset";
}

// What a device's button does is the active tool's choice: grab (Touch), explore (Explore), or
// nothing in the simulation (a sketch draws with it itself).
TEST(LiveSimulation, TheDeviceButtonDoesWhatTheToolDoes) {
  Scene scene;
  SceneObject o;
  o.name = "torus";
  o.shape = generate("clifford-torus", {{"n", 24}, {"m", 24}});
  scene.objects.push_back(o);
  scene.frame.rotate(Plane{2, 3}, 0.5);
  const Vec3 at = scene.frame.shadow(std::get<Surface<4>>(o.shape).vertices[30]);
  const Vec3 d0 = unit_mapping().to_device(at);
  auto run = [&](DeviceButton b, bool switch_live) {
    LiveOptions lo;
    lo.mapping = unit_mapping();
    lo.frame = scene.frame;
    lo.button = switch_live ? DeviceButton::kGrab : b;
    Trajectory t = pull(d0, d0 + Vec3(0.005, 0, 0), 1, 50, 150, 300);
    for (std::size_t i = 250; i < t.ticks.size(); ++i) t.ticks[i].buttons = 0;  // let go after 250 ticks
    auto loop = std::make_unique<HapticLoop>(std::make_unique<ReplayDevice>(std::move(t), false),
                                             make_live_simulation(scene, nullptr, lo));
    if (switch_live) loop->send(live::command(live::SetDeviceButton{b, 0}));
    loop->run_ticks(200);
    const SceneStatus during = loop->snapshot().status;
    loop->run_ticks(200);  // the recording ends: the button is up
    return std::make_pair(during, loop->snapshot().status);
  };
  const auto [grab, grab_after] = run(DeviceButton::kGrab, false);
  EXPECT_GE(grab.held_vertex, 0);
  EXPECT_FALSE(grab.exploring);
  EXPECT_EQ(grab_after.held_vertex, -1) << "released with the button";
  for (bool live : {false, true}) {
    const auto [explore, explore_after] = run(DeviceButton::kExplore, live);
    EXPECT_TRUE(explore.exploring) << "the button put the probe out";
    EXPECT_EQ(explore.held_vertex, -1);
    EXPECT_LT((Vec3(explore.probe) - at).norm(), 0.3) << "where the device is";
    EXPECT_FALSE(explore_after.exploring) << "and takes it in with the button";
  }
  const auto [none, none_after] = run(DeviceButton::kNone, true);
  EXPECT_EQ(none.held_vertex, -1);
  EXPECT_FALSE(none.exploring);
}

// Fig. 12's local deformations: with carry rings the device's button carries the patch around
// the vertex kinematically (its centre exactly with the hand, the rest by its weight), and the
// patch stays held where the button lets go; the band's one vertex (0 rings) springs back.
TEST(LiveSimulation, ACarriedPatchFollowsTheHandAndStaysWhereItIsLetGo) {
  const Scene scene = cloth_scene(12, false);
  const auto& start = std::get<Surface<4>>(scene.objects[0].shape).vertices;
  const int v = 5 * 12 + 6, neighbour = v + 1, far = 0;
  const int rings = 2;
  const DeviceMapping m = unit_mapping();
  const Vec3 d0 = m.to_device(start[v].head<3>());
  Trajectory t = pull(d0, d0 + Vec3(0, 0, 0.02), 1, 50, 500, 1500);  // 0.25 toward the eye
  for (std::size_t i = 1200; i < t.ticks.size(); ++i) t.ticks[i].buttons = 0;  // let go
  LiveOptions lo;
  lo.button_carry = rings;
  Rig rig(scene, std::make_unique<ReplayDevice>(std::move(t), false), lo);
  rig.loop->run_ticks(1100);
  const SceneStatus held = rig.snap().status;
  EXPECT_EQ(held.held_vertex, v);
  EXPECT_EQ(held.carry_rings, rings);
  const std::vector<Vec4> x = positions(rig.snap());
  EXPECT_NEAR(x[v].z() - start[v].z(), 0.25, 0.01) << "the centre goes with the hand";
  const double w = (1 - 1 / 9.0) * (1 - 1 / 9.0);  // the neighbour, ring 1 of 2: (1 - (1/3)^2)^2
  EXPECT_NEAR(x[neighbour].z() - start[neighbour].z(), w * 0.25, 0.01) << "its neighbour by its weight";
  int pinned = 0;
  for (std::size_t i = 0; i < rig.snap().flags.size(); ++i) pinned += rig.snap().flags[i] & 1;
  EXPECT_EQ(pinned, 19) << "the patch is held: 1 + 6 + 12 vertices, two rings of the triangulated grid";
  EXPECT_EQ(rig.snap().flags[far] & 1, 0) << "outside the patch nothing is held";
  rig.loop->run_ticks(900);  // the button is up
  EXPECT_EQ(rig.snap().status.held_vertex, -1);
  const std::vector<Vec4> after = positions(rig.snap());
  EXPECT_NEAR(after[v].z() - start[v].z(), 0.25, 0.01) << "the patch stays where it was let go";
  EXPECT_EQ(rig.snap().status.pinned, pinned);
  EXPECT_EQ(true_intersections(after, scene), 0);
  EXPECT_EQ(rig.snap().safety.nonfinite, 0u);
  EXPECT_LE(rig.snap().max_force_output, 3.3 + 1e-12);
}

}  // namespace
}  // namespace s4d
