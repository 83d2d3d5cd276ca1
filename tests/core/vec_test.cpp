#include "core/vec.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace s4d {
namespace {

// The whole-array test agrees with testing every coordinate, wherever the bad value sits, and an
// empty array or large finite values (whose products and sums could overflow) count as finite.
TEST(Vec, AllFiniteOverPointsMatchesThePointwiseTest) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  EXPECT_TRUE(all_finite<4>(std::vector<Vec4>{}));
  std::vector<Vec4> x(9, Vec4(1, -2, 3, std::numeric_limits<double>::max()));
  EXPECT_TRUE(all_finite<4>(x));
  for (const double b : bad)
    for (std::size_t i = 0; i < x.size(); ++i)
      for (int k = 0; k < 4; ++k) {
        std::vector<Vec4> y = x;
        y[i][k] = b;
        EXPECT_FALSE(all_finite<4>(y)) << "point " << i << " coordinate " << k;
      }
  std::vector<Vec2> z(3, Vec2(-0.0, 1e-310));
  EXPECT_TRUE(all_finite<2>(z));
}

}  // namespace
}  // namespace s4d
