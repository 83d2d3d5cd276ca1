// Crossings of a knot's 2D shadow: the trefoil's three alternating crossings, agreement with an
// all-pairs brute force, and the depth of both strands.
#include "proximity/shadow_crossings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace s4d {
namespace {

constexpr double kPi = 3.14159265358979323846;

Curve<3> trefoil(int n) {
  Curve<3> c;
  Polyline<3> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    p.points.push_back(Vec3(std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t),
                            -std::sin(3 * t)));
  }
  c.components.push_back(p);
  return c;
}

TEST(ShadowCrossings, TrefoilHasThreeAlternatingCrossings) {
  const Curve<3> k = trefoil(300);
  const auto r = shadow_crossings(k, Frame<3>());
  ASSERT_EQ(r.crossings.size(), 3u);
  EXPECT_EQ(r.non_generic, 0);
  // Walk along the knot: each crossing is met twice, alternately over and under.
  std::vector<std::pair<double, bool>> events;  // (position along the curve, over?)
  for (const auto& x : r.crossings) {
    events.push_back({x.a.segment + x.ta, x.a_over()});
    events.push_back({x.b.segment + x.tb, !x.a_over()});
    // The crossing point lies on both shadows, and the depths are those of the strands.
    const auto& pts = k.components[0].points;
    const int n = static_cast<int>(pts.size());
    const Vec3 pa = pts[x.a.segment] + x.ta * (pts[(x.a.segment + 1) % n] - pts[x.a.segment]);
    const Vec3 pb = pts[x.b.segment] + x.tb * (pts[(x.b.segment + 1) % n] - pts[x.b.segment]);
    EXPECT_NEAR((pa.head<2>() - x.point).norm(), 0.0, 1e-12);
    EXPECT_NEAR((pb.head<2>() - x.point).norm(), 0.0, 1e-12);
    EXPECT_NEAR(pa.z(), x.depth_a, 1e-12);
    EXPECT_NEAR(pb.z(), x.depth_b, 1e-12);
    EXPECT_GT(std::abs(x.depth_a - x.depth_b), 0.1);
  }
  std::sort(events.begin(), events.end());
  for (std::size_t i = 0; i < events.size(); ++i)
    EXPECT_NE(events[i].second, events[(i + 1) % events.size()].second);
}

TEST(ShadowCrossings, MatchesAllPairsBruteForceUnderRandomFrames) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> ang(-kPi, kPi);
  const Curve<3> k = trefoil(120);
  for (int trial = 0; trial < 10; ++trial) {
    Frame<3> f;
    f.rotate({0, 2}, ang(rng));
    f.rotate({1, 2}, ang(rng));
    const auto r = shadow_crossings(k, f);
    const auto& pts = k.components[0].points;
    const int n = static_cast<int>(pts.size());
    int want = 0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;  // adjacent through the closing segment
        const Vec2 p0 = f.shadow(pts[i]), p1 = f.shadow(pts[(i + 1) % n]);
        const Vec2 q0 = f.shadow(pts[j]), q1 = f.shadow(pts[(j + 1) % n]);
        auto orient = [](const Vec2& a, const Vec2& b, const Vec2& c) {
          return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
        };
        if (orient(p0, p1, q0) * orient(p0, p1, q1) < 0 && orient(q0, q1, p0) * orient(q0, q1, p1) < 0)
          ++want;
      }
    EXPECT_EQ(static_cast<int>(r.crossings.size()), want) << "trial " << trial;
    EXPECT_GE(want, 3);  // a trefoil diagram has at least 3 crossings
  }
}

TEST(ShadowCrossings, LinkComponentsAndOpenCurves) {
  // Two round circles linked once: the Hopf link's diagram has two crossings between components.
  Curve<3> hopf;
  for (int c = 0; c < 2; ++c) {
    Polyline<3> p;
    for (int i = 0; i < 64; ++i) {
      const double t = 2 * kPi * i / 64;
      p.points.push_back(c == 0 ? Vec3(std::cos(t), std::sin(t), 0)
                                : Vec3(1 + std::cos(t), 0.1, std::sin(t)));
    }
    hopf.components.push_back(p);
  }
  const auto r = shadow_crossings(hopf, Frame<3>());
  // Seen from +z the second circle is a flat segment-like ellipse (y = 0.1) crossing the first
  // circle's shadow twice.
  Frame<3> tilted;
  tilted.rotate({1, 2}, 0.4);
  const auto rt = shadow_crossings(hopf, tilted);
  ASSERT_EQ(rt.crossings.size(), 2u);
  for (const auto& x : rt.crossings) {
    EXPECT_EQ(x.a.component, 0);
    EXPECT_EQ(x.b.component, 1);
  }
  EXPECT_NE(rt.crossings[0].a_over(), rt.crossings[1].a_over());  // linked: one over, one under
  (void)r;
  // An open polyline crossing itself once (a loop).
  Curve<3> loop;
  loop.components.push_back({{Vec3(0, 0, 0), Vec3(2, 2, 1), Vec3(2, 0, 0), Vec3(0, 2, -1)}, false});
  const auto rl = shadow_crossings(loop, Frame<3>());
  ASSERT_EQ(rl.crossings.size(), 1u);
  EXPECT_NEAR((rl.crossings[0].point - Vec2(1, 1)).norm(), 0.0, 1e-15);
  EXPECT_TRUE(rl.crossings[0].a_over());  // z = 0.5 on the first segment, -0.5 on the last
}

TEST(ShadowCrossings, NonGenericProjectionsAreCounted) {
  // A segment seen end-on, and a vertex lying exactly on another segment's shadow.
  Curve<3> c;
  c.components.push_back({{Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 1, 0), Vec3(1, -1, 0)}, true});
  const auto r = shadow_crossings(c, Frame<3>());
  EXPECT_GT(r.non_generic, 0);
  // NaN points are skipped, never a crash.
  Curve<3> bad = trefoil(30);
  bad.components[0].points[3].x() = std::nan("");
  const auto rb = shadow_crossings(bad, Frame<3>());
  EXPECT_GT(rb.non_generic, 0);
}

TEST(ShadowCrossings, FourDimensionalCurvesUseATolerance) {
  // In R^4 the shadow is 3D; two strands whose shadows pass within the tolerance count.
  Curve<4> c;
  c.components.push_back({{Vec4(-1, 0, 0, 0.3), Vec4(1, 0, 0, 0.3)}, false});
  c.components.push_back({{Vec4(0, -1, 1e-4, -0.2), Vec4(0, 1, 1e-4, -0.2)}, false});
  EXPECT_TRUE(shadow_crossings(c, Frame<4>()).crossings.empty());
  ShadowCrossingOptions o;
  o.tolerance = 1e-3;
  const auto r = shadow_crossings(c, Frame<4>(), o);
  ASSERT_EQ(r.crossings.size(), 1u);
  EXPECT_NEAR(r.crossings[0].depth_a, 0.3, 1e-15);
  EXPECT_NEAR(r.crossings[0].depth_b, -0.2, 1e-15);
  EXPECT_TRUE(r.crossings[0].a_over());
}

}  // namespace
}  // namespace s4d
