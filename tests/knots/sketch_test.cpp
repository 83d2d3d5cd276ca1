// Sketching a knot: a stroke along the trefoil's shadow becomes the unknot when drawn without the
// modifier (each new strand lies over the old, like rope laid on a table) and the trefoil when the
// modifier is held where the trefoil passes under; bad strokes get clear errors.
#include "knots/sketch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "knots/knot_diagram.hpp"
#include "knots/knot_identify.hpp"

namespace s4d {
namespace {

// The trefoil's shadow (sin t + 2 sin 2t, cos t - 2 cos 2t) drawn in 2 s at 120 Hz, stopping 1%
// (about 0.3) short of its start; its height is -sin 3t. With `choose`, the modifier is held where the
// height is below zero; `jitter` shakes the hand by that fraction of the drawing's size.
std::vector<SketchSample> trefoil_stroke(bool choose, double jitter = 0) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> shake(-jitter * 6, jitter * 6);
  std::vector<SketchSample> s;
  const int n = 240;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * 0.99 * i / (n - 1);
    SketchSample p;
    p.at = Vec2(std::sin(t) + 2 * std::sin(2 * t) + shake(rng), std::cos(t) - 2 * std::cos(2 * t) + shake(rng));
    p.time = i / 120.0;
    p.under = choose && -std::sin(3 * t) < 0;
    s.push_back(p);
  }
  return s;
}

TEST(Sketch, AStrokeWithoutChoicesLiesOverItselfAndIsTheUnknot) {
  const SketchedKnot k = knot_from_sketch(trefoil_stroke(false));
  EXPECT_EQ(k.crossings, 3);
  ASSERT_EQ(k.curve.components.size(), 1u);
  EXPECT_TRUE(k.curve.components[0].closed);
  EXPECT_EQ(diagram_from_curve(k.curve, Frame<3>()).crossing_count(), 3);
  EXPECT_EQ(identify_knot(k.curve).kind, KnotKind::kUnknot);
}

TEST(Sketch, HoldingTheModifierWhereItPassesUnderMakesTheTrefoil) {
  const SketchedKnot k = knot_from_sketch(trefoil_stroke(true));
  EXPECT_EQ(k.crossings, 3);
  const KnotIdentification id = identify_knot(k.curve);
  EXPECT_EQ(id.name, "3_1 (DT 3a_1)");
  EXPECT_TRUE(id.proven);
  // An alternating diagram: over and under take turns along the curve.
  const KnotDiagram d = diagram_from_curve(k.curve, Frame<3>());
  const auto& visits = d.components[0];
  for (std::size_t v = 0; v < visits.size(); ++v)
    EXPECT_NE(d.passages[visits[v]].over, d.passages[visits[(v + 1) % visits.size()]].over);
}

TEST(Sketch, ASmoothedShakyHandDrawsTheSameKnot) {
  const SketchedKnot k = knot_from_sketch(trefoil_stroke(true, 0.01));
  EXPECT_EQ(k.crossings, 3);
  EXPECT_EQ(identify_knot(k.curve).name, "3_1 (DT 3a_1)");
}

TEST(Sketch, DepthStaysNearThePlaneAndTheShadowNearTheStroke) {
  const auto stroke = trefoil_stroke(true);
  const SketchedKnot k = knot_from_sketch(stroke);
  for (const Vec3& p : k.curve.components[0].points) {
    // Size of the drawing is about 6: depth within a few clearances of the plane.
    EXPECT_LT(std::abs(p.z()), 0.2 * 6);
    double best = std::numeric_limits<double>::infinity();
    for (const SketchSample& s : stroke) best = std::min(best, (s.at - p.head<2>()).norm());
    EXPECT_LT(best, 0.3) << "the pen follows the hand; the closing stretch is about 0.3 long";
  }
}

// A stroke written as the window saves it and read back as `knot sketch --knot` reads it makes
// the same knot: samples and choices are kept, and evenly spaced times change only the smoothing.
TEST(Sketch, AStrokeSavedAndReadBackMakesTheSameKnot) {
  auto stroke = trefoil_stroke(true);
  for (std::size_t i = 0; i < stroke.size(); ++i) stroke[i].time = 0.004 * i + 0.001 * (i % 3);  // uneven, never back
  const Curve<3> file = stroke_as_curve(stroke);
  ASSERT_EQ(file.components.size(), 1u);
  EXPECT_FALSE(file.components[0].closed);
  const auto back = stroke_from_curve(file, 1.0 / 120.0);
  ASSERT_EQ(back.size(), stroke.size());
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].at, stroke[i].at);
    EXPECT_EQ(back[i].under, stroke[i].under);
    EXPECT_DOUBLE_EQ(back[i].time, i / 120.0);
  }
  const SketchedKnot a = knot_from_sketch(stroke), b = knot_from_sketch(back);
  EXPECT_EQ(a.crossings, b.crossings);
  EXPECT_EQ(diagram_from_curve(a.curve, Frame<3>()).gauss_code(), diagram_from_curve(b.curve, Frame<3>()).gauss_code());
  EXPECT_THROW(stroke_from_curve(Curve<3>{}, 0.01), Error);
}

TEST(Sketch, BadStrokesAreRefused) {
  auto s = trefoil_stroke(false);
  EXPECT_THROW(knot_from_sketch(std::span(s).first(2)), Error);
  auto nan = s;
  nan[10].at.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(knot_from_sketch(nan), Error);
  auto back = s;
  back[10].time = -1;
  EXPECT_THROW(knot_from_sketch(back), Error);
  std::vector<SketchSample> still(50);
  for (int i = 0; i < 50; ++i) still[i].time = i / 120.0;
  EXPECT_THROW(knot_from_sketch(still), Error);
}

}  // namespace
}  // namespace s4d
