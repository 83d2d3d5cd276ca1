// World<D>: equilibrium, free fall against the closed form, energy conservation, pins and tool
// forces, roll-back of exploding steps, determinism, and no allocation inside a step.
#include "physics/world.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <new>
#include <random>

#include "physics/test_worlds.hpp"

// Counts heap allocations so the test can assert that a warmed-up step makes none.
static std::atomic<long> g_allocations{0};
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
// GCC sees free() meet a pointer from (this) operator new and warns; here the pair is malloc/free.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace s4d {
namespace {

template <int D>
World<D> make_world(const PhysicsParams<D>& p, const std::vector<Surface<D>>& bodies) {
  ModelBuilder<D> b(p);
  for (const auto& s : bodies) b.add_body(s);
  return World<D>(b.build());
}

template <int D>
void rest_is_equilibrium() {
  World<D> w = make_world<D>(test::quiet_params<D>(), {test::flat_cloth<D>(6, 1.0)});
  for (int i = 0; i < 500; ++i) w.step();
  for (int i = 0; i < w.vertex_count(); ++i) {
    EXPECT_LT((w.positions()[i] - w.model().initial[i]).norm(), 1e-12);
    EXPECT_LT(w.velocities()[i].norm(), 1e-12);
  }
}
TEST(World, RestLengthIsEquilibriumD2) { rest_is_equilibrium<2>(); }
TEST(World, RestLengthIsEquilibriumD3) { rest_is_equilibrium<3>(); }
TEST(World, RestLengthIsEquilibriumD4) { rest_is_equilibrium<4>(); }

template <int D>
void stretched_returns_to_rest() {
  PhysicsParams<D> p = test::quiet_params<D>();
  p.damping = 0.05;
  p.spring_damping = 0.05;
  World<D> w = make_world<D>(p, {test::lone_triangle<D>(0.5)});
  std::vector<Vec<D>> x(w.positions().begin(), w.positions().end());
  x[1][0] += 0.1;  // stretch one edge by 20 %
  w.set_state(x, std::vector<Vec<D>>(3, Vec<D>::Zero()));
  for (int i = 0; i < 20000; ++i) w.step();
  for (const Spring& s : w.model().springs)
    EXPECT_NEAR((w.positions()[s.b] - w.positions()[s.a]).norm(), s.rest, 1e-6);
}
TEST(World, StretchedTriangleSettlesAtRestLengthsD2) { stretched_returns_to_rest<2>(); }
TEST(World, StretchedTriangleSettlesAtRestLengthsD4) { stretched_returns_to_rest<4>(); }

TEST(World, FreeFallMatchesClosedForm) {
  PhysicsParams<4> p = test::quiet_params<4>();
  p.gravity = Vec4(1.0, -9.81, 0.5, 2.0);  // any direction of R^4
  World<4> w = make_world<4>(p, {test::flat_cloth<4>(4, 0.3)});
  const double h = p.time_step;
  const int n = 500;
  for (int i = 0; i < n; ++i) w.step();
  const double t = n * h;
  for (int i = 0; i < w.vertex_count(); ++i) {
    const Vec4 fall = w.positions()[i] - w.model().initial[i];
    // Symplectic Euler's exact discrete solution: x_n = x_0 + h² g n(n+1)/2 ...
    EXPECT_LT((fall - p.gravity * (h * h * n * (n + 1) / 2)).norm(), 1e-9);
    // ... which is the continuous ½ g t² up to the method's O(h) term ½ g h t.
    EXPECT_LT((fall - 0.5 * p.gravity * t * t).norm(), 0.5 * p.gravity.norm() * h * t + 1e-9);
    EXPECT_LT((w.velocities()[i] - p.gravity * t).norm(), 1e-9);
  }
}

// Largest relative energy error of an undamped, collision-free run of 5 s with tick h.
double energy_drift(double h, double* h_omega) {
  PhysicsParams<4> p = test::quiet_params<4>();
  p.stiffness = 200;
  p.time_step = h;
  p.collisions = false;  // the integrator alone: contacts are allowed to take energy out
  World<4> w = make_world<4>(p, {test::flat_cloth<4>(8, 0.5)});
  std::vector<Vec4> x(w.positions().begin(), w.positions().end());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  for (auto& q : x) q += Vec4(u(rng), u(rng), u(rng), u(rng));
  w.set_state(x, std::vector<Vec4>(x.size(), Vec4::Zero()));
  const double e0 = w.energy();
  double worst = 0;
  const int steps = static_cast<int>(std::lround(5.0 / h));
  for (int i = 0; i < steps; ++i) {
    w.step();
    worst = std::max(worst, std::abs(w.energy() - e0) / e0);
  }
  EXPECT_GT(w.kinetic_energy(), 0.01 * e0);  // it really moved
  EXPECT_EQ(w.data().warnings.rollbacks, 0);
  *h_omega = h / w.data().last_substeps * w.model().omega_max;
  return worst;
}

TEST(World, UndampedSymplecticRunConservesEnergy) {
  // Stated bound: symplectic Euler conserves a modified energy; on a harmonic mode ω the true
  // energy then stays within h·ω/2 of its start (relative), h the substep. No secular drift.
  double hw_coarse = 0, hw_fine = 0;
  const double coarse = energy_drift(1e-3, &hw_coarse);
  const double fine = energy_drift(1e-4, &hw_fine);
  EXPECT_LT(coarse, 0.5 * hw_coarse);
  EXPECT_LT(fine, 0.5 * hw_fine);
  EXPECT_LT(fine, 0.25 * coarse);  // first order in h: 5x smaller substep, >= 4x smaller error
}

TEST(World, PinnedVerticesFollowTheirTargetsAndToolForcesAccelerate) {
  PhysicsParams<4> p = test::quiet_params<4>();
  p.gravity = Vec4(0, 0, 0, -9.81);  // out of the cloth's plane: it swings down in w
  World<4> w = make_world<4>(p, {test::flat_cloth<4>(5, 0.4)});
  w.pin(0);
  w.pin(4, w.positions()[4] + Vec4(0, 0, 0, 0.01));
  for (int i = 0; i < 200; ++i) w.step();
  EXPECT_EQ(w.positions()[0], w.model().initial[0]);
  EXPECT_LT((w.positions()[4] - (w.model().initial[4] + Vec4(0, 0, 0, 0.01))).norm(), 1e-15);
  EXPECT_LT(w.positions()[24][3], -0.01);  // the free corner swings down

  // A lone triangle pushed by F on each vertex moves as x = ½ (F/m) t² (+ O(h) term).
  World<4> t = make_world<4>(test::quiet_params<4>(), {test::lone_triangle<4>(0.1)});
  const Vec4 f(0, 0, 0, 2e-3);  // N
  for (int i = 0; i < 3; ++i) t.set_external_force(i, f);
  t.set_external_force(1, Vec4(NAN, 0, 0, 0));  // rejected, the previous force stays
  EXPECT_EQ(t.data().warnings.rejected_inputs, 1);
  for (int i = 0; i < 300; ++i) t.step();
  const double a = f[3] / 1e-3, time = 0.3;
  EXPECT_NEAR(t.positions()[1][3] - t.model().initial[1][3], 0.5 * a * time * time, a * 1e-3 * time);
}

TEST(World, PaperEulerExplodesOnStiffClothAndIsRolledBackSymplecticDoesNot) {
  PhysicsParams<4> p = test::quiet_params<4>();
  p.stiffness = 2e4;  // N/m: ω·h ≈ 10 at 1 kHz
  p.gravity = Vec4(0, 0, 0, -9.81);
  std::vector<Surface<4>> cloth{test::flat_cloth<4>(8, 0.5)};
  p.integrator = Integrator::kPaperEuler;
  World<4> paper = make_world<4>(p, cloth);
  p.integrator = Integrator::kSymplecticEuler;
  World<4> stable = make_world<4>(p, cloth);
  for (World<4>* w : {&paper, &stable}) {
    w->pin(0);
    w->pin(7);
    for (int i = 0; i < 1000; ++i) w->step();
    for (const Vec4& x : w->positions()) ASSERT_TRUE(x.allFinite());
  }
  EXPECT_GT(paper.data().warnings.rollbacks, 0);
  EXPECT_EQ(stable.data().warnings.rollbacks, 0);
  EXPECT_GT(stable.data().last_substeps, 5);
  EXPECT_LT(stable.positions()[63][3], -0.01);  // it hangs from its pins
}

TEST(World, AdversarialRunStaysFiniteSeparatedAndBounded) {
  PhysicsParams<4> p;
  p.gravity = Vec4(0, -9.81, 0, 0);
  World<4> w = make_world<4>(p, {test::flat_cloth<4>(5, 0.4),
                                 test::flat_cloth<4>(5, 0.4, Vec4(0.05, 0.03, 0.0, 0.1))});
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int> vert(0, w.vertex_count() - 1);
  std::normal_distribution<double> g(0, 1);
  const double eta = w.model().hard_thickness;
  double worst_energy = 0;
  for (int s = 0; s < 100000; ++s) {
    if (s % 50 == 0) {
      w.clear_external_forces();
      for (int k = 0; k < 6; ++k) {
        const Vec4 dir(g(rng), g(rng), g(rng), g(rng));
        w.set_external_force(vert(rng), 2.0 * dir);  // N on a 1 g vertex: ~2000 m/s²
      }
      if (s % 5000 == 0) w.set_external_force(vert(rng), Vec4(INFINITY, 0, NAN, 0));
    }
    w.step();
    worst_energy = std::max(worst_energy, w.kinetic_energy() + w.spring_energy());
    if (s % 10000 == 9999) {
      ASSERT_GT(w.min_separation(0.05), 0.99 * eta) << "step " << s;
    }
  }
  for (const Vec4& x : w.positions()) ASSERT_TRUE(x.allFinite());
  for (const Vec4& v : w.velocities()) ASSERT_TRUE(v.allFinite());
  EXPECT_GT(w.min_separation(0.05), 0.99 * eta);
  // Speed is capped by δ per step, so kinetic energy ≤ ½ m n (δ/h)²; springs stay bounded.
  EXPECT_LT(worst_energy, 50.0);
  EXPECT_GT(w.data().warnings.rejected_inputs, 0);
}

TEST(World, SameInputsGiveBitIdenticalRuns) {
  auto run = [] {
    PhysicsParams<4> p;
    p.gravity = Vec4(0, -9.81, 0, 1);
    World<4> w = make_world<4>(p, {test::flat_cloth<4>(6, 0.3)});
    w.pin(0);
    for (int i = 0; i < 300; ++i) w.step();
    std::uint64_t hash = 1469598103934665603ull;
    for (const Vec4& x : w.positions())
      for (int k = 0; k < 4; ++k) {
        std::uint64_t bits;
        const double c = x[k];
        std::memcpy(&bits, &c, 8);
        hash = (hash ^ bits) * 1099511628211ull;
      }
    return hash;
  };
  EXPECT_EQ(run(), run());
}

TEST(World, WarmStepAllocatesNothing) {
  PhysicsParams<4> p;
  p.gravity = Vec4(0, -9.81, 0, 0);
  World<4> w = make_world<4>(p, {test::flat_cloth<4>(10, 0.5),
                                 test::flat_cloth<4>(6, 0.3, Vec4(0, -0.1, 0.0, 0.05))});
  w.pin(0);
  w.pin(9);
  for (int i = 0; i < 100; ++i) w.step();
  const long before = g_allocations.load();
  for (int i = 0; i < 100; ++i) w.step();
  EXPECT_EQ(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace s4d
