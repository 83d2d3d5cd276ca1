// The flat curve modes without GL: the crossing diagram's gaps are on the under strand of every
// crossing the view finds and on no over strand, its strands lie on the curve's screen image, the
// plain shadow is the whole image, both follow the view, and the strips are as wide as the strand
// at the curve's depth.
#include "render/curve_diagram.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/scene_geometry.hpp"
#include "render/test_shapes.hpp"

namespace s4d {
namespace {

Scene trefoil_scene(CurveMode mode) {
  Scene sc = load_scene(std::string(S4D_SOURCE_DIR) + "/scenes/trefoil-knot.json");
  sc.view.curve_mode = mode;
  return sc;
}

double segment_distance(const Vec2& a, const Vec2& b, const Vec2& q, double& t) {
  const Vec2 ab = b - a;
  t = ab.squaredNorm() > 0 ? std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * ab - q).norm();
}

double strand_length(const DiagramStrand& s) {
  double l = 0;
  for (std::size_t k = 0; k + 1 < s.points.size(); ++k) l += (s.points[k + 1] - s.points[k]).norm();
  if (s.closed) l += (s.points.front() - s.points.back()).norm();
  return l;
}

// The screen image of the scene's curve objects, a polyline per component (whole curves only).
std::vector<std::vector<Vec2>> screen_image(const Scene& sc, const Camera& cam, int object = 0) {
  std::vector<std::vector<Vec2>> out;
  for (const Polyline<3>& p : drawn_curve(sc.objects[static_cast<std::size_t>(object)].shape, sc.frame)) {
    out.emplace_back();
    for (const Vec3& q : p.points) out.back().push_back(screen_point(cam, q));
  }
  return out;
}

// Every crossing the view finds has a gap, on its under strand: no strand passes the crossing at
// the under strand's depth, and the under strand's two ends stand the gap's half-length either
// side of it. The over strand is drawn through: a strand passes exactly through the crossing at
// the over strand's depth, and does not end within the gap's reach.
void expect_gaps_on_under_strands_only(const Scene& sc, const SceneGeometry& g) {
  const Camera& cam = g.camera;
  const CurveDiagram& d = g.diagram;
  const ScreenCrossings screen = screen_crossings(sc, cam);
  ASSERT_FALSE(screen.crossings.empty());
  ASSERT_EQ(d.gaps.size(), screen.crossings.size()) << "one gap per crossing of the view";
  const double h = d.half_width;
  ASSERT_GT(h, 0);
  std::vector<int> gaps_at(screen.crossings.size(), 0);
  for (const DiagramGap& gap : d.gaps) {
    SCOPED_TRACE("crossing " + std::to_string(gap.crossing));
    ASSERT_GE(gap.crossing, 0);
    ASSERT_LT(gap.crossing, static_cast<int>(screen.crossings.size()));
    ++gaps_at[static_cast<std::size_t>(gap.crossing)];
    const ScreenCrossing& c = screen.crossings[static_cast<std::size_t>(gap.crossing)];
    EXPECT_LT((gap.at - screen_point(cam, c.under)).norm(), 1e-9);
    EXPECT_LT((gap.at - screen_point(cam, c.over)).norm(), 1e-9);
    EXPECT_GE(gap.half_length, 2 * h);
    const double over_depth = 1 / cam.view_depth(c.over), under_depth = 1 / cam.view_depth(c.under);
    ASSERT_GT(over_depth, under_depth);
    const double apart = over_depth - under_depth;
    int over_passes = 0, under_ends = 0;
    for (const DiagramStrand& s : d.strands) {
      if (s.object != gap.object) continue;
      const std::size_t n = s.points.size();
      const std::size_t segments = s.closed ? n : n - 1;
      for (std::size_t k = 0; k < segments; ++k) {
        double t = 0;
        const std::size_t next = (k + 1) % n;
        const double dist = segment_distance(s.points[k], s.points[next], gap.at, t);
        const double depth = (1 - t) * s.depth[k] + t * s.depth[next];
        if (dist < 1e-9 && std::abs(depth - over_depth) < 1e-6 * apart) {
          ++over_passes;
          if (!s.closed) {
            EXPECT_GT((s.points.front() - gap.at).norm(), gap.half_length) << "over strand ends at the crossing";
            EXPECT_GT((s.points.back() - gap.at).norm(), gap.half_length) << "over strand ends at the crossing";
          }
        }
        EXPECT_FALSE(dist < 1.5 * h && std::abs(depth - under_depth) < 0.25 * apart)
            << "the under strand is drawn " << dist / h << " half-widths from the crossing";
      }
      // The gap ends: chords of half_length along a strand that bends gently.
      for (const Vec2* end : {&s.points.front(), &s.points.back()}) {
        const double r = (*end - gap.at).norm();
        if (!s.closed && r > 0.9 * gap.half_length && r <= gap.half_length * (1 + 1e-9)) ++under_ends;
      }
    }
    EXPECT_EQ(over_passes, 1) << "the over strand passes once, uncut";
    EXPECT_EQ(under_ends, 2) << "the under strand stops either side";
  }
  for (const int n : gaps_at) EXPECT_EQ(n, 1);
}

// The strands lie on the curve's screen image: their inner points are its points (the anchors
// name which), their ends on its segments; and with the gaps they make up its whole length.
void expect_strands_on_the_image(const Scene& sc, const SceneGeometry& g) {
  const CurveDiagram& d = g.diagram;
  const auto image = screen_image(sc, g.camera);
  std::vector<Vec2> all;
  std::vector<std::pair<Vec2, Vec2>> segments;
  double length = 0;
  for (const auto& c : image) {
    all.insert(all.end(), c.begin(), c.end());
    for (std::size_t k = 0; k < c.size(); ++k) {
      segments.emplace_back(c[k], c[(k + 1) % c.size()]);
      length += (c[(k + 1) % c.size()] - c[k]).norm();
    }
  }
  double drawn = 0;
  for (const DiagramStrand& s : d.strands) {
    ASSERT_EQ(s.points.size(), s.depth.size());
    ASSERT_EQ(s.points.size(), s.anchor.size());
    drawn += strand_length(s);
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const int a = s.anchor[k];
      ASSERT_GE(a, 0);
      ASSERT_LT(a, static_cast<int>(all.size()));
      const bool end = !s.closed && (k == 0 || k + 1 == s.points.size());
      if (!end) {
        EXPECT_LT((s.points[k] - all[static_cast<std::size_t>(a)]).norm(), 1e-12);
      } else {
        double best = 1e9, t = 0;
        for (const auto& [p, q] : segments) best = std::min(best, segment_distance(p, q, s.points[k], t));
        EXPECT_LT(best, 1e-12);
      }
    }
  }
  double gaps = 0;
  for (const DiagramGap& gap : d.gaps) gaps += 2 * gap.half_length;
  ASSERT_EQ(d.merged_gaps, 0);
  // Each gap's chord-length ends were cut by arc length along the image, which it matches.
  EXPECT_NEAR(drawn + gaps, length, 1e-9 * length);
}

// The shipped trefoil scene as the camera sees it: three crossings, three gaps, each on the under
// strand; three strands (the runs between under-passes), none closed.
TEST(CurveDiagram, TrefoilSceneHasAGapOnTheUnderStrandOfEachCrossing) {
  const Scene sc = trefoil_scene(CurveMode::kDiagram);
  const SceneGeometry g = build_scene_geometry(sc, 4.0 / 3);
  EXPECT_EQ(g.diagram.gaps.size(), 3u);
  EXPECT_EQ(g.diagram.strands.size(), 3u) << "a knot's diagram has as many strands as under-passes";
  for (const DiagramStrand& s : g.diagram.strands) EXPECT_FALSE(s.closed);
  expect_gaps_on_under_strands_only(sc, g);
  expect_strands_on_the_image(sc, g);
  // Drawn in place of the tube: flat, unlit, in normalised device coordinates.
  ASSERT_EQ(g.objects.size(), 1u);
  EXPECT_TRUE(g.objects[0].screen);
  EXPECT_FALSE(g.objects[0].lit);
  EXPECT_GT(g.objects[0].mesh.triangle_count(), 0u);
}

// The plain shadow is the whole image, one closed strand through every point, with no gaps; the
// tubes have no strands.
TEST(CurveDiagram, PlainShadowIsTheWholeImage) {
  const Scene sc = trefoil_scene(CurveMode::kShadow);
  const SceneGeometry g = build_scene_geometry(sc, 4.0 / 3);
  EXPECT_TRUE(g.diagram.gaps.empty());
  ASSERT_EQ(g.diagram.strands.size(), 1u);
  EXPECT_TRUE(g.diagram.strands[0].closed);
  const auto image = screen_image(sc, g.camera);
  ASSERT_EQ(g.diagram.strands[0].points.size(), image[0].size());
  for (std::size_t k = 0; k < image[0].size(); ++k) {
    EXPECT_LT((g.diagram.strands[0].points[k] - image[0][k]).norm(), 1e-12);
    EXPECT_EQ(g.diagram.strands[0].anchor[k], static_cast<int>(k));
  }
  expect_strands_on_the_image(sc, g);
  EXPECT_TRUE(g.objects[0].screen);
  const SceneGeometry tubes = build_scene_geometry(trefoil_scene(CurveMode::kTubes), 4.0 / 3);
  EXPECT_TRUE(tubes.diagram.strands.empty());
  EXPECT_FALSE(tubes.objects[0].screen);
  EXPECT_TRUE(tubes.objects[0].lit);
}

// view.intersections works in the flat modes too: the same crossings and Gauss code as the tubes'
// view, found once for the diagram and the dots.
TEST(CurveDiagram, IntersectionsAreCountedInTheFlatModesToo) {
  Scene sc = trefoil_scene(CurveMode::kTubes);
  sc.view.intersections = true;
  const IntersectionSummary tubes = build_scene_geometry(sc, 1.0).intersections;
  for (const CurveMode m : {CurveMode::kShadow, CurveMode::kDiagram}) {
    sc.view.curve_mode = m;
    const SceneGeometry g = build_scene_geometry(sc, 1.0);
    EXPECT_EQ(g.intersections.crossings, 3);
    EXPECT_EQ(g.intersections.gauss_codes, tubes.gauss_codes);
    ASSERT_EQ(g.overlays.size(), 1u);
    if (m == CurveMode::kDiagram) {
      EXPECT_GT(g.overlays[0].mesh.vertex_count(), 0u) << "the dots";
    } else {
      EXPECT_EQ(g.overlays[0].mesh.vertex_count(), 0u) << "the plain shadow (Fig. 1a) marks no crossing";
    }
  }
}

// Switching modes does not visibly move the camera: the flat modes frame the view by the round
// tube they do not build rather than by its mesh, the same in both, and every curve point is where
// the tubes' camera puts it to a tenth of a pixel of a 1024-pixel view.
TEST(CurveDiagram, TheCameraHardlyMovesBetweenModes) {
  const Scene sc = trefoil_scene(CurveMode::kTubes);
  const SceneGeometry tubes = build_scene_geometry(sc, 1.5);
  const Camera shadow = build_scene_geometry(trefoil_scene(CurveMode::kShadow), 1.5).camera;
  const Camera diagram = build_scene_geometry(trefoil_scene(CurveMode::kDiagram), 1.5).camera;
  EXPECT_EQ(shadow.view(), diagram.view());
  EXPECT_EQ(shadow.projection(), diagram.projection());
  EXPECT_NEAR(shadow.distance, tubes.camera.distance, 1e-3 * tubes.camera.distance);
  for (const Polyline<3>& p : drawn_curve(sc.objects[0].shape, sc.frame))
    for (const Vec3& q : p.points) EXPECT_LT((shadow.ndc(q) - tubes.camera.ndc(q)).norm() * 512, 0.1);
}

// Turned, close up and in a wide perspective, the diagram is that of the new view: a gap on the
// under strand of each of its crossings.
TEST(CurveDiagram, DiagramFollowsTheView) {
  const std::vector<Eigen::Quaterniond> turns = {
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3(1, 0.3, 0).normalized()) * Eigen::AngleAxisd(0.4, Vec3::UnitZ())),
      Eigen::Quaterniond(Eigen::AngleAxisd(0.6, Vec3::UnitY())),
      Eigen::Quaterniond(Eigen::AngleAxisd(-0.5, Vec3(0.2, 1, 0.4).normalized()))};
  for (std::size_t i = 0; i < turns.size(); ++i) {
    SCOPED_TRACE("view " + std::to_string(i));
    Scene sc = test::scene_of(test::trefoil(200));
    sc.view.curve_mode = CurveMode::kDiagram;
    sc.view.trackball = turns[i];
    sc.view.fov_deg = 70;
    sc.view.zoom = 1.3;
    const SceneGeometry g = build_scene_geometry(sc, 1.5);
    EXPECT_GE(g.diagram.gaps.size(), 3u);
    EXPECT_EQ(g.diagram.strands.size(), g.diagram.gaps.size());
    expect_gaps_on_under_strands_only(sc, g);
    expect_strands_on_the_image(sc, g);
  }
}

// A gap across the loop's first point is one gap: the curve's points renumbered so that an
// under-pass is on its first segment give the same diagram.
TEST(CurveDiagram, AGapAcrossTheStartOfTheLoopIsOneGap) {
  Scene sc = test::scene_of(test::trefoil(200));
  sc.view.curve_mode = CurveMode::kDiagram;
  const SceneGeometry before = build_scene_geometry(sc, 1.0);
  const ScreenCrossing c = screen_crossings(sc, before.camera).crossings.at(0);  // a copy: the list is a temporary
  ASSERT_GE(c.under_at.segment, 0);
  auto& points = std::get<Curve<3>>(sc.objects[0].shape).components[0].points;
  std::rotate(points.begin(), points.begin() + c.under_at.segment, points.end());
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  ASSERT_EQ(g.diagram.gaps.size(), 3u);
  EXPECT_EQ(g.diagram.strands.size(), 3u);
  expect_gaps_on_under_strands_only(sc, g);
  expect_strands_on_the_image(sc, g);
}

// A link (the Hopf link, one object of two components): each component is cut at its own
// under-passes, a strand per under-pass.
TEST(CurveDiagram, ALinkHasAStrandPerUnderPassOfEachComponent) {
  Scene sc = load_scene_or_object("torus-knot:p=2,q=2");
  sc.view.curve_mode = CurveMode::kDiagram;
  sc.view.trackball = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3::UnitX()));
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  ASSERT_EQ(std::get<Curve<3>>(sc.objects[0].shape).components.size(), 2u);
  EXPECT_EQ(g.diagram.gaps.size(), 2u);
  std::vector<int> gaps(2, 0), strands(2, 0);
  for (const DiagramGap& gap : g.diagram.gaps) ++gaps.at(static_cast<std::size_t>(gap.run));
  for (const DiagramStrand& s : g.diagram.strands) ++strands.at(static_cast<std::size_t>(s.run));
  EXPECT_EQ(gaps, strands);
  expect_gaps_on_under_strands_only(sc, g);
  expect_strands_on_the_image(sc, g);
}

// Two over strands closer together than a gap: the under strand's two gaps are drawn as one, and
// counted; the over strands are whole.
TEST(CurveDiagram, GapsThatOverlapAreDrawnAsOne) {
  Curve<3> c;
  c.components.push_back({{Vec3(-1, 0, -0.5), Vec3(1, 0, -0.5)}, false});        // under
  c.components.push_back({{Vec3(0, -1, 0.5), Vec3(0, 1, 0.5)}, false});          // over
  c.components.push_back({{Vec3(0.02, -1, 0.5), Vec3(0.02, 1, 0.5)}, false});    // over, close by
  Scene sc = test::scene_of(c);
  sc.view.curve_mode = CurveMode::kDiagram;
  sc.view.tube_radius = 0.02;
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  ASSERT_EQ(g.diagram.gaps.size(), 2u);
  EXPECT_EQ(g.diagram.merged_gaps, 1);
  ASSERT_EQ(g.diagram.strands.size(), 4u) << "the under strand in two, the over strands whole";
  int under = 0;
  for (const DiagramStrand& s : g.diagram.strands) {
    if (s.run != 0) {
      EXPECT_EQ(s.points.size(), 2u);
      continue;
    }
    ++under;
    // The left piece ends a gap's reach before the first crossing, the right one starts a gap's
    // reach after the second.
    const double x0 = g.diagram.gaps[0].at.x(), x1 = g.diagram.gaps[1].at.x(), a = g.diagram.gaps[0].half_length;
    if (s.points.front().x() < std::min(x0, x1))
      EXPECT_NEAR(s.points.back().x(), std::min(x0, x1) - a, 1e-9);
    else
      EXPECT_NEAR(s.points.front().x(), std::max(x0, x1) + a, 1e-9);
  }
  EXPECT_EQ(under, 2);
}

// With the eye inside the knot only what it sees is drawn, and the crossings among that still get
// their gaps (found on the image's runs without the crossing finder's segment names).
TEST(CurveDiagram, WithPartOfTheCurveBehindTheEyeTheSeenCrossingsGetGaps) {
  Scene sc = test::scene_of(test::trefoil(200));
  sc.view.curve_mode = CurveMode::kDiagram;
  sc.view.trackball = Eigen::AngleAxisd(0.5, Vec3::UnitX()) * Eigen::AngleAxisd(0.3, Vec3::UnitY());
  sc.view.distance = 0.15;
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  ASSERT_GT(g.diagram.screen.behind_eye, 0);
  const std::size_t n = std::get<Curve<3>>(sc.objects[0].shape).components[0].points.size();
  for (const DiagramStrand& s : g.diagram.strands) {
    EXPECT_FALSE(s.closed);
    for (const int a : s.anchor) {
      EXPECT_GE(a, 0);
      EXPECT_LT(a, static_cast<int>(n));
    }
    for (const double depth : s.depth) EXPECT_GT(depth, 0) << "in front of the eye";
  }
  ASSERT_FALSE(g.diagram.screen.crossings.empty());
  expect_gaps_on_under_strands_only(sc, g);
}

// The strip of an open straight curve: each pair of vertices straddles the curve's point on the
// screen, 2 half-widths apart across it, at the depth OpenGL gives the point.
TEST(CurveDiagram, StripIsAsWideAsTheStrandAtTheDepthOfTheCurve) {
  Curve<3> line;
  line.components.push_back({{Vec3(-1, -0.2, 0.3), Vec3(0, 0, 0), Vec3(1, 0.2, -0.3)}, false});
  Scene sc = test::scene_of(line);
  sc.view.curve_mode = CurveMode::kShadow;
  sc.view.tube_radius = 0.05;
  const double aspect = 1.6;
  const SceneGeometry g = build_scene_geometry(sc, aspect);
  const Camera& cam = g.camera;
  const RenderMesh& m = g.objects[0].mesh;
  ASSERT_EQ(m.vertex_count(), 6u);
  EXPECT_EQ(m.triangle_count(), 4u);
  EXPECT_NEAR(g.diagram.half_width, strand_half_width(cam, 0.05), 1e-15);
  const auto& pts = line.components[0].points;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Eigen::Vector4d clip = cam.projection() * cam.view() * pts[k].homogeneous();
    const Vec3 ndc = clip.head<3>() / clip.w();
    const Vec3 a = m.positions[2 * k], b = m.positions[2 * k + 1];
    EXPECT_LT(((a + b) / 2 - ndc).norm(), 1e-9);
    const Vec2 across((a.x() - b.x()) * aspect, a.y() - b.y());  // in screen units
    EXPECT_NEAR(across.norm(), 2 * g.diagram.half_width, 1e-9);
    EXPECT_EQ(m.source[2 * k], static_cast<int>(k));
  }
  // Mitred at the middle point: across both segments' directions by the same amount.
  const Vec2 d0 = screen_point(cam, pts[1]) - screen_point(cam, pts[0]);
  const Vec2 across((m.positions[2].x() - m.positions[3].x()) * aspect, m.positions[2].y() - m.positions[3].y());
  EXPECT_NEAR(std::abs(across.dot(d0.normalized())), 0, 1e-9);
}

TEST(CurveDiagram, ScreenToPixelsPutsTheViewsCornersAtTheImagesCorners) {
  const double aspect = 2.0;
  EXPECT_LT((screen_to_pixels(Vec2(-aspect, 1), aspect, 200, 100) - Vec2(0, 0)).norm(), 1e-12);
  EXPECT_LT((screen_to_pixels(Vec2(aspect, -1), aspect, 200, 100) - Vec2(200, 100)).norm(), 1e-12);
  EXPECT_LT((screen_to_pixels(Vec2(0, 0), aspect, 200, 100) - Vec2(100, 50)).norm(), 1e-12);
  // A screen point is the camera's NDC with the aspect taken out.
  const Camera cam = make_camera(BoundingSphere{Vec3::Zero(), 1.0}, Eigen::Quaterniond::Identity(), 0, 35, aspect);
  const Vec3 p(0.3, -0.2, 0.1);
  const Vec2 s = screen_point(cam, p);
  EXPECT_NEAR(s.x() / aspect, cam.ndc(p).x(), 1e-12);
  EXPECT_NEAR(s.y(), cam.ndc(p).y(), 1e-12);
}

}  // namespace
}  // namespace s4d
