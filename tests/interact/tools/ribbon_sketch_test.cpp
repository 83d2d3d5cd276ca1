// Sketching a ribbon in the 3D shadow: passages where the stroke crosses a sphere's shadow, w
// above or below it by the clearance, the shadow kept on the stroke, an embedded result checked
// independently, choices the smoothing never changes, the ribbon passing itself, bad strokes
// refused, stroke files; and the paper's Fig. 14 as physics: threaded above then below, the
// ribbon lifts the sphere; above twice, the sphere falls away.
#include "interact/tools/ribbon_sketch.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "physics/model.hpp"
#include "physics/world.hpp"
#include "shape/surfaces_4d.hpp"

namespace s4d {
namespace {

constexpr double kRadius = 0.5;  // the sphere's

// A stroke at 120 Hz through the points of `at(t)`, t in [0, 1] over `seconds`; the modifier held
// where `below(t)`.
template <class At, class Below>
std::vector<RibbonStrokeSample> stroke_of(At at, Below below, double seconds = 2.0) {
  std::vector<RibbonStrokeSample> s;
  const int n = static_cast<int>(seconds * 120);
  for (int i = 0; i <= n; ++i) {
    const double t = double(i) / n;
    s.push_back({at(t), t * seconds, below(t)});
  }
  return s;
}

// Straight along x at height y0 in the plane z = 0 (facing the eye on +z), from x = -1.5 to 1.5;
// the modifier held over x > 0 when `then_below`.
std::vector<RibbonStrokeSample> straight_stroke(double y0, bool then_below) {
  return stroke_of([&](double t) { return Vec3(-1.5 + 3 * t, y0, 0); },
                   [&](double t) { return then_below && t > 0.5; });
}

// Distance in R^4 from p to the round 2-sphere of radius r about c in the hyperplane w = c.w.
double sphere_distance(const Vec4& p, const Vec4& c, double r) {
  const Vec4 d = p - c;
  return std::hypot(d.head<3>().norm() - r, d[3]);
}

// Smallest distance from the ribbon to the sphere, sampling every triangle on a barycentric grid:
// shares nothing with the engine's finders.
double sampled_distance(const Surface<4>& s, const Vec4& c, double r) {
  double best = std::numeric_limits<double>::infinity();
  constexpr int k = 8;
  for (const Triangle& t : s.triangles)
    for (int i = 0; i <= k; ++i)
      for (int j = 0; i + j <= k; ++j) {
        const double a = double(i) / k, b = double(j) / k;
        const Vec4 p = (1 - a - b) * s.vertices[t[0]] + a * s.vertices[t[1]] + b * s.vertices[t[2]];
        best = std::min(best, sphere_distance(p, c, r));
      }
  return best;
}

// The centre of each row in the shadow of `frame`.
std::vector<Vec3> row_centres(const SketchedRibbon& r, const Frame<4>& frame) {
  const Grid& g = *r.surface.grid;
  std::vector<Vec3> out;
  for (int i = 0; i < g.rows; ++i) {
    Vec4 c = Vec4::Zero();
    for (int j = 0; j < g.cols; ++j) c += r.surface.vertices[g.index(i, j)];
    out.push_back(frame.shadow(c / g.cols));
  }
  return out;
}

double distance_to_polyline(const Vec3& p, std::span<const RibbonStrokeSample> s) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    const Vec3 a = s[i].at, d = s[i + 1].at - a;
    const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * d - p).norm());
  }
  return best;
}

const Vec3 kEye = Vec3::UnitZ();

TEST(RibbonSketch, PassagesAreWhereTheStrokeCrossesTheSphere) {
  const Surface<4> sphere = uv_sphere<4>(32, kRadius, Vec4::Zero());
  RibbonSketchOptions o;
  o.width = 0.2;
  o.clearance = 0.1;
  const double y0 = 0.2;
  const SketchedRibbon r = ribbon_from_sketch(straight_stroke(y0, true), std::span(&sphere, 1), Frame<4>(), kEye, o);
  ASSERT_EQ(r.passages.size(), 2u);
  const double x = std::sqrt(kRadius * kRadius - y0 * y0);  // where the centre line meets the sphere
  const RibbonPassage& in = r.passages[0];
  const RibbonPassage& out = r.passages[1];
  EXPECT_EQ(in.surface, 0);
  EXPECT_EQ(out.surface, 0);
  // The mesh's chords lie within r (1 - cos(pi / 32)) = 0.0024 of the round sphere.
  EXPECT_LT((in.place - Vec3(-x, y0, 0)).norm(), 0.005);
  EXPECT_LT((out.place - Vec3(x, y0, 0)).norm(), 0.005);
  EXPECT_FALSE(in.below);
  EXPECT_TRUE(out.below);
  // The sphere's w is 0: above by the clearance at the first passage, below at the second,
  // on every row whose cross-section meets the sphere's shadow.
  EXPECT_NEAR(in.other_w, 0, 1e-12);
  EXPECT_GE(in.ribbon_w, o.clearance - 1e-9);
  EXPECT_LE(out.ribbon_w, -o.clearance + 1e-9);
  EXPECT_GE(in.gap, o.clearance - 1e-9);
  EXPECT_GE(out.gap, o.clearance - 1e-9);
  const double inner = std::sqrt(kRadius * kRadius - std::pow(y0 + o.width / 2, 2)) - 0.01;
  const double outer = std::sqrt(kRadius * kRadius - std::pow(y0 - o.width / 2, 2)) + 0.005;
  int rows_over = 0;
  for (std::size_t i = 0; i < r.centre.size(); ++i) {
    const double cx = r.centre[i].x();
    if (std::abs(cx) < inner || std::abs(cx) > outer) continue;
    ++rows_over;
    if (cx < 0) {
      EXPECT_GE(r.w[i], o.clearance - 1e-9) << "row " << i << " at x = " << cx;
    } else {
      EXPECT_LE(r.w[i], -o.clearance + 1e-9) << "row " << i << " at x = " << cx;
    }
  }
  EXPECT_GE(rows_over, 4);
  // Above then below: the ribbon passes w = 0 inside the ball's shadow, between the passages.
  EXPECT_GT(r.w.front(), 0);
  EXPECT_LT(r.w.back(), 0);
}

TEST(RibbonSketch, AboveTwiceStaysAboveAllTheWayAcross) {
  const Surface<4> sphere = uv_sphere<4>(32, kRadius, Vec4::Zero());
  RibbonSketchOptions o;
  o.clearance = 0.1;
  const SketchedRibbon r = ribbon_from_sketch(straight_stroke(0.2, false), std::span(&sphere, 1), Frame<4>(), kEye, o);
  ASSERT_EQ(r.passages.size(), 2u);
  EXPECT_FALSE(r.passages[0].below);
  EXPECT_FALSE(r.passages[1].below);
  // Between the passages nothing holds w up but the smoothing: it stays above all the same, so
  // the ribbon never enters the sphere's hyperplane over its ball.
  for (std::size_t i = 0; i < r.centre.size(); ++i)
    if (std::abs(r.centre[i].x()) < kRadius) {
      EXPECT_GT(r.w[i], 0.5 * o.clearance) << "row " << i;
    }
}

TEST(RibbonSketch, TheShadowStaysOnTheStrokeAndTheResultIsEmbedded) {
  // A turned view: the sphere's shadow is an ellipsoid whose w varies across it.
  Frame<4> frame;
  frame.rotate(Plane{0, 3}, 0.5);
  frame.rotate(Plane{1, 2}, 0.3);
  const Vec4 c(0.1, -0.05, 0.0, 0.0);
  const Surface<4> sphere = uv_sphere<4>(24, kRadius, c);
  // A wave through the shadow, with the modifier held on its second half.
  const auto stroke = stroke_of(
      [](double t) { return Vec3(-1.4 + 2.8 * t, 0.25 * std::sin(2 * std::numbers::pi * t), 0.05 * t); },
      [](double t) { return t > 0.5; });
  RibbonSketchOptions o;
  o.width = 0.15;
  o.clearance = 0.08;
  const SketchedRibbon r = ribbon_from_sketch(stroke, std::span(&sphere, 1), frame, kEye, o);
  ASSERT_GE(r.passages.size(), 2u);
  const std::vector<Vec3> centres = row_centres(r, frame);
  ASSERT_EQ(centres.size(), r.centre.size());
  for (std::size_t i = 0; i < centres.size(); ++i) {
    EXPECT_LT((centres[i] - r.centre[i]).norm(), 1e-9) << "smoothing moved row " << i << " off its place";
    EXPECT_LT(distance_to_polyline(centres[i], stroke), 0.02) << "row " << i << " strays from the stroke";
  }
  // Each row keeps one w across it and the width lies across the stroke, facing the eye.
  const Grid& g = *r.surface.grid;
  for (int i = 0; i < g.rows; ++i) {
    const Vec4 a = frame.to_view(r.surface.vertices[g.index(i, 0)]), b = frame.to_view(r.surface.vertices[g.index(i, 1)]);
    EXPECT_NEAR(a[3], b[3], 1e-12);
    EXPECT_NEAR((a - b).norm(), o.width, 1e-9);
    EXPECT_NEAR((a - b).head<3>().dot(kEye), 0, 1e-9);
  }
  // Independent: the ribbon stays apart from the round sphere by more than half the clearance
  // (w gap 0.08 at every passage, less the mesh's chord error of 0.5 (1 - cos(pi / 24)) = 0.004).
  const double d = sampled_distance(r.surface, c, kRadius);
  EXPECT_GT(d, 0.5 * o.clearance);
  EXPECT_GT(r.gap_to_others, 0.5 * o.clearance);
  EXPECT_LT(r.gap_to_others, d + 0.01);
}

// Whatever the smoothing, every passage keeps the side it was given, by at least the clearance.
TEST(RibbonSketch, SmoothingNeverChangesAChoice) {
  const Surface<4> sphere = uv_sphere<4>(24, kRadius, Vec4::Zero());
  // A three-petalled flower about the sphere's outline that passes through it six times, the
  // modifier held on two stretches (over the passages at 90, 150 and 270 degrees).
  const auto stroke = stroke_of(
      [](double t) {
        const double a = 2 * std::numbers::pi * 0.95 * t, r = 0.5 + 0.15 * std::cos(3 * a);
        return Vec3(r * std::cos(a), r * std::sin(a), 0);
      },
      [](double t) {
        const double a = 2 * std::numbers::pi * 0.95 * t, pi = std::numbers::pi;
        return (a > pi / 3 && a < pi) || (a > 4 * pi / 3 && a < 5 * pi / 3);
      },
      4.0);
  for (const double smoothing : {0.05, 0.3, 3.0}) {
    RibbonSketchOptions o;
    o.width = 0.12;
    o.clearance = 0.06;
    o.smoothing = smoothing;
    const SketchedRibbon r = ribbon_from_sketch(stroke, std::span(&sphere, 1), Frame<4>(), kEye, o);
    ASSERT_EQ(r.passages.size(), 6u) << "smoothing " << smoothing;
    int above = 0, below = 0;
    for (const RibbonPassage& p : r.passages) {
      const double side = p.below ? -1 : 1;
      EXPECT_GE(side * (p.ribbon_w - p.other_w), o.clearance - 1e-9) << "smoothing " << smoothing;
      EXPECT_GE(p.gap, o.clearance - 1e-9);
      (p.below ? below : above)++;
    }
    EXPECT_EQ(below, 3);
    EXPECT_EQ(above, 3);
    EXPECT_GT(sampled_distance(r.surface, Vec4::Zero(), kRadius), 0.5 * o.clearance);
  }
}

// A loop that crosses itself: the later strand passes above, or below where the modifier is held.
TEST(RibbonSketch, TheRibbonPassesItselfByStrokeOrder) {
  // The nodal cubic x = s^2 - 1, y = 0.8 s (s^2 - 1): it crosses itself at the origin (s = -1, 1).
  auto alpha = [](double t) {
    const double s = -1.6 + 3.2 * t;
    return Vec3(s * s - 1, 0.8 * s * (s * s - 1), 0);
  };
  for (const bool hold : {false, true}) {
    RibbonSketchOptions o;
    o.width = 0.2;
    o.clearance = 0.1;
    const auto stroke = stroke_of(alpha, [&](double t) { return hold && t > 0.7; }, 3.0);
    const SketchedRibbon r = ribbon_from_sketch(stroke, {}, Frame<4>(), kEye, o);
    ASSERT_EQ(r.passages.size(), 1u);
    const RibbonPassage& p = r.passages[0];
    EXPECT_EQ(p.surface, -1);
    EXPECT_EQ(p.below, hold);
    EXPECT_LT(p.place.norm(), 0.03) << "read where the strands cross";
    EXPECT_GT(p.at_length, 0.6 * r.length) << "the later strand chooses";
    EXPECT_GE((hold ? -1 : 1) * (p.ribbon_w - p.other_w), o.clearance - 1e-9);
    EXPECT_GE(p.gap, o.clearance - 1e-9);
  }
}

// A loop through the sphere's shadow, above where it enters and below where it leaves: the chain's
// link (Fig. 8), sketched. Rows wrap round, and the passages are read on either side of the join.
TEST(RibbonSketch, AClosedLoopThroughTheSphere) {
  const Surface<4> sphere = uv_sphere<4>(24, kRadius, Vec4::Zero());
  // A circle of radius 0.7 about (0, 0.75), from its bottom (inside the sphere's shadow): out
  // through the sphere's outline at (0.45, 0.22), back in at (-0.45, 0.22), the modifier held on
  // the left half.
  const auto loop = stroke_of(
      [](double t) {
        const double a = 2 * std::numbers::pi * t - std::numbers::pi / 2;
        return Vec3(0.7 * std::cos(a), 0.75 + 0.7 * std::sin(a), 0);
      },
      [](double t) { return t > 0.5; }, 3.0);
  RibbonSketchOptions o;
  o.closed = true;
  o.width = 0.15;
  o.clearance = 0.08;
  const SketchedRibbon r = ribbon_from_sketch(loop, std::span(&sphere, 1), Frame<4>(), kEye, o);
  ASSERT_TRUE(r.surface.grid && r.surface.grid->wrap_i);
  ASSERT_EQ(r.passages.size(), 2u);
  EXPECT_GT(r.passages[0].place.x(), 0);  // met first on the right, where no modifier was held
  EXPECT_FALSE(r.passages[0].below);
  EXPECT_LT(r.passages[1].place.x(), 0);
  EXPECT_TRUE(r.passages[1].below);
  for (const RibbonPassage& p : r.passages) {
    EXPECT_NEAR(p.place.norm(), kRadius, 0.01);
    EXPECT_GE((p.below ? -1 : 1) * p.ribbon_w, o.clearance - 1e-9);
  }
  EXPECT_GT(sampled_distance(r.surface, Vec4::Zero(), kRadius), 0.5 * o.clearance);
}

// Drawn across a ribbon already drawn in the same view, the two lie in one plane of the shadow:
// their overlap is an area, not a curve, and the new ribbon takes a side of it all the same.
TEST(RibbonSketch, AcrossAFlatRibbonOfTheSameView) {
  RibbonSketchOptions o;
  o.width = 0.2;
  o.clearance = 0.05;
  const SketchedRibbon first = ribbon_from_sketch(
      stroke_of([](double t) { return Vec3(0, -1 + 2 * t, 0); }, [](double) { return false; }), {}, Frame<4>(), kEye, o);
  for (const bool hold : {false, true}) {
    const auto across = stroke_of([](double t) { return Vec3(-1 + 2 * t, 0.1, 0); }, [&](double) { return hold; });
    const SketchedRibbon second = ribbon_from_sketch(across, std::span(&first.surface, 1), Frame<4>(), kEye, o);
    ASSERT_EQ(second.passages.size(), 1u);
    EXPECT_EQ(second.passages[0].below, hold);
    EXPECT_LT(std::abs(second.passages[0].place.x()), 0.1);
    // Every row whose cross-section lies over the first ribbon's strip (|x| < 0.1) is on its side.
    for (std::size_t i = 0; i < second.centre.size(); ++i) {
      if (std::abs(second.centre[i].x()) > 0.1) continue;
      EXPECT_GE((hold ? -1 : 1) * second.w[i], o.clearance - 1e-9) << "row " << i;
    }
  }
}

// Two flat ribbons overlapping in the shadow, the second just below the first in w: passing above
// the first and below the second is impossible where they overlap, and is refused as such.
TEST(RibbonSketch, ChoicesThatCannotBothHoldAreRefused) {
  RibbonSketchOptions o;
  o.width = 0.2;
  o.clearance = 0.05;
  auto upright = [&](double x) {
    return ribbon_from_sketch(stroke_of([&](double t) { return Vec3(x, -1 + 2 * t, 0); }, [](double) { return false; }),
                              {}, Frame<4>(), kEye, o)
        .surface;
  };
  std::vector<Surface<4>> flats{upright(0), upright(0.15)};
  for (Vec4& p : flats[1].vertices) p[3] -= 0.02;
  const std::vector<std::string> names{"first", "second"};
  // The modifier held from x = 0.075 on, between the middles of the two overlaps.
  const auto across = stroke_of([](double t) { return Vec3(-1 + 2 * t, 0.1, 0); }, [](double t) { return t > 0.5375; });
  try {
    ribbon_from_sketch(across, flats, Frame<4>(), kEye, o, names);
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("above 'first'"), std::string::npos) << what;
    EXPECT_NE(what.find("below 'second'"), std::string::npos) << what;
    EXPECT_NE(what.find("cannot both hold"), std::string::npos) << what;
  }
  // Below both, as one choice over the whole overlap, is fine.
  const auto below = stroke_of([](double t) { return Vec3(-1 + 2 * t, 0.1, 0); }, [](double) { return true; });
  const SketchedRibbon r = ribbon_from_sketch(below, flats, Frame<4>(), kEye, o, names);
  ASSERT_EQ(r.passages.size(), 2u);
  EXPECT_TRUE(r.passages[0].below && r.passages[1].below);
}

TEST(RibbonSketch, ScenesGiveTheirSurfacesAsTheViewShowsThem) {
  Scene scene;
  scene.frame.rotate(Plane{0, 3}, 0.4);
  SceneObject flat;
  flat.name = "flat";
  Surface<3> tri;
  tri.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0.5)};
  tri.triangles = {{0, 1, 2}};
  flat.shape = tri;
  SceneObject sphere;
  sphere.name = "sphere";
  sphere.shape = uv_sphere<4>(8, kRadius, Vec4::Zero());
  SceneObject knot;
  knot.name = "knot";
  knot.shape = Curve<3>{};
  scene.objects = {flat, knot, sphere};
  const SketchObstacles o = sketch_obstacles(scene);
  ASSERT_EQ(o.surfaces.size(), 2u);
  EXPECT_EQ(o.names, (std::vector<std::string>{"flat", "sphere"}));
  EXPECT_EQ(o.curves, 1);
  for (int k = 0; k < 3; ++k) {
    const Vec4 q = scene.frame.to_view(o.surfaces[0].vertices[k]);
    EXPECT_LT((q.head<3>() - tri.vertices[k]).norm(), 1e-12);  // where it is drawn
    EXPECT_NEAR(q[3], 0, 1e-12);
  }
  EXPECT_EQ(o.surfaces[1].vertices, std::get<Surface<4>>(sphere.shape).vertices);
  SketchedRibbon r;
  r.surface = uv_sphere<4>(8, 1, Vec4::Zero());
  EXPECT_EQ(add_sketched_ribbon(scene, r), "ribbon");
  EXPECT_EQ(add_sketched_ribbon(scene, r), "ribbon 2");
  EXPECT_EQ(add_sketched_ribbon(scene, r, "sphere"), "sphere 2");
  EXPECT_EQ(scene.objects.size(), 6u);
}

TEST(RibbonSketch, WithoutOtherSurfacesTheRibbonIsFlat) {
  RibbonSketchOptions o;
  o.closed = true;
  const auto circle = stroke_of([](double t) { return Vec3(std::cos(2 * std::numbers::pi * t), std::sin(2 * std::numbers::pi * t), 0); },
                                [](double) { return false; });
  const SketchedRibbon r = ribbon_from_sketch(circle, {}, Frame<4>(), kEye, o);
  EXPECT_TRUE(r.passages.empty());
  ASSERT_TRUE(r.surface.grid);
  EXPECT_TRUE(r.surface.grid->wrap_i);
  for (double w : r.w) EXPECT_EQ(w, 0);
  EXPECT_NEAR(r.length, 2 * std::numbers::pi, 0.1);
}

TEST(RibbonSketch, BadStrokesAreRefusedWithASentence) {
  const Surface<4> sphere = uv_sphere<4>(16, kRadius, Vec4::Zero());
  const auto good = straight_stroke(0.2, false);
  auto refused = [&](std::span<const RibbonStrokeSample> s, const RibbonSketchOptions& o, const std::string& says) {
    try {
      ribbon_from_sketch(s, std::span(&sphere, 1), Frame<4>(), kEye, o);
      ADD_FAILURE() << "accepted; expected: " << says;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  refused({}, {}, "at least 2 cursor samples");
  refused(std::span(good).first(1), {}, "at least 2 cursor samples");
  auto nan = good;
  nan[7].at.y() = std::numeric_limits<double>::quiet_NaN();
  refused(nan, {}, "sample 7 is not finite");
  auto back = good;
  back[9].time = -1;
  refused(back, {}, "goes back in time");
  std::vector<RibbonStrokeSample> still(20);
  for (int i = 0; i < 20; ++i) still[i].time = i / 120.0;
  refused(still, {}, "no extent");
  RibbonSketchOptions o;
  for (const double w : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    o.width = w;
    refused(good, o, "width must be a positive number");
  }
  o.width = 50;
  refused(good, o, "wider than the whole stroke");
  o.width = 1e-9;
  refused(good, o, "too narrow");
  o = {};
  o.across = 1;
  refused(good, o, "2 to 64 vertices across");
  // 5000 rows, under the row limit, but 64 across them is 320 k vertices: minutes and gigabytes.
  o.across = 64;
  o.spacing = 3.0 / 5000;
  refused(good, o, "vertices, more than 200000: take fewer across or space the rows wider");
  // A hairpin tighter than the ribbon is wide folds it onto itself.
  const auto hairpin = stroke_of([](double t) {
    const double a = std::numbers::pi * std::clamp((t - 0.4) / 0.2, 0.0, 1.0);
    const double x = t < 0.4 ? -1 + 2.5 * t : t > 0.6 ? 1.5 - 2.5 * t : 0;
    return Vec3(x + 0.05 * std::sin(a), 0.05 - 0.05 * std::cos(a), 0);
  }, [](double) { return false; });
  o = {};
  o.width = 0.3;
  refused(hairpin, o, "folds onto itself");
  refused(stroke_of([](double t) { return Vec3(0, 0, t); }, [](double) { return false; }), {},
          "runs along the line of sight");
  EXPECT_THROW(ribbon_from_sketch(good, {}, Frame<4>(), Vec3::Zero(), {}), Error);
}

// [Fig. 14] A U-shaped ribbon sketched through a sphere's shadow, its ends held and lifted in a
// World<4> with gravity. Above then below threads it through the sphere's ball (its core crosses the
// sphere's hyperplane inside it): the sphere hangs in the U and rises with it. Above twice, the
// ribbon passes over the whole ball in w and never touches the sphere, which falls away.
struct LiftResult {
  double rise = 0;        // of the sphere's centre, from the moment the lift starts to the end
  double ends_rise = 0;   // of the held ends over the same time
  double min_gap = 0;     // between any two triangles at the end (the World's own measure)
  std::int64_t rollbacks = 0;
};

LiftResult lift(bool then_below) {
  // Turned in zw: the view's depth mixes world z and w, so the sphere's w varies over its shadow.
  Frame<4> frame;
  frame.rotate(Plane{2, 3}, 40 * std::numbers::pi / 180);
  const Surface<4> sphere = uv_sphere<4>(16, kRadius, Vec4::Zero());
  // y = 0.25 + 1.2 x^4, x from -1 to 1: the bottom runs through the upper half of the sphere's shadow.
  const auto stroke = stroke_of([](double t) { const double x = -1 + 2 * t; return Vec3(x, 0.25 + 1.2 * std::pow(x, 4), 0); },
                                [&](double t) { return then_below && t > 0.5; });
  RibbonSketchOptions o;
  o.width = 0.2;
  o.clearance = 0.1;
  o.spacing = 0.05;
  const SketchedRibbon r = ribbon_from_sketch(stroke, std::span(&sphere, 1), frame, kEye, o);
  EXPECT_EQ(r.passages.size(), 2u);
  for (std::size_t k = 0; k < r.passages.size(); ++k) EXPECT_EQ(r.passages[k].below, then_below && k == 1);

  // The ribbon-lifts-sphere scenario's material: slippery enough to slide, stiff enough to carry.
  PhysicsParams<4> p;
  p.time_step = 1e-3;    // s
  p.thickness = 0.03;    // m
  p.gravity = Vec4(0, -9.81, 0, 0);
  p.mass = 1e-3;         // kg per vertex
  p.stiffness = 300;     // N/m
  p.shear_scale = 0.5;
  p.bending_scale = 0.2;
  p.damping = 0.01;
  p.spring_damping = 0.02;
  p.friction = 0.3;
  ModelBuilder<4> builder(p);
  const int s0 = builder.add_body(sphere);
  const int r0 = builder.add_body(r.surface);
  World<4> world(builder.build());
  const Grid& g = *r.surface.grid;
  std::vector<int> ends;
  for (int j = 0; j < g.cols; ++j) {
    ends.push_back(r0 + g.index(0, j));
    ends.push_back(r0 + g.index(g.rows - 1, j));
  }
  std::vector<Vec4> start;
  for (int v : ends) {
    world.pin(v);
    start.push_back(world.positions()[v]);
  }
  auto centre = [&] {
    Vec4 c = Vec4::Zero();
    for (std::size_t v = 0; v < sphere.vertices.size(); ++v) c += world.positions()[s0 + v];
    return Vec4(c / static_cast<double>(sphere.vertices.size()));
  };
  // Held while the sphere settles (0.3 s), lifted by 1.5 over 1.5 s (smooth start and stop, as
  // scenario_run's "move"), then held 0.5 s.
  const double from = 0.3, to = 1.8, end = 2.3, by = 1.5;
  LiftResult out;
  double y0 = 0, ends0 = 0;
  const long steps = std::lround(end / p.time_step);
  for (long k = 1; k <= steps; ++k) {
    const double t = k * p.time_step;
    const double u = std::clamp((t - from) / (to - from), 0.0, 1.0), ramp = u * u * (3 - 2 * u);
    for (std::size_t i = 0; i < ends.size(); ++i) world.set_target(ends[i], start[i] + Vec4(0, by * ramp, 0, 0));
    world.step();
    if (k == std::lround(from / p.time_step)) {
      y0 = centre()[1];
      ends0 = world.positions()[ends[0]][1];
    }
  }
  out.rise = centre()[1] - y0;
  out.ends_rise = world.positions()[ends[0]][1] - ends0;
  out.min_gap = world.min_separation(1.0);
  out.rollbacks = world.data().warnings.rollbacks;
  return out;
}

TEST(RibbonSketch, ThreadedAboveThenBelowTheRibbonLiftsTheSphere) {
  const auto t0 = std::chrono::steady_clock::now();
  const LiftResult linked = lift(true);
  const LiftResult apart = lift(false);
  // Lifted by 1.5: caught, the sphere rises with the ribbon less the U's stretch (measured 1.29);
  // free, it falls at its terminal speed, about g m / damping = 1 m/s (measured -1.96).
  EXPECT_NEAR(linked.ends_rise, 1.5, 1e-9);
  EXPECT_GT(linked.rise, 1.0);
  EXPECT_LT(apart.rise, -1.0);
  EXPECT_GT(linked.min_gap, 0);
  EXPECT_GT(apart.min_gap, 0);
  EXPECT_EQ(linked.rollbacks, 0);
  EXPECT_EQ(apart.rollbacks, 0);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 20.0);
}

TEST(RibbonSketch, StrokeFiles) {
  const auto s = parse_ribbon_stroke("# a stroke\n0 0 0 0\n\n1 0.5 0 1  # held\n#! open\n2 1 0 0\n", "s.txt", 0.01);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[1].at, Vec3(1, 0.5, 0));
  EXPECT_TRUE(s[1].under);
  EXPECT_FALSE(s[2].under);
  EXPECT_DOUBLE_EQ(s[2].time, 0.02);
  auto fails = [](const std::string& text, const std::string& says) {
    try {
      parse_ribbon_stroke(text, "s.txt", 0.01);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const ParseError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  fails("0 0 0 0\n1 1 nan 0\n", "s.txt:2: expected x, y, z or u (a finite number), found 'nan'");
  fails("0 0 0 0\n1 1 0\n", "s.txt:2: a stroke sample is x y z u (4 numbers), this line has 3");
  fails("0 0 0 0 0\n", "s.txt:1: too many numbers");
  fails("0 0 0 0.5\n", "s.txt:1: u is 1 where the modifier was held");
  fails("# nothing\n\n", "s.txt: the stroke has no samples");
}

}  // namespace
}  // namespace s4d
