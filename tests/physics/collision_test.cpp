// Collision avoidance: surfaces driven into each other in R^3 and R^4 never pass through (the
// same runs with collisions off do, so the check can fail), contacts do not add energy, and the
// friction setting decides whether a body slides.
#include "physics/collision.hpp"

#include <gtest/gtest.h>

#include "physics/test_worlds.hpp"

namespace s4d {
namespace {

// Two parallel cloths, the second `gap` away along the last axis, pushed together by forces.
template <int D>
World<D> facing_cloths(bool collisions, double gap) {
  PhysicsParams<D> p;
  p.collisions = collisions;
  ModelBuilder<D> b(p);
  b.add_body(test::flat_cloth<D>(8, 0.5));
  Vec<D> off = Vec<D>::Zero();
  off[D - 1] = gap;
  off[0] = 0.013;  // not vertex-aligned
  b.add_body(test::flat_cloth<D>(8, 0.5, off));
  return World<D>(b.build());
}

// Signed gap along the last axis between the centres of the two cloths.
template <int D>
double centre_gap(const World<D>& w) {
  double a = 0, b = 0;
  const int n = w.vertex_count() / 2;
  for (int i = 0; i < n; ++i) {
    a += w.positions()[i][D - 1];
    b += w.positions()[n + i][D - 1];
  }
  return (b - a) / n;
}

template <int D>
void pushed_together(bool collisions) {
  World<D> w = facing_cloths<D>(collisions, 0.05);
  const int n = w.vertex_count() / 2;
  Vec<D> push = Vec<D>::Zero();
  push[D - 1] = 0.02;  // N per vertex, towards each other
  for (int i = 0; i < n; ++i) {
    w.set_external_force(i, push);
    w.set_external_force(n + i, -push);
  }
  double min_sep = 1e9;
  for (int s = 0; s < 1500; ++s) {
    w.step();
    if (s % 100 == 99) min_sep = std::min(min_sep, w.min_separation(0.1));
  }
  if (collisions) {
    EXPECT_GT(centre_gap(w), 0);
    EXPECT_GT(min_sep, 0.99 * w.model().hard_thickness);
    EXPECT_GT(w.data().last_contacts, 0);
  } else {
    EXPECT_LT(centre_gap(w), 0);  // without avoidance they pass through each other
  }
}
TEST(Collision, PushedClothsNeverPassD3) { pushed_together<3>(true); }
TEST(Collision, PushedClothsNeverPassD4) { pushed_together<4>(true); }
TEST(Collision, WithoutAvoidanceTheyDoPassD4) { pushed_together<4>(false); }

template <int D>
void thrown_fast() {
  // 15 m/s towards the other cloth: 15 mm per step, near δ per step: the fail-safe must hold.
  World<D> w = facing_cloths<D>(true, 0.06);
  std::vector<Vec<D>> v(w.vertex_count(), Vec<D>::Zero());
  for (int i = w.vertex_count() / 2; i < w.vertex_count(); ++i) v[i][D - 1] = -15;
  w.set_state(std::vector<Vec<D>>(w.positions().begin(), w.positions().end()), v);
  const double e0 = w.kinetic_energy();
  for (int s = 0; s < 200; ++s) {
    w.step();
    ASSERT_GT(w.min_separation(0.1), 0.99 * w.model().hard_thickness) << "step " << s;
    // Contacts are inelastic: the energy never rises above where it started (no gravity here).
    ASSERT_LE(w.kinetic_energy() + w.spring_energy(), e0 * 1.0001);
  }
  EXPECT_GT(centre_gap(w), 0);
}
TEST(Collision, ThrownClothIsStoppedD3) { thrown_fast<3>(); }
TEST(Collision, ThrownClothIsStoppedD4) { thrown_fast<4>(); }

// A small triangle sliding over a pinned floor cloth under gravity: friction decides how far.
double slide_distance(double friction) {
  PhysicsParams<3> p;
  p.friction = friction;
  p.damping = 0;
  p.gravity = Vec3(0, 0, -9.81);
  ModelBuilder<3> b(p);
  b.add_body(test::flat_cloth<3>(10, 1.0));
  b.add_body(test::lone_triangle<3>(0.05, Vec3(-0.3, 0.01, 0.015)));
  World<3> w(b.build());
  for (int i = 0; i < 100; ++i) w.pin(i);
  std::vector<Vec3> v(w.vertex_count(), Vec3::Zero());
  for (int i = 100; i < 103; ++i) v[i] = Vec3(1.0, 0, 0);
  w.set_state(std::vector<Vec3>(w.positions().begin(), w.positions().end()), v);
  for (int s = 0; s < 300; ++s) w.step();
  EXPECT_GT(w.positions()[100][2], 0.0);  // still above the floor
  return w.positions()[100][0] - (-0.3);
}

TEST(Collision, FrictionSlowsSlidingSlipperyDoesNot) {
  const double slippery = slide_distance(0.0);
  const double rough = slide_distance(1.0);
  EXPECT_GT(slippery, 0.27);  // ~1 m/s for 0.3 s
  EXPECT_LT(rough, 0.2);      // μ g = 9.81 m/s²: stops after ~0.1 s and 5 cm
  EXPECT_LT(rough, slippery - 0.1);
}

// The repulsion's impulses on finite but absurd input (heavy vertices closing at 1e308 m/s, so
// the impulse overflows): the solver says so, for the world to roll the step back. The same
// contact at a sane speed stays finite and says nothing.
template <int D>
bool repulsion_overflows(double speed) {
  PhysicsParams<D> p = test::quiet_params<D>();
  p.mass = 1e6;
  ModelBuilder<D> b(p);
  b.add_body(test::lone_triangle<D>(0.1));
  Vec<D> off = Vec<D>::Zero();
  off[D - 1] = 0.2 * p.thickness;  // within δ
  b.add_body(test::lone_triangle<D>(0.1, off));
  const Model<D> model = b.build();
  CollisionSolver<D, 3> solver(model);
  const std::vector<Vec<D>> x0(model.initial.begin(), model.initial.end());
  std::vector<Vec<D>> x1 = x0, v(x0.size(), Vec<D>::Zero());
  for (int i = 3; i < 6; ++i) v[i][D - 1] = -speed;  // the upper triangle falls onto the lower
  const std::vector<std::uint8_t> pinned(x0.size(), 0);
  const CollisionStats stats = solver.solve(model, x0, x1, v, pinned, 1e-3);
  EXPECT_GT(stats.contacts, 0);
  bool finite = true;
  for (std::size_t i = 0; i < x0.size(); ++i) finite = finite && all_finite(x1[i]) && all_finite(v[i]);
  EXPECT_EQ(stats.nonfinite, !finite);
  return stats.nonfinite;
}
TEST(Collision, OverflowingImpulseIsReportedD3) {
  EXPECT_TRUE(repulsion_overflows<3>(1e308));
  EXPECT_FALSE(repulsion_overflows<3>(1.0));
}
TEST(Collision, OverflowingImpulseIsReportedD4) {
  EXPECT_TRUE(repulsion_overflows<4>(1e308));
  EXPECT_FALSE(repulsion_overflows<4>(1.0));
}

}  // namespace
}  // namespace s4d
