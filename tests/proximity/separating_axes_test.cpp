// The cheap rejections of the narrow phase (separating_axes.hpp) and the float node boxes of the
// BVH must be conservative: never drop a pair the exact distance or the double boxes keep.
#include "proximity/separating_axes.hpp"

#include <gtest/gtest.h>

#include <set>

#include "proximity/bvh.hpp"
#include "proximity/reference.hpp"

namespace s4d {
namespace {

using test::random_vec;

// Random simplices near each other (some crossing, some parallel stacked, some degenerate), with
// delta around their exact distance: a rejection must always mean distance > delta.
template <int D, int KA, int KB>
void check_static(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  int rejected = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Simplex<D, KA> a;
    Simplex<D, KB> b;
    const Vec<D> offset = random_vec<D>(rng, 0.6);
    for (auto& p : a) p = random_vec<D>(rng, 0.3);
    for (int j = 0; j < KB; ++j) b[j] = (trial % 5 == 0 && j < KA ? a[j] : random_vec<D>(rng, 0.3)) + offset;
    if (trial % 7 == 0) a[KA - 1] = a[0];  // degenerate
    const double d = closest_points<D, KA, KB>(a, b).distance;
    for (double f : {0.0, 0.5, 0.99, 1.0, 1.01, 2.0}) {
      const double delta = f * d;
      const bool far_ab = provably_farther<D, KA, KB>(a, b, delta);
      if (far_ab) {
        ++rejected;
        EXPECT_GT(d, delta) << "D=" << D << " trial " << trial;
      }
      // The bound itself never exceeds the distance, whatever it was asked to reach.
      const double lower = distance_lower_bound<D, KA, KB>(a, b, delta);
      EXPECT_LE(lower, d * (1 + 1e-12) + 1e-15) << "D=" << D << " trial " << trial;
      EXPECT_EQ(lower > delta, far_ab);
      // Also the swept version with no motion, and with motion over a short step.
      if (provably_apart_over_step<D, KA, KB>(a, a, b, b, 1.0, delta)) {
        EXPECT_GT(d, delta);
      }
    }
  }
  EXPECT_GT(rejected, 1000) << "the bounds should reject most far pairs";
}

TEST(SeparatingAxes, StaticBoundsAreConservative) {
  check_static<2, 3, 3>(1);
  check_static<3, 3, 3>(2);
  check_static<4, 3, 3>(3);
  check_static<4, 2, 3>(4);
  check_static<4, 3, 2>(5);
  check_static<3, 2, 2>(6);
  check_static<4, 1, 3>(7);
}

// Over a step: if the bound says "apart over [0, t_max]", dense time sampling finds no contact.
template <int D, int KA, int KB>
void check_swept(unsigned seed) {
  std::mt19937 rng(seed);
  int rejected = 0;
  for (int trial = 0; trial < 600; ++trial) {
    Simplex<D, KA> a0, a1;
    Simplex<D, KB> b0, b1;
    const Vec<D> offset = random_vec<D>(rng, 0.8);
    for (int i = 0; i < KA; ++i) a0[i] = random_vec<D>(rng, 0.3), a1[i] = a0[i] + random_vec<D>(rng, 0.3);
    for (int j = 0; j < KB; ++j)
      b0[j] = random_vec<D>(rng, 0.3) + offset, b1[j] = b0[j] + random_vec<D>(rng, 0.3);
    const double delta = 0.05, t_max = trial % 2 ? 1.0 : 0.5;
    if (!provably_apart_over_step<D, KA, KB>(a0, a1, b0, b1, t_max, delta)) continue;
    ++rejected;
    for (int s = 0; s <= 200; ++s) {
      const double t = t_max * s / 200;
      const double d = closest_points<D, KA, KB>(lerp_simplex<D, KA>(a0, a1, t),
                                                 lerp_simplex<D, KB>(b0, b1, t)).distance;
      ASSERT_GT(d, delta) << "D=" << D << " trial " << trial << " t=" << t;
    }
  }
  EXPECT_GT(rejected, 50);
}

TEST(SeparatingAxes, SweptBoundsAreConservative) {
  check_swept<2, 3, 3>(11);
  check_swept<3, 3, 3>(12);
  check_swept<4, 3, 3>(13);
  check_swept<4, 2, 2>(14);
}

TEST(SeparatingAxes, NanNeverRejects) {
  Simplex<4, 3> a{Vec4::Zero(), Vec4::UnitX(), Vec4::UnitY()};
  Simplex<4, 3> b{Vec4::Constant(5), Vec4::Constant(std::nan("")), Vec4::Constant(6)};
  EXPECT_FALSE((provably_farther<4, 3, 3>(a, b, 0.1)));
}

// Float boxes are outward: every pair the double test keeps, the float test keeps, for boxes at
// large offsets (where float rounding is coarse) and margins down to zero.
TEST(FloatBox, NeverRejectsWhatDoublesKeep) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20000; ++trial) {
    const double base = (trial % 3 == 0) ? 1e4 : 1.0;
    Box<3> a, b;
    Vec3 p(base + u(rng), -base + u(rng), u(rng) * 1e-3);
    a.add(p);
    a.add(p + Vec3(1e-6 * std::abs(u(rng)), 1e-3, 1e-9));
    // b touches a (or nearly) on the first axis
    Vec3 q = p;
    q[0] = a.hi[0] + 1e-9 * u(rng);
    b.add(q);
    b.add(q + Vec3(1e-5, 1e-5, 1e-5));
    for (double m : {0.0, 1e-12, 1e-9, 1e-6}) {
      if (a.near(b, m)) {
        EXPECT_TRUE(FloatBox::outward<3>(a).near(FloatBox::outward<3>(b), float_margin(m)));
      }
    }
  }
  Box<2> n;
  n.add(Vec2(std::nan(""), 0.0));
  EXPECT_TRUE(FloatBox::outward<2>(n).near(FloatBox::outward<2>(Box<2>{Vec2(9, 0), Vec2(9, 0)}), 0.f));
}

// pairs_with and query against brute force on random boxes (self_pairs is covered in
// mesh_proximity_test.cpp).
TEST(FloatBox, BvhPairAndPointQueriesEqualBruteForce) {
  std::mt19937 rng(22);
  for (int n : {1, 2, 5, 40, 400}) {
    std::vector<Box<3>> a(n), b(n / 2 + 1);
    for (auto* v : {&a, &b})
      for (auto& box : *v) {
        const Vec3 c = random_vec<3>(rng);
        box.add(c);
        box.add(c + random_vec<3>(rng, 0.15));
      }
    Bvh<3> ta, tb;
    ta.build(a);
    tb.build(b);
    std::set<std::pair<int, int>> got, want;
    ta.pairs_with(tb, 0.02, [&](int i, int j) { EXPECT_TRUE(got.insert({i, j}).second); });
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < static_cast<int>(b.size()); ++j)
        if (a[i].near(b[j], 0.02)) want.insert({i, j});
    EXPECT_EQ(got, want);
    std::set<int> qgot, qwant;
    ta.query(b[0], 0.05, [&](int i) { qgot.insert(i); });
    for (int i = 0; i < n; ++i)
      if (a[i].near(b[0], 0.05)) qwant.insert(i);
    EXPECT_EQ(qgot, qwant);
  }
}

}  // namespace
}  // namespace s4d
