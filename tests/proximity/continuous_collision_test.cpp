// Continuous collision never misses a contact that fine time sampling finds, in R^2, R^3, R^4,
// and catches the R^4 edge-through-triangle contact that end-of-step checks miss.
#include "proximity/continuous_collision.hpp"

#include <gtest/gtest.h>

#include "proximity/reference.hpp"

namespace s4d {
namespace {

using test::random_vec;

template <int D, int KA, int KB>
void check_never_misses(unsigned seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  int hits = 0;
  for (int n = 0; n < count; ++n) {
    Simplex<D, KA> a0, a1;
    Simplex<D, KB> b0, b1;
    // A tumbles a little; B flies towards (or past) A with some spin.
    const Vec<D> drift = random_vec<D>(rng, 0.3);
    for (int i = 0; i < KA; ++i) {
      a0[i] = random_vec<D>(rng, 0.5);
      a1[i] = a0[i] + drift + random_vec<D>(rng, 0.2);
    }
    // B starts well away and flies at a point near where A ends up (through it, or past it).
    Vec<D> centre = Vec<D>::Zero();
    for (int i = 0; i < KA; ++i) centre += a1[i] / KA;
    const Vec<D> start = random_vec<D>(rng, 0.5) + Vec<D>::Constant(1.5);
    const Vec<D> aim = centre + random_vec<D>(rng, 0.2);
    for (int j = 0; j < KB; ++j) {
      const Vec<D> spread = random_vec<D>(rng, 0.4);
      b0[j] = start + spread;
      b1[j] = aim + spread + random_vec<D>(rng, 0.1);
    }
    if (n % 5 == 0 && KB >= 2) b1[1] = b0[1];  // one vertex pinned: rotation-like motion
    CcdOptions opt;
    opt.thickness = (n % 4) * 0.06;  // δ = 0 too: touching is non-generic in R^4 but not in R^2
    const CcdResult<D> r = earliest_contact<D, KA, KB>(a0, a1, b0, b1, opt);
    // Fine sampling: the first sampled time within the thickness.
    double first = 2;
    const int samples = 4000;
    for (int k = 0; k <= samples; ++k) {
      const double t = double(k) / samples;
      const double d =
          closest_points<D, KA, KB>(lerp_simplex<D, KA>(a0, a1, t), lerp_simplex<D, KB>(b0, b1, t))
              .distance;
      if (d <= opt.thickness) {
        first = t;
        break;
      }
    }
    SCOPED_TRACE("D=" + std::to_string(D) + " case " + std::to_string(n));
    if (first <= 1) {
      ++hits;
      ASSERT_TRUE(r.hit);
      EXPECT_LE(r.t, first + 1e-12);
    }
    if (r.hit) {
      // Stopped early by at most the tolerance: the distance there is within reach of δ.
      const double speed = relative_speed_bound<D, KA, KB>(a0, a1, b0, b1);
      if (r.iterations < opt.max_iterations) {
        EXPECT_LE(r.at_t.distance, opt.thickness + speed * opt.time_tolerance * 1.0001 + 1e-15);
      }
    }
  }
  EXPECT_GT(hits, count / 20);  // the generator does produce contacts
}

template <int D>
void all_pairs(unsigned seed) {
  check_never_misses<D, 1, 3>(seed + 1, 150);
  check_never_misses<D, 2, 2>(seed + 2, 150);
  check_never_misses<D, 2, 3>(seed + 3, 150);
  check_never_misses<D, 3, 3>(seed + 4, 150);
}

TEST(ContinuousCollision, NeverMissesASampledContactInR2) { all_pairs<2>(10); }
TEST(ContinuousCollision, NeverMissesASampledContactInR3) { all_pairs<3>(20); }
TEST(ContinuousCollision, NeverMissesASampledContactInR4) { all_pairs<4>(30); }

TEST(ContinuousCollision, EdgeSweepsThroughTriangleInteriorInR4) {
  // Triangle in the xy-plane at rest; a segment along z sweeps in w from w = +1 to w = -1 above
  // the triangle's interior. At t = 0 and t = 1 everything is 1 apart, and the segment's end
  // points stay far from the triangle throughout: only the edge–interior contact (at t = 0.5)
  // reveals the pass-through.
  const Simplex<4, 3> tri{Vec4(0, 0, 0, 0), Vec4(1, 0, 0, 0), Vec4(0, 1, 0, 0)};
  const Simplex<4, 2> e0{Vec4(0.25, 0.25, -1, 1), Vec4(0.25, 0.25, 1, 1)};
  const Simplex<4, 2> e1{Vec4(0.25, 0.25, -1, -1), Vec4(0.25, 0.25, 1, -1)};
  EXPECT_NEAR((closest_points<4, 2, 3>(e0, tri).distance), 1.0, 1e-15);
  EXPECT_NEAR((closest_points<4, 2, 3>(e1, tri).distance), 1.0, 1e-15);
  CcdOptions opt;
  opt.thickness = 0.01;
  const auto r = earliest_contact<4, 2, 3>(e0, e1, tri, tri, opt);
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.t, 0.495, 1e-5);  // distance |1 - 2t| reaches 0.01 at t = 0.495
  EXPECT_LE(r.t, 0.495 + 1e-12);
  EXPECT_GT(r.at_t.distance, 0.0);
  // Stopping short: a step ending before the contact reports none.
  opt.t_max = 0.4;
  EXPECT_FALSE((earliest_contact<4, 2, 3>(e0, e1, tri, tri, opt).hit));
}

TEST(ContinuousCollision, RigidCommonMotionNeverHitsAndNaNIsReportedAsContact) {
  const Simplex<3, 2> a0{Vec3(0, 0, 0), Vec3(1, 0, 0)}, b0{Vec3(0, 1, 0), Vec3(1, 1, 0)};
  Simplex<3, 2> a1 = a0, b1 = b0;
  for (auto& v : a1) v += Vec3(5, 5, 5);
  for (auto& v : b1) v += Vec3(5, 5, 5);
  EXPECT_FALSE((earliest_contact<3, 2, 2>(a0, a1, b0, b1, {}).hit));
  b1[0].x() = std::numeric_limits<double>::quiet_NaN();
  const auto r = earliest_contact<3, 2, 2>(a0, a1, b0, b1, {});
  EXPECT_TRUE(r.hit);  // the safe side: a non-finite motion is never "free"
}

}  // namespace
}  // namespace s4d
