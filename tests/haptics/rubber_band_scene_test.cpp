// The rubber band (5.1.4) to a vertex of a 4D cloth (physics World<4>), felt through the simulated
// Omni and hand: action/reaction, bounded energy, no sustained oscillation, deterministic.
#include "haptics/rubber_band_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "haptics/haptic_loop.hpp"
#include "haptics/simulated_arm.hpp"
#include "haptics/world_simulation.hpp"
#include "shape/surfaces_4d.hpp"

namespace s4d {
namespace {

// A hanging 8 x 8 cloth of 8 cm in R^4, its top corners pinned, seen through a frame turned in xw.
std::unique_ptr<WorldSimulation<4>> make_cloth(Frame<4>* frame_out = nullptr) {
  PhysicsParams<4> p;
  p.gravity = Vec4(0, -9.81, 0, 0);
  p.collisions = false;  // the band's stability is under test here; collisions have their own tests
  ModelBuilder<4> b(p);
  b.add_body(cloth(8, 0.08));
  World<4> world(b.build());
  for (int v = 0; v < world.vertex_count(); ++v) {
    const Vec4 x = world.positions()[v];
    if (x.y() > 0.039 && std::abs(std::abs(x.x()) - 0.04) < 1e-9) world.pin(v);
  }
  Frame<4> frame;
  frame.rotate(Plane{0, 3}, 0.3);
  if (frame_out) *frame_out = frame;
  return std::make_unique<WorldSimulation<4>>(std::move(world), frame, 1.0);
}

TEST(WorldSimulation, ProjectsAndLiftsWithTheFrame) {
  Frame<4> frame;
  auto sim = make_cloth(&frame);
  const World<4>& w = sim->world();
  for (int v : {0, 17, 63}) {
    const Vec3 expected = frame.shadow(w.positions()[v]);
    EXPECT_LT((sim->shadow_position(v) - expected).norm(), 1e-15);
  }
  // A device force along x acts in the world along the frame's first axis (inside the shadow).
  sim->set_external_force(20, Vec3(1, 0, 0));
  EXPECT_LT((w.data().f_ext[20] - frame.axis(0)).norm(), 1e-15);
  EXPECT_NEAR(w.data().f_ext[20].dot(frame.axis(3)), 0, 1e-15) << "no push along the depth axis";
  sim->set_external_force(-1, Vec3::Zero());
  EXPECT_EQ(w.data().f_ext[20], Vec4::Zero()) << "released";
}

TEST(RubberBandScene, PicksOnPressAndPullsTheVertexBack) {
  RubberBandScene scene(make_cloth());
  DeviceState s;
  s.position = scene.simulation().shadow_position(9);
  EXPECT_FALSE(scene.step(s, 1e-3).engaged) << "no button, nothing held";
  s.buttons = 1;
  s.position = scene.simulation().shadow_position(9);
  scene.step(s, 1e-3);  // press on the vertex: picked
  s.position = scene.simulation().shadow_position(9) + Vec3(0.01, 0, 0);  // then 1 cm away
  const ToolOutput out = scene.step(s, 1e-3);
  EXPECT_EQ(scene.picked_vertex(), 9);
  EXPECT_TRUE(out.engaged);
  // K = 150 N/m over 1 cm: about 1.5 N towards the vertex.
  EXPECT_NEAR(out.force.x(), -1.5, 0.05);
  s.buttons = 0;
  scene.step(s, 1e-3);
  EXPECT_EQ(scene.picked_vertex(), -1);
}

TEST(RubberBandScene, StableOnTheSimulatedArm) {
  auto sim = make_cloth();
  const int vertex = 3 * 8 + 4;
  const Vec3 start = sim->shadow_position(vertex);
  auto arm = std::make_unique<SimulatedArm>();
  SimulatedArm* a = arm.get();
  a->set_position(start);
  // The hand drags the vertex 2 cm sideways over 0.5 s, then holds still for 2.5 s.
  a->set_hand_script([start](double t) -> Vec3 { return start + Vec3(0.02 * std::min(1.0, t / 0.5), 0, 0); });
  auto scene = std::make_unique<RubberBandScene>(std::move(sim));
  scene->set_param(RubberBandScene::kHold, 1);
  RubberBandScene* rb = scene.get();
  HapticLoopConfig cfg;
  cfg.publish_every = 1000;
  HapticLoop loop(std::move(arm), std::move(scene), cfg);
  double max_energy = 0, sum_v2 = 0;
  int n = 0;
  const int ticks = 3000;
  for (int i = 0; i < ticks; ++i) {
    loop.run_ticks(1);
    const auto& world = static_cast<const WorldSimulation<4>&>(rb->simulation()).world();
    const double band =
        0.5 * 150 * (a->true_position() - rb->simulation().shadow_position(vertex)).squaredNorm();
    max_energy =
        std::max(max_energy, a->mechanical_energy() + world.kinetic_energy() + world.spring_energy() + band);
    if (i >= ticks - 300) {
      sum_v2 += a->true_velocity().squaredNorm();
      ++n;
    }
  }
  const Vec3 moved = rb->simulation().shadow_position(vertex) - start;
  EXPECT_EQ(rb->picked_vertex(), vertex);
  EXPECT_GT(moved.x(), 0.003) << "the band's reaction dragged the cloth vertex along";
  EXPECT_LT(max_energy, 0.05) << "energy bounded";
  EXPECT_LT(std::sqrt(sum_v2 / n), 2e-3) << "no sustained oscillation";
  EXPECT_EQ(loop.safety().counters().nonfinite, 0u);
}

}  // namespace
}  // namespace s4d
