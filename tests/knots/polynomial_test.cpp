// Laurent polynomials, fingerprints and the Alexander polynomial derived from HOMFLY-PT.
#include "knots/polynomial.hpp"

#include <gtest/gtest.h>

#include <random>

namespace s4d {
namespace {

// HOMFLY-PT (alpha, z) of the right-handed trefoil in Regina's convention.
Laurent2 trefoil() {
  Laurent2 p;
  p.add(-2, 2, 1);
  p.add(-2, 0, 2);
  p.add(-4, 0, -1);
  return p;
}

TEST(Polynomial, TextForms) {
  EXPECT_EQ(trefoil().str("a", "z"), "a^-2 z^2 + 2 a^-2 - a^-4");  // as Regina prints it
  Laurent1 j;
  j.add(4, -1);
  j.add(3, 1);
  j.add(1, 1);
  EXPECT_EQ(j.str("t"), "-t^4 + t^3 + t");
  EXPECT_EQ(Laurent1{}.str("t"), "0");
}

TEST(Polynomial, AlexanderOfTheTrefoilFromHomfly) {
  Laurent1 a = alexander_from_homfly(trefoil()), in_t;
  ASSERT_TRUE(halve_exponents(a, in_t));
  EXPECT_EQ(in_t.str("t"), "t - 1 + t^-1");
  EXPECT_EQ(abs_at_t_minus_one(a), 3);  // the trefoil's determinant
}

TEST(Polynomial, FingerprintIsMultiplicative) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> e(-6, 6), c(-9, 9);
  for (int trial = 0; trial < 50; ++trial) {
    Laurent2 p, q;
    for (int k = 0; k < 6; ++k) {
      p.add(e(rng), e(rng), c(rng));
      q.add(e(rng), e(rng), c(rng));
    }
    EXPECT_EQ(homfly_fingerprint(p * q), modp::mul(homfly_fingerprint(p), homfly_fingerprint(q)));
  }
  EXPECT_EQ(homfly_fingerprint(Laurent2{{{{0, 0}, 1}}}), 1u);
  EXPECT_NE(homfly_fingerprint(trefoil()), homfly_fingerprint(trefoil().mirror_alpha()));
}

TEST(Polynomial, ModularInverse) {
  for (std::uint64_t a :
       {std::uint64_t{2}, std::uint64_t{12345}, modp::kP - 1, std::uint64_t{0x1234567890abc}})
    EXPECT_EQ(modp::mul(a, modp::inv(a)), 1u);
}

}  // namespace
}  // namespace s4d
