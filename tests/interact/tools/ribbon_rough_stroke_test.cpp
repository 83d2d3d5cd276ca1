// Rough strokes in the ribbon sketch: a hand-drawn loop with corners and tremor, whose ribbon folds
// as drawn, ends smoothed into an embedded ribbon close to the stroke; a stroke that no smoothing
// within the bound can flatten is refused with where, what to change and a width that works;
// smooth strokes are kept exactly as drawn.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "interact/tools/ribbon_centre_line.hpp"
#include "interact/tools/ribbon_sketch.hpp"
#include "proximity/self_intersections.hpp"
#include "shape/mesh_checks.hpp"
#include "shape/surfaces_4d.hpp"

namespace s4d {
namespace {

const Vec3 kEye = Vec3::UnitZ();

std::vector<RibbonStrokeSample> rough_loop() {
  return read_ribbon_stroke(std::string(S4D_SOURCE_DIR) + "/tests/interact/data/rough_loop_stroke.txt", 1.0 / 120);
}

template <class At>
std::vector<RibbonStrokeSample> stroke_of(At at, double seconds = 2.0) {
  std::vector<RibbonStrokeSample> s;
  const int n = static_cast<int>(seconds * 120);
  for (int i = 0; i <= n; ++i) s.push_back({at(double(i) / n), i / 120.0, false});
  return s;
}

// Distance from p to the stroke's polyline, with the closing stretch when `closed`.
double to_stroke(const Vec3& p, std::span<const RibbonStrokeSample> s, bool closed) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = s.size();
  for (std::size_t i = 0; i < (closed ? n : n - 1); ++i) {
    const Vec3 a = s[i].at, d = s[(i + 1) % n].at - a;
    const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * d - p).norm());
  }
  return best;
}

// A hairpin: along x to the left, a half turn of radius 0.05 at x = 0, back: folds any ribbon
// wider than about 0.1.
std::vector<RibbonStrokeSample> hairpin() {
  return stroke_of([](double t) {
    const double a = std::numbers::pi * std::clamp((t - 0.4) / 0.2, 0.0, 1.0);
    const double x = t < 0.4 ? -1 + 2.5 * t : t > 0.6 ? 1.5 - 2.5 * t : 0;
    return Vec3(x + 0.05 * std::sin(a), 0.05 - 0.05 * std::cos(a), 0);
  });
}

TEST(RibbonRoughStroke, AHandDrawnLoopWithCornersEndsInAnEmbeddedRibbon) {
  const auto stroke = rough_loop();
  ASSERT_GT(stroke.size(), 200u);
  RibbonSketchOptions o;
  o.width = 0.1;
  o.closed = true;
  // As drawn (no smoothing), its ribbon folds onto itself.
  RibbonSketchOptions as_drawn = o;
  as_drawn.max_move = 0;
  EXPECT_THROW(ribbon_from_sketch(stroke, {}, Frame<4>(), kEye, as_drawn), RibbonFoldError);

  const SketchedRibbon r = ribbon_from_sketch(stroke, {}, Frame<4>(), kEye, o);
  EXPECT_GT(r.smoothing.rounds, 0);
  EXPECT_GE(r.smoothing.turns, 3) << "its corners";
  EXPECT_NE(r.changes.find("smoothed the stroke"), std::string::npos) << r.changes;
  ASSERT_TRUE(r.surface.grid && r.surface.grid->wrap_i);
  // Embedded: the engine's finder and the test-only brute-force checker both find no meeting, in
  // R^4 and in the shadow (it passes nothing, so w is 0 throughout and the two are one).
  EXPECT_TRUE(self_intersections<4>(r.surface).pairs.empty());
  EXPECT_EQ(independent::self_intersections<4>(r.surface).intersecting_pairs, 0);
  Surface<3> shadow;
  shadow.triangles = r.surface.triangles;
  for (const Vec4& p : r.surface.vertices) shadow.vertices.push_back(p.head<3>());
  EXPECT_EQ(independent::self_intersections<3>(shadow).intersecting_pairs, 0);
  // Close to what was drawn: the smoothed line moved at most half the width, and every row lies
  // within that (plus the Dynadraw pen's own distance from the cursor's path, measured 0.0093) of
  // the stroke itself (measured: 0.036); no point drawn is left more than a width from it.
  EXPECT_GT(r.smoothing.moved, 0);
  EXPECT_LE(r.smoothing.moved, 0.5 * o.width);
  EXPECT_DOUBLE_EQ(r.smoothing.limit, 0.5 * o.width);
  EXPECT_LE(r.smoothing.cut, o.width);
  double farthest = 0;
  int on_stroke = 0;
  for (const Vec3& c : r.centre) {
    const double d = to_stroke(c, stroke, true);
    farthest = std::max(farthest, d);
    on_stroke += d < 0.01;
  }
  EXPECT_LT(farthest, 0.5 * o.width + 0.01);
  // ... and away from the corners it is the stroke as drawn (the pen's path, within a pixel or so;
  // measured: 124 of 146 rows).
  EXPECT_GT(on_stroke, 0.75 * static_cast<double>(r.centre.size())) << "of " << r.centre.size() << " rows";
  EXPECT_NEAR(r.length, 3.4, 0.15);
}

TEST(RibbonRoughStroke, ItsRibbonAlsoThreadsASphere) {
  // The same loop about a sphere of R^4 whose shadow its lower side crosses, below in w there.
  const auto stroke = rough_loop();
  const Surface<4> sphere = uv_sphere<4>(16, 0.3, Vec4(0, -0.6, 0, 0));
  RibbonSketchOptions o;
  o.width = 0.12;
  o.closed = true;
  o.clearance = 0.08;
  const SketchedRibbon r = ribbon_from_sketch(stroke, std::span(&sphere, 1), Frame<4>(), kEye, o);
  EXPECT_GT(r.smoothing.rounds, 0);
  EXPECT_EQ(r.passages.size(), 2u);
  EXPECT_TRUE(self_intersections<4>(r.surface).pairs.empty());
  EXPECT_EQ(independent::self_intersections<4>(r.surface).intersecting_pairs, 0);
  EXPECT_GT(r.gap_to_others, 0.5 * o.clearance);
}

TEST(RibbonRoughStroke, SmoothStrokesAreKeptExactlyAsDrawn) {
  RibbonSketchOptions o;
  o.width = 0.15;
  auto same_as_unsmoothed = [&](const std::vector<RibbonStrokeSample>& s, const RibbonSketchOptions& opt) {
    RibbonSketchOptions never = opt;
    never.max_move = 0;
    const SketchedRibbon a = ribbon_from_sketch(s, {}, Frame<4>(), kEye, opt);
    const SketchedRibbon b = ribbon_from_sketch(s, {}, Frame<4>(), kEye, never);
    EXPECT_EQ(a.smoothing.rounds, 0);
    EXPECT_TRUE(a.changes.empty()) << a.changes;
    EXPECT_EQ(a.surface.vertices, b.surface.vertices);
    EXPECT_EQ(a.centre, b.centre);
    EXPECT_EQ(a.length, b.length);
  };
  same_as_unsmoothed(stroke_of([](double t) { return Vec3(-1.4 + 2.8 * t, 0.25 * std::sin(2 * std::numbers::pi * t), 0); }), o);
  same_as_unsmoothed(
      read_ribbon_stroke(std::string(S4D_SOURCE_DIR) + "/tests/interact/data/u_stroke.txt", 1.0 / 120), o);
  RibbonSketchOptions loop = o;
  loop.closed = true;
  same_as_unsmoothed(stroke_of([](double t) {
    return Vec3(std::cos(2 * std::numbers::pi * t), 0.6 * std::sin(2 * std::numbers::pi * t), 0);
  }), loop);
}

TEST(RibbonRoughStroke, AFoldSmoothingCannotTakeOutSaysWhereAndWhatToChange) {
  RibbonSketchOptions o;
  o.width = 0.3;
  try {
    ribbon_from_sketch(hairpin(), {}, Frame<4>(), kEye, o);
    ADD_FAILURE() << "a hairpin of radius 0.05 under a ribbon 0.3 wide was accepted";
  } catch (const RibbonFoldError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("folds onto itself near ("), std::string::npos) << what;
    EXPECT_NE(what.find("even smoothed as far as it may move (0.15"), std::string::npos) << what;
    EXPECT_NE(what.find("draw that turn wider"), std::string::npos) << what;
    EXPECT_NE(what.find("or make the ribbon at most "), std::string::npos) << what;
    EXPECT_LT(std::abs(e.place.x()), 0.3) << "at the turn";
    // The width it names is narrower, and a ribbon that wide is made.
    EXPECT_GT(e.widest, 0.02);
    EXPECT_LT(e.widest, 0.15);
    RibbonSketchOptions narrower = o;
    narrower.width = e.widest;
    const SketchedRibbon r = ribbon_from_sketch(hairpin(), {}, Frame<4>(), kEye, narrower);
    EXPECT_TRUE(self_intersections<4>(r.surface).pairs.empty());
  }
}

TEST(RibbonRoughStroke, AStrokeThatDoublesBackFoldsAtAnyWidth) {
  // Out along x and straight back over itself: no ribbon lies flat at the reversal.
  const auto back = stroke_of([](double t) { return Vec3(1 - std::abs(2 * t - 1), 0, 0); });
  RibbonSketchOptions o;
  o.width = 0.1;
  try {
    ribbon_from_sketch(back, {}, Frame<4>(), kEye, o);
    ADD_FAILURE() << "accepted";
  } catch (const RibbonFoldError& e) {
    EXPECT_EQ(e.widest, 0);
    EXPECT_NE(std::string(e.what()).find("no narrower ribbon lies flat there"), std::string::npos) << e.what();
  }
}

TEST(RibbonRoughStroke, ALongStrokeIsRefusedAsBeforeWithinTheSearchsBudget) {
  // The fuzzer's stroke (a spike to y = 720 the pen rounds off at 56): 117 long, 585 widths of the
  // default ribbon, folding at the spike's tip at every width. Its search for a narrower ribbon
  // took 745 k rows of fold tests, seconds (minutes under ASan); it stops at the budget, with the
  // refusal it gave before and a sentence saying how far it looked.
  const auto stroke = read_ribbon_stroke(
      std::string(S4D_TEST_DATA) + "/fuzz_regressions/ribbon_stroke/spike_585_widths_long.txt", 1.0 / 120);
  try {
    ribbon_from_sketch(stroke, {}, Frame<4>(), kEye);
    ADD_FAILURE() << "accepted";
  } catch (const RibbonFoldError& e) {
    const std::string what = e.what();
    const std::string before =
        "the ribbon folds onto itself near (0.6062, 56.61, 0), 49% of the way along the stroke: the stroke "
        "turns there more sharply than half the ribbon's width (0.1), even smoothed as far as it may move "
        "(0.1, 0.5 of the width); draw that turn wider";
    EXPECT_EQ(what.substr(0, before.size()), before) << what;
    EXPECT_EQ(what.substr(before.size()),
              " (the search for a narrower ribbon that lies flat there was cut short: none down to 0.0686 "
              "wide does)");
    EXPECT_EQ(e.widest, 0) << "as before: none found";
    EXPECT_TRUE(e.search_cut_short);
    EXPECT_LE(e.search_work, kRibbonSuggestionWork);
    EXPECT_GT(e.search_work, kRibbonSuggestionWork / 2);
  }
}

TEST(RibbonRoughStroke, TheCentreLinesSmoothingStopsAtItsBudget) {
  // The right angle of the test below, smoothed with room for its first fold tests only: it
  // stops, says so, and has looked at no more rows than it was given.
  std::vector<PenPoint<3>> path;
  for (int i = 0; i <= 100; ++i) path.push_back({Vec3(-1 + 0.01 * i, 0, 0), 0.01 * i});
  for (int i = 1; i <= 100; ++i) path.push_back({Vec3(0, 0.01 * i, 0), 1 + 0.01 * i});
  const CentreLineResult as_drawn = ribbon_centre_line(path, false, 0.05, 2, 0.2, kEye, 0);
  const long long rows = static_cast<long long>(as_drawn.line.rows.size());
  EXPECT_EQ(as_drawn.work, rows) << "one fold test";
  const CentreLineResult whole = ribbon_centre_line(path, false, 0.05, 2, 0.2, kEye, 0.1);
  EXPECT_FALSE(whole.cut_short);
  EXPECT_GT(whole.work, 4 * rows - 10) << "the line as drawn and at least one round, each at two widths";
  const CentreLineResult cut = ribbon_centre_line(path, false, 0.05, 2, 0.2, kEye, 0.1, 3 * rows);
  EXPECT_TRUE(cut.cut_short);
  EXPECT_EQ(cut.work, 2 * rows);
  EXPECT_EQ(cut.smoothing.rounds, 0);
  EXPECT_FALSE(cut.folds.empty());
  const CentreLineResult roomy = ribbon_centre_line(path, false, 0.05, 2, 0.2, kEye, 0.1, whole.work);
  EXPECT_FALSE(roomy.cut_short);
  EXPECT_EQ(roomy.line.rows.size(), whole.line.rows.size());
  EXPECT_EQ(roomy.work, whole.work);
}

TEST(RibbonRoughStroke, TheCentreLineAloneMovesOnlyNearTheFolds) {
  // A right-angled corner under a ribbon 0.2 wide: smoothed there, the far ends untouched.
  std::vector<PenPoint<3>> path;
  for (int i = 0; i <= 100; ++i) path.push_back({Vec3(-1 + 0.01 * i, 0, 0), 0.01 * i});
  for (int i = 1; i <= 100; ++i) path.push_back({Vec3(0, 0.01 * i, 0), 1 + 0.01 * i});
  const CentreLineResult as_drawn = ribbon_centre_line(path, false, 0.05, 2, 0.2, kEye, 0);
  ASSERT_FALSE(as_drawn.folds.empty()) << "a right angle folds a ribbon 0.2 wide";
  const CentreLineResult r = ribbon_centre_line(path, false, 0.05, 2, 0.2, kEye, 0.1);
  EXPECT_TRUE(r.folds.empty());
  EXPECT_EQ(r.smoothing.turns, 1);
  EXPECT_GT(r.smoothing.rounds, 0);
  EXPECT_LE(r.smoothing.moved, 0.1);
  // A right angle blurred until a ribbon 1.25 × 0.2 wide lies flat moves its corner by about
  // 0.18 × 0.25 = 0.044 (the blur's theory, in ribbon_centre_line.cpp).
  EXPECT_GT(r.smoothing.moved, 0.02);
  EXPECT_EQ(ribbon_folds(r.line, 0.2).size(), 0u);
  EXPECT_EQ(r.line.rows.front().at, path.front().at);  // an open line keeps its ends
  EXPECT_EQ(r.line.rows.back().at, path.back().at);
  for (const PenPoint<3>& p : r.line.rows) {
    if (p.at.norm() > 0.7) {  // far from the corner: on the line drawn
      EXPECT_LT(std::min(std::abs(p.at.x()), std::abs(p.at.y())), 1e-12) << p.at.transpose();
    }
  }
}

}  // namespace
}  // namespace s4d
