// Strokes to a link: the later strand's choice at each crossing, against the scene's fixed
// strands too, and bad strokes refused with the reason.
#include "knots/sketch_link.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "knots/knot_diagram.hpp"

namespace s4d {
namespace {

StrokeComponent circle(const Vec2& c, double r, CrossChoice choice, int n = 80) {
  StrokeComponent s;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    s.points.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
    s.choices.push_back(choice);
  }
  s.closed = true;
  return s;
}

// The depth of the stroke's curve where its shadow is nearest `p`.
double depth_near(const Curve<3>& c, const Vec2& p) {
  double best = 1e300, z = 0;
  for (const Vec3& q : c.components[0].points)
    if ((q.head<2>() - p).norm() < best) {
      best = (q.head<2>() - p).norm();
      z = q.z();
    }
  return z;
}

TEST(LinkFromStrokes, AStrokePassesAFixedStrandAsChosen) {
  FixedStrand line;
  line.points = {Vec2(0, -2), Vec2(0, 2)};
  line.depth = {0.3, 0.3};
  line.closed = false;
  for (const CrossChoice c : {CrossChoice::kOver, CrossChoice::kUnder}) {
    const StrokeComponent s = circle(Vec2(0.5, 0), 1, c);
    const StrokeLink l = link_from_strokes(std::vector{s}, {}, std::vector{line});
    EXPECT_EQ(l.fixed_crossings, 2);
    EXPECT_EQ(l.crossings, 0);
    for (const double y : {-std::sqrt(0.75), std::sqrt(0.75)}) {
      const double z = depth_near(l.curve, Vec2(0, y));
      if (c == CrossChoice::kOver) EXPECT_GT(z, 0.3) << y;
      else EXPECT_LT(z, 0.3) << y;
    }
  }
}

TEST(LinkFromStrokes, TheProbesCrossingDecidesBeforeThePointsChoice) {
  const StrokeComponent a = circle(Vec2(-0.5, 0), 1, CrossChoice::kNone);
  const StrokeComponent b = circle(Vec2(0.5, 0), 1, CrossChoice::kOver);
  // The probe crossed under at the upper crossing; the lower one takes the point's choice (over).
  const std::vector<StrokeCrossing> crossed{{Vec2(0, std::sqrt(0.75)), CrossChoice::kUnder}};
  const StrokeLink l = link_from_strokes(std::vector{a, b}, crossed, {});
  ASSERT_EQ(l.crossings, 2);
  EXPECT_EQ(std::abs(diagram_from_curve(l.curve, Frame<3>()).linking_numbers()[0][1]), 1);
}

TEST(LinkFromStrokes, BadStrokesAreRefused) {
  EXPECT_THROW(link_from_strokes({}, {}, {}), Error);
  StrokeComponent s = circle(Vec2(0, 0), 1, CrossChoice::kNone);
  s.points[3].x() = std::nan("");
  EXPECT_THROW(link_from_strokes(std::vector{s}, {}, {}), Error);
  StrokeComponent two;
  two.points = {Vec2(0, 0), Vec2(1, 0)};
  two.choices = {CrossChoice::kNone, CrossChoice::kNone};
  EXPECT_THROW(link_from_strokes(std::vector{two}, {}, {}), Error);
  StrokeComponent still = circle(Vec2(0, 0), 0, CrossChoice::kNone);
  EXPECT_THROW(link_from_strokes(std::vector{still}, {}, {}), Error);
}

}  // namespace
}  // namespace s4d
