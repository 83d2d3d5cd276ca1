// The doubling search for a smallest distance: the same answer as one query at the whole radius,
// asking only radii up to twice the answer.
#include "proximity/smallest_within.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace s4d {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A query over fixed pair distances, as pairs_within would answer it, recording each radius.
struct Query {
  explicit Query(std::vector<double> d) : distances(std::move(d)) {}
  std::vector<double> distances;
  std::vector<double> asked;
  double operator()(double r) {
    asked.push_back(r);
    double d = kInf;
    for (double x : distances)
      if (x <= r) d = std::min(d, x);
    return d;
  }
};

TEST(SmallestWithin, EqualsOneQueryAtTheWholeRadiusAndAsksNoFartherThanTwiceTheAnswer) {
  for (const double up_to : {1.0, 0.02, 3e5}) {
    for (const double fraction : {0.0, 1e-6, 0.01, 1.0 / 64, 0.02, 0.3, 0.5, 0.99, 1.0, 1.5}) {
      Query q({fraction * up_to, 1.7 * up_to, 0.9 * up_to + fraction * up_to});
      Query whole = q;
      const double want = whole(up_to);
      const double got = smallest_within(up_to, q);
      EXPECT_EQ(got, want <= up_to ? want : kInf) << up_to << " " << fraction;
      ASSERT_FALSE(q.asked.empty());
      EXPECT_DOUBLE_EQ(q.asked.front(), up_to / 64);
      EXPECT_LE(q.asked.back(), up_to);
      if (got < kInf) {
        EXPECT_LE(q.asked.back(), std::max(2 * got, up_to / 64)) << up_to << " " << fraction;
      }
      EXPECT_TRUE(std::is_sorted(q.asked.begin(), q.asked.end()));
    }
  }
}

TEST(SmallestWithin, NothingWithinTheRadiusAsksUpToItAndGivesInfinity) {
  Query q({2.0, 5.0});
  EXPECT_EQ(smallest_within(1.0, q), kInf);
  EXPECT_DOUBLE_EQ(q.asked.back(), 1.0);
  EXPECT_EQ(q.asked.size(), 7u);  // 1/64, 1/32, ..., 1/2, 1
}

TEST(SmallestWithin, ABadRadiusAsksNothing) {
  for (const double bad : {-1.0, std::numeric_limits<double>::quiet_NaN()}) {
    Query q({0.0});
    EXPECT_EQ(smallest_within(bad, q), kInf);
    EXPECT_TRUE(q.asked.empty());
  }
}

}  // namespace
}  // namespace s4d
