// The live checks' smallest gap: the same as the brute force over every pair within the search,
// on a crumpled cloth whose mesh is much finer than the search (where listing every pair within
// it once took gigabytes).
#include "interact/session/session_monitor.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <thread>

#include "physics/test_worlds.hpp"
#include "proximity/closest_points.hpp"

namespace s4d {
namespace {

MonitorResult checked(SessionMonitor& m, const std::vector<double>& points) {
  m.submit(points, 0.5);
  for (int i = 0; i < 2000 && !m.latest().valid; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return m.latest();
}

TEST(SessionMonitor, TheSmallestGapIsTheBruteForceOneWithinTheSearch) {
  const Surface<4> cloth = test::flat_cloth<4>(24, 1.0);  // 0.043 between rows
  std::mt19937 rng(5);
  std::normal_distribution<double> bump(0, 0.004);
  std::vector<Vec4> x = cloth.vertices;
  for (Vec4& v : x) v[3] += bump(rng);
  std::vector<double> points;
  for (const Vec4& v : x)
    for (int k = 0; k < 4; ++k) points.push_back(v[k]);
  for (const double search : {0.4, 0.03, 0.001}) {
    double want = std::numeric_limits<double>::infinity();
    for (const Triangle& a : cloth.triangles)
      for (const Triangle& b : cloth.triangles) {
        bool shared = false;
        for (int u : a)
          for (int v : b) shared = shared || u == v;
        if (shared) continue;
        const double d = triangle_triangle<4>({x[a[0]], x[a[1]], x[a[2]]}, {x[b[0]], x[b[1]], x[b[2]]}).distance;
        if (d <= search) want = std::min(want, d);
      }
    SessionMonitor m(cloth.triangles, {}, 4, search, nullptr, {0}, {static_cast<int>(x.size())}, x);
    const MonitorResult r = checked(m, points);
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(r.true_intersections, 0);
    if (std::isinf(want)) {
      EXPECT_TRUE(std::isinf(r.min_gap)) << "search " << search;
    } else {
      EXPECT_NEAR(r.min_gap, want, 1e-12) << "search " << search;  // another kernel, to rounding
    }
  }
}

}  // namespace
}  // namespace s4d
