// The haptic loop's scenes by name: the cloth is a scene built by the world builder and run by the
// live simulation, held by its corners across resets; the rubber band's reaction is what the hand
// feels, stable on the simulated arm; a recording replays bit for bit; on its own thread a slow
// physics never stalls the loop; older recordings' scene names still open.
#include "interact/live/haptic_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>

#include "core/error.hpp"
#include "haptics/haptic_loop.hpp"
#include "haptics/mouse_device.hpp"
#include "haptics/replay_device.hpp"
#include "haptics/simulated_arm.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

HapticSceneChoice cloth_choice(int n, bool collisions = true, bool async = false) {
  HapticSceneChoice c;
  c.name = "cloth";
  c.cloth_n = n;
  c.collisions = collisions;
  c.async_physics = async;
  return c;
}

std::vector<Vec4> positions(const HapticSnapshot& s) {
  std::vector<Vec4> x(s.points.size() / 4);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < 4; ++k) x[i][k] = s.points[4 * i + static_cast<std::size_t>(k)];
  return x;
}

// Up to 20 s: a deadline for a thread to get going, not a bound on its speed (those are asserted
// on their own); the checked builds, instrumented on a loaded machine, need more than release.
template <typename Pred>
bool wait_for(HapticLoop& loop, Pred pred) {
  for (int i = 0; i < 2000 && !pred(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    loop.run_ticks(0);  // publishes the physics thread's newest state
  }
  return pred();
}

// Ticks the loop at about 1 kHz until pred holds, up to 60 s. For a condition on the simulated
// time: the physics is owed at most a moment of the loop's clock, so on a slow (instrumented,
// loaded) build it is reached by ticking on, not by waiting.
template <typename Pred>
bool tick_until(HapticLoop& loop, Pred pred) {
  for (int i = 0; i < 60000 && !pred(); ++i) {
    loop.run_ticks(1);
    std::this_thread::sleep_for(std::chrono::microseconds(1000));
  }
  return pred();
}

TEST(HapticScenes, TheClothIsASceneHeldByItsCornersAcrossResets) {
  const Scene scene = haptic_cloth_scene(8, 0.1, true);
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].generator->name, "cloth");
  const auto& start = std::get<Surface<4>>(scene.objects[0].shape).vertices;
  HapticSceneSetup setup = make_haptic_scene(cloth_choice(8));
  EXPECT_EQ(setup.scene->name(), "cloth");
  EXPECT_EQ(setup.held_vertex, 4 * 8 + 2);
  EXPECT_LT((setup.hand_start - scene.frame.shadow(start[34])).norm(), 1e-15) << "the hand starts on it (1 unit = 1 m)";
  HapticLoop loop(std::make_unique<MouseDevice>(), std::move(setup.scene));
  loop.run_ticks(400);
  std::vector<Vec4> x = positions(loop.snapshot());
  ASSERT_EQ(x.size(), 64u);
  EXPECT_EQ(loop.snapshot().status.pinned, 2);
  for (int v : haptic_cloth_corners(8)) EXPECT_EQ(x[v], start[v]) << "corner " << v << " holds";
  EXPECT_LT(x[34].y(), start[34].y() - 0.005) << "the rest hangs down under gravity";
  loop.send(live::command(live::Reset{}));  // the window's reset, and the loop's below
  loop.run_ticks(1);
  EXPECT_LE(loop.snapshot().status.sim_steps, 1);
  EXPECT_LT((positions(loop.snapshot())[34] - start[34]).norm(), 1e-3) << "back at the start";
  loop.run_ticks(300);
  loop.reset_scene();
  loop.run_ticks(300);
  x = positions(loop.snapshot());
  EXPECT_EQ(loop.snapshot().status.pinned, 2) << "a reset does not drop the cloth";
  for (int v : haptic_cloth_corners(8)) EXPECT_EQ(x[v], start[v]);
  EXPECT_LT(x[34].y(), start[34].y() - 0.005);
}

// A device that rests at `from` for `rest` ticks, then with button 1 held moves to `to` over `move`
// ticks and stays there.
Trajectory pull(const Vec3& from, const Vec3& to, int rest, int move, int hold) {
  Trajectory t;
  t.header.device = "test hand";
  t.header.caps.max_force = 3.3;
  t.header.caps.max_continuous_force = 3.3;
  t.header.caps.max_stiffness = 1000;
  t.header.caps.max_force_rate = 1000;
  t.header.caps.outputs_force = true;
  for (int i = 0; i < rest + move + hold; ++i) {
    TickRecord r;
    r.tick = static_cast<std::uint64_t>(i);
    const double u = i < rest ? 0.0 : std::min(1.0, static_cast<double>(i - rest) / move);
    const Vec3 p = from + u * (to - from);
    const Vec3 v = i >= rest && i < rest + move ? Vec3((to - from) * 1000.0 / move) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      r.position[k] = r.target[k] = p[k];
      r.velocity[k] = v[k];
    }
    r.buttons = i < rest ? 0 : 1;
    t.ticks.push_back(r);
  }
  return t;
}

TEST(HapticScenes, TheHandFeelsTheBandsPullOnTheVertexReversed) {
  HapticSceneSetup setup = make_haptic_scene(cloth_choice(8, false));
  const Vec3 d0 = setup.hand_start, d1 = d0 + Vec3(0, 0, 0.01);  // 1 cm towards the eye
  HapticLoopConfig cfg;
  cfg.publish_every = 1;
  HapticLoop loop(std::make_unique<ReplayDevice>(pull(d0, d1, 5, 100, 2000), false), std::move(setup.scene), cfg);
  int checked = 0;
  for (int i = 0; i < 1500; ++i) {
    loop.run_ticks(1);
    const HapticSnapshot& s = loop.snapshot();
    if (i < 200) continue;
    ASSERT_EQ(s.status.held_vertex, 34);
    const Vec3 stretch = s.status.band_to - s.status.band_from;  // hand → vertex, shadow = device here
    const Vec3 felt = s.tool.force;
    ASSERT_NEAR(felt.norm(), s.status.band_force, 1e-12 * (1 + s.status.band_force)) << "tick " << i;
    if (stretch.norm() > 1e-4) {
      EXPECT_GT(felt.normalized().dot(stretch.normalized()), 0.9) << "towards the vertex, tick " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
  // Held still at the end: the band is a spring of K = 100 N/m between the hand and the vertex.
  const HapticSnapshot& s = loop.snapshot();
  const double k = s.params[kBandStiffness].value;
  EXPECT_NEAR(s.tool.force.norm(), k * (s.status.band_to - s.status.band_from).norm(), 0.1 * s.tool.force.norm());
  EXPECT_GT(s.tool.force.norm(), 0.01) << "the hanging cloth pulls back";
  EXPECT_EQ(s.safety.nonfinite, 0u);
}

TEST(HapticScenes, StableOnTheSimulatedArm) {
  HapticSceneChoice c = cloth_choice(8, false);
  c.cloth_size = 0.08;
  HapticSceneSetup setup = make_haptic_scene(c);
  const Vec3 start = setup.hand_start;
  auto arm = std::make_unique<SimulatedArm>();
  SimulatedArm* a = arm.get();
  a->set_position(start);
  // The hand drags the vertex 2 cm sideways over 0.5 s, then holds still for 2.5 s.
  a->set_hand_script([start](double t) -> Vec3 { return start + Vec3(0.02 * std::min(1.0, t / 0.5), 0, 0); });
  HapticLoopConfig cfg;
  cfg.publish_every = 1000;
  HapticLoop loop(std::move(arm), std::move(setup.scene), cfg);
  loop.set_pointer(start, 1u);  // button 1 held on the vertex
  double max_energy = 0, sum_v2 = 0;
  int n = 0;
  const int ticks = 3000;
  for (int i = 0; i < ticks; ++i) {
    loop.run_ticks(1);
    max_energy = std::max(max_energy, a->mechanical_energy());
    if (i >= ticks - 300) {
      sum_v2 += a->true_velocity().squaredNorm();
      ++n;
    }
  }
  const HapticSnapshot& s = loop.snapshot();
  EXPECT_EQ(s.status.held_vertex, setup.held_vertex);
  const Vec3 moved = s.status.band_to - start;
  EXPECT_GT(moved.x(), 0.01) << "the band dragged the cloth vertex along";
  EXPECT_LT(max_energy, 0.01) << "the arm's energy stays bounded";
  EXPECT_LT(std::sqrt(sum_v2 / n), 2e-3) << "no sustained oscillation";
  EXPECT_GT(s.max_force_output, 0.0);
  EXPECT_EQ(s.safety.nonfinite, 0u);
}

std::unique_ptr<SimulatedArm> circling_arm(const Vec3& start) {
  auto arm = std::make_unique<SimulatedArm>();
  arm->set_position(start);
  arm->set_hand_script([start](double t) -> Vec3 {  // a Vec3, not an Eigen expression of a temporary
    return start + Vec3(0.004 * (std::cos(3 * t) - 1), 0.004 * std::sin(3 * t), 0.003 * std::sin(7 * t));
  });
  return arm;
}

TEST(HapticScenes, AClothRecordingReplaysBitForBit) {
  const fs::path file = fs::temp_directory_path() / "s4d_haptic_scenes_cloth.traj";
  std::uint64_t ticks = 0;
  {
    HapticSceneSetup setup = make_haptic_scene(cloth_choice(6));
    auto arm = circling_arm(setup.hand_start);
    SimulatedArm* a = arm.get();
    HapticLoop loop(std::move(arm), std::move(setup.scene));
    loop.set_pointer(setup.hand_start, 1u);
    loop.record_to(file, "cloth_n=6");
    loop.run_ticks(700);
    loop.reset_scene();  // lets go of the vertex: the hand lets go of the button and presses again
    loop.set_pointer(setup.hand_start, 0u);
    loop.run_ticks(20);
    loop.set_pointer(setup.hand_start, 1u);
    loop.run_ticks(280);
    a->set_connected(false);
    loop.run_ticks(50);
    a->set_connected(true);
    loop.run_ticks(950);
    ticks = loop.ticks();
    loop.finish_recording();
  }
  const Trajectory t = read_trajectory(file);
  ASSERT_EQ(t.ticks.size(), ticks);
  EXPECT_EQ(t.header.scene, "cloth");
  EXPECT_NE(std::find_if(t.header.params.begin(), t.header.params.end(),
                         [](const auto& p) { return p.first == "max force"; }),
            t.header.params.end())
      << "a parameter name with a space reads back";
  std::uint64_t nonzero = 0;
  for (const auto& r : t.ticks) nonzero += r.force[0] != 0 || r.force[1] != 0 || r.force[2] != 0;
  EXPECT_GT(nonzero, ticks / 2) << "the session produced forces worth comparing";

  auto replay = std::make_unique<ReplayDevice>(t, true);
  ReplayDevice* rp = replay.get();
  HapticLoop again(std::move(replay), make_haptic_scene(cloth_choice(6)).scene);
  again.run_ticks(ticks);
  EXPECT_EQ(rp->compared(), ticks - 50) << "every connected tick compared";
  EXPECT_EQ(rp->mismatches(), 0u) << "first mismatch at tick " << rp->first_mismatch_tick();

  auto replay2 = std::make_unique<ReplayDevice>(t, true);
  ReplayDevice* rp2 = replay2.get();
  HapticLoop changed(std::move(replay2), make_haptic_scene(cloth_choice(6)).scene);
  changed.set_param(kBandStiffness, changed.scene().params()[kBandStiffness].value * 1.01);
  changed.run_ticks(ticks);
  EXPECT_GT(rp2->mismatches(), 0u) << "the comparison can fail";
}

TEST(HapticScenes, OnItsOwnThreadASlowPhysicsNeverStallsTheLoop) {
  // The 32² cloth with collisions takes some 8 ms a World step: inline, each tick waits for one.
  HapticLoop inline_loop(std::make_unique<MouseDevice>(), make_haptic_scene(cloth_choice(32)).scene);
  const auto t0 = std::chrono::steady_clock::now();
  inline_loop.run_ticks(3);
  const double inline_tick_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / 3;
  EXPECT_GT(inline_loop.snapshot().status.sim_steps, 0);

  HapticLoop loop(std::make_unique<MouseDevice>(), make_haptic_scene(cloth_choice(32, true, true)).scene);
  ASSERT_TRUE(wait_for(loop, [&] { return loop.snapshot().status.script_running; })) << "the hold script started";
  const std::int64_t steps0 = loop.snapshot().status.sim_steps;
  std::vector<double> tick_us;
  const int ticks = 300;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < ticks; ++i) {  // paced by the wall clock, as the loop's thread would be
    std::this_thread::sleep_until(start + std::chrono::milliseconds(i));
    const auto a = std::chrono::steady_clock::now();
    loop.run_ticks(1);
    tick_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - a).count());
  }
  std::sort(tick_us.begin(), tick_us.end());
  EXPECT_LT(tick_us[ticks * 9 / 10], 500) << "the tick reads the published state and steps nothing";
  EXPECT_LT(tick_us.back(), inline_tick_us) << "not even the slowest tick waits for a World step";
  const SceneStatus& st = loop.snapshot().status;
  EXPECT_LT(st.sim_steps - steps0, ticks / 2) << "the physics fell behind (an inline tick took " << inline_tick_us << " us)";
  EXPECT_GT(st.lag, 0.05);
  EXPECT_LE(st.lag, 0.1 + 1e-9) << "by 0.1 s at most (slow motion beyond)";
  EXPECT_EQ(st.pinned, 2) << "held by its corners";
}

TEST(HapticScenes, OnItsOwnThreadResetGoesBackToTheHeldStart) {
  const Scene scene = haptic_cloth_scene(8, 0.1, true);
  const auto& start = std::get<Surface<4>>(scene.objects[0].shape).vertices;
  HapticLoop loop(std::make_unique<MouseDevice>(), make_haptic_scene(cloth_choice(8, true, true)).scene);
  ASSERT_TRUE(tick_until(loop, [&] { return loop.snapshot().status.sim_time > 0.25; }));
  EXPECT_LT(positions(loop.snapshot())[34].y(), start[34].y() - 0.005);
  loop.reset_scene();
  loop.run_ticks(1);
  ASSERT_TRUE(wait_for(loop, [&] { return loop.snapshot().status.sim_time < 0.01; })) << "restarted";
  EXPECT_LT((positions(loop.snapshot())[34] - start[34]).norm(), 1e-3);
  ASSERT_TRUE(tick_until(loop, [&] { return loop.snapshot().status.sim_time > 0.15; }));
  const std::vector<Vec4> x = positions(loop.snapshot());
  EXPECT_EQ(loop.snapshot().status.pinned, 2);
  for (int v : haptic_cloth_corners(8)) EXPECT_EQ(x[v], start[v]);
  EXPECT_LT(x[34].y(), start[34].y() - 0.005) << "and runs on, held by its corners";
}

TEST(HapticScenes, NamesOldAndNew) {
  EXPECT_EQ(make_haptic_scene({}).scene->name(), "sticky-plane");
  HapticSceneChoice c;
  c.name = "sticky-plane";
  EXPECT_EQ(make_haptic_scene(c).held_vertex, -1);
  c.name = "rubber-band";  // recordings made before the cloth was a live simulation
  c.cloth_n = 4;
  EXPECT_EQ(make_haptic_scene(c).scene->name(), "cloth");
  c.cloth_n = 1;
  EXPECT_THROW(make_haptic_scene(c), Error);
  c.name = "trampoline";
  EXPECT_THROW(make_haptic_scene(c), Error);
  EXPECT_THROW(make_held_live_simulation("x", haptic_cloth_scene(4, 0.1, true), "cloth", {16}, {}), Error);
  EXPECT_THROW(make_held_live_simulation("x", haptic_cloth_scene(4, 0.1, true), "sheet", {0}, {}), Error);
}

TEST(HapticScenes, TheWorkspaceFitHoldsTheShadow) {
  const Scene scene = haptic_cloth_scene(8, 2.0, true);
  MouseDevice mouse;
  const DeviceCapabilities& caps = mouse.capabilities();
  const DeviceMapping m = fit_to_workspace(scene, caps);
  for (const Vec4& p : std::get<Surface<4>>(scene.objects[0].shape).vertices) {
    const Vec3 d = m.to_device(scene.frame.shadow(p));
    EXPECT_TRUE((d.array() >= caps.workspace_min.array() - 1e-12).all() &&
                (d.array() <= caps.workspace_max.array() + 1e-12).all());
  }
}

}  // namespace
}  // namespace s4d
