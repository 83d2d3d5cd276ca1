// Torus knots and links, the figure-eight knot: on their surfaces, embedded, right diagrams.
#include "shape/knot_curves.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "shape/mesh_checks.hpp"

namespace s4d {
namespace {

int writhe(const std::vector<test::Crossing>& xs) {
  int w = 0;
  for (const auto& x : xs) w += x.sign;
  return w;
}

TEST(TorusKnot, PointsLieOnTheTorus) {
  const double R = 2.5, r = 0.7;
  const Curve<3> c = torus_knot(3, 5, 300, R, r);
  ASSERT_EQ(c.components.size(), 1u);
  EXPECT_EQ(c.point_count(), 300u);
  EXPECT_TRUE(c.all_closed());
  for (const Vec3& p : c.components[0].points) {
    const double ring = std::hypot(p.x(), p.y()) - R;
    EXPECT_NEAR(ring * ring + p.z() * p.z(), r * r, 1e-12);
  }
}

TEST(TorusKnot, TrefoilDiagramHasThreeCrossingsAndMirrorFlipsWrithe) {
  // Seen along the axis, T(p, q) has q(p - 1) crossings, all of the same sign.
  const auto x = test::diagram_crossings(torus_knot(2, 3, 200));
  const auto xm = test::diagram_crossings(torus_knot(2, -3, 200));
  ASSERT_EQ(x.size(), 3u);
  ASSERT_EQ(xm.size(), 3u);
  EXPECT_EQ(std::abs(writhe(x)), 3);
  EXPECT_EQ(writhe(xm), -writhe(x));
  EXPECT_EQ(test::diagram_crossings(torus_knot(3, 4, 400)).size(), 8u);
  EXPECT_EQ(test::diagram_crossings(torus_knot(2, 5, 400)).size(), 5u);
}

// Clearance between parts of a curve more than a tenth of its points apart: distinct strands.
double strand_clearance(const Curve<3>& c) {
  return test::curve_clearance(c, static_cast<int>(c.components[0].points.size() / 10));
}

TEST(TorusKnot, EmbeddedWithClearance) {
  // On the torus R = 2, r = 1 the three strands of T(2,3) pass each other about r apart.
  EXPECT_GT(strand_clearance(torus_knot(2, 3, 200)), 0.8);
  EXPECT_GT(strand_clearance(torus_knot(3, 7, 400)), 0.2);
}

TEST(TorusKnot, NonCoprimeGivesALinkWithTheRightLinkingNumber) {
  // T(2, 4): two unknotted components, each T(1, 2), linked twice.
  const Curve<3> c = torus_knot(2, 4, 160);
  ASSERT_EQ(c.components.size(), 2u);
  EXPECT_GT(strand_clearance(c), 0.8);
  int self = 0, lk2 = 0;
  for (const auto& x : test::diagram_crossings(c)) {
    if (x.comp_over == x.comp_under) ++self;
    else lk2 += x.sign;
  }
  EXPECT_EQ(self, 0);
  EXPECT_EQ(std::abs(lk2) / 2, 2);  // linking number = half the signed inter-component crossings
  EXPECT_EQ(torus_knot(6, 9, 100).components.size(), 3u);
}

TEST(TorusKnot, RejectsBadArguments) {
  EXPECT_THROW(torus_knot(0, 3, 100), Error);
  EXPECT_THROW(torus_knot(2, 3, 2), Error);
  EXPECT_THROW(torus_knot(2, 3, 100, 1.0, 1.0), Error);  // r = R: the torus pinches
}

TEST(FigureEight, ClosedEmbeddedAlternatingFourCrossingsWritheZero) {
  const Curve<3> c = figure_eight_knot(400);
  ASSERT_EQ(c.components.size(), 1u);
  EXPECT_TRUE(c.all_closed());
  EXPECT_GT(strand_clearance(c), 0.4);
  const auto x = test::diagram_crossings(c);
  // The minimal diagram of 4_1: four crossings and writhe 0 (the knot is amphichiral).
  EXPECT_EQ(x.size(), 4u);
  EXPECT_EQ(writhe(x), 0);
  EXPECT_THROW(figure_eight_knot(4), Error);
}

}  // namespace
}  // namespace s4d
