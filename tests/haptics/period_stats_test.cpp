// Period statistics against a sorted brute-force reference.
#include "haptics/period_stats.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace s4d {
namespace {

TEST(PeriodStats, PercentilesMatchSortedSamplesToOneMicrosecond) {
  PeriodStats stats(1000);
  std::vector<double> v;
  std::uint64_t s = 7;
  for (int i = 0; i < 50000; ++i) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    const double u = static_cast<double>(s >> 11) / 9007199254740992.0;
    // Mostly ~1 ms with a heavy tail, as a loaded machine produces.
    const double us = 990 + 20 * u + (u > 0.995 ? 3000 * u : 0);
    v.push_back(us);
    stats.add_period(us);
  }
  std::sort(v.begin(), v.end());
  auto ref = [&](double q) { return v[static_cast<std::size_t>(std::ceil(q * v.size())) - 1]; };
  const PeriodSummary sum = stats.summary();
  EXPECT_EQ(sum.ticks, 50000u);
  EXPECT_NEAR(sum.p50_us, ref(0.5), 1.0);
  EXPECT_NEAR(sum.p99_us, ref(0.99), 1.0);
  EXPECT_NEAR(sum.p999_us, ref(0.999), 1.0);
  EXPECT_DOUBLE_EQ(sum.max_us, v.back());
  const std::uint64_t over = std::count_if(v.begin(), v.end(), [](double x) { return x > 2000; });
  EXPECT_EQ(sum.over_2ms, over);
  EXPECT_GT(over, 0u);
}

TEST(PeriodStats, RecentKeepsTheLatestInOrderAndResetClears) {
  PeriodStats stats(1000);
  for (int i = 0; i < 300; ++i) stats.add_period(i);
  std::array<float, PeriodStats::kRecent> r{};
  ASSERT_EQ(stats.recent(r), PeriodStats::kRecent);
  EXPECT_EQ(r.front(), 300 - PeriodStats::kRecent);
  EXPECT_EQ(r.back(), 299);
  stats.add_missed();
  EXPECT_EQ(stats.summary().missed, 1u);
  stats.reset();
  EXPECT_EQ(stats.summary().ticks, 0u);
  EXPECT_EQ(stats.summary().missed, 0u);
  EXPECT_EQ(stats.recent(r), 0);
}

TEST(PeriodStats, HugeAndBadValuesAreContained) {
  PeriodStats stats(1000);
  stats.add_period(1e9);  // a 1000 s stall (suspend): lands in the last bin, max is exact
  stats.add_period(std::nan(""));
  stats.add_period(-5);
  const PeriodSummary s = stats.summary();
  EXPECT_EQ(s.ticks, 3u);
  EXPECT_EQ(s.max_us, 1e9);
  EXPECT_EQ(s.over_2ms, 1u);
}

}  // namespace
}  // namespace s4d
