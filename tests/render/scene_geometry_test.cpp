// Scene geometry tests: depth colour follows w across objects (R^4) and view depth (R^3), the
// colour switch, tube building for curves, the camera containing everything drawn, the shadow's
// intersection curves with their above-below marks and pinch points, crossings of curves' images.
#include "render/scene_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "knots/knot_diagram.hpp"
#include "render/test_shapes.hpp"
#include "shape/surfaces_4d.hpp"

namespace s4d {
namespace {

// Redness: red minus blue, +1 for pure red, -1 for pure blue.
float redness(const Vec3f& c) { return c.x() - c.z(); }

TEST(SceneGeometry, FourDimensionalDepthColourIsSharedAcrossObjects) {
  // Two parallel squares at w = -1 and w = +1 (flat in w): the far one must be blue, the near
  // one red, which only holds if the w range spans both objects.
  Scene sc;
  for (double w : {-1.0, 1.0}) {
    Surface<4> s = test::tilted_square(0.0, 4);
    for (auto& v : s.vertices) v[3] = w;
    SceneObject o;
    o.shape = s;
    sc.objects.push_back(o);
  }
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  ASSERT_EQ(g.objects.size(), 2u);
  EXPECT_DOUBLE_EQ(g.w_range.lo, -1);
  EXPECT_DOUBLE_EQ(g.w_range.hi, 1);
  EXPECT_TRUE(g.view_range.empty());
  for (const Vec3f& c : g.objects[0].colours) EXPECT_LT(redness(c), -0.4f);
  for (const Vec3f& c : g.objects[1].colours) EXPECT_GT(redness(c), 0.4f);
  EXPECT_EQ(g.objects[0].colours[0], map_colour(ColourMap::kCoolWarm, 0.0));
  EXPECT_EQ(g.objects[1].colours[0], map_colour(ColourMap::kCoolWarm, 1.0));
}

TEST(SceneGeometry, ColourFollowsWAfterAFourDimensionalRotation) {
  Scene sc = test::scene_of(test::tilted_square(0.5, 8));
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  const DrawObject& o = g.objects[0];
  for (std::size_t v = 0; v < o.mesh.vertex_count(); ++v) {
    // w = 0.5 x, and the identity frame keeps x: redness grows with x.
    EXPECT_NEAR(o.depth[v], 0.5 * o.mesh.positions[v].x(), 1e-12);
    for (std::size_t u = 0; u < o.mesh.vertex_count(); ++u)
      if (o.mesh.positions[u].x() > o.mesh.positions[v].x() + 0.1) {
        EXPECT_GT(redness(o.colours[u]), redness(o.colours[v]));
      }
  }
  // A quarter turn in xw trades x and w: the shadow's x now spans the old w range (±0.5) and
  // the 4D depth the old x range (±1).
  sc.frame.rotate(Plane{0, 3}, test::kPi / 2);
  const SceneGeometry h = build_scene_geometry(sc, 1.0);
  double max_x = 0;
  for (const Vec3& p : h.objects[0].mesh.positions) max_x = std::max(max_x, std::abs(p.x()));
  EXPECT_NEAR(max_x, 0.5, 1e-9);
  EXPECT_NEAR(h.w_range.lo, -1, 1e-9);
  EXPECT_NEAR(h.w_range.hi, 1, 1e-9);
}

TEST(SceneGeometry, ThreeDimensionalObjectsAreColouredByDistanceFromTheCamera) {
  Scene sc = test::scene_of(test::uv_sphere(12, 16));
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  EXPECT_TRUE(g.w_range.empty());
  const DrawObject& o = g.objects[0];
  EXPECT_EQ(o.dim, 3);
  // The identity trackball looks down -z: the +z pole is nearest (red), the -z pole farthest.
  std::size_t top = 0, bottom = 0;
  for (std::size_t v = 0; v < o.mesh.vertex_count(); ++v) {
    if (o.mesh.positions[v].z() > o.mesh.positions[top].z()) top = v;
    if (o.mesh.positions[v].z() < o.mesh.positions[bottom].z()) bottom = v;
  }
  EXPECT_GT(redness(o.colours[top]), 0.4f);
  EXPECT_LT(redness(o.colours[bottom]), -0.4f);
  EXPECT_NEAR(g.view_range.hi - g.view_range.lo, 2, 1e-9);
}

TEST(SceneGeometry, DepthColourOffGivesGreyOrTheObjectColour) {
  Scene sc = test::scene_of(test::clifford_torus(12));
  sc.view.depth_colour = false;
  SceneGeometry g = build_scene_geometry(sc, 1.0);
  for (const Vec3f& c : g.objects[0].colours) EXPECT_EQ(c, map_colour(ColourMap::kGrey, 0.5));
  sc.objects[0].colour = Vec3f(0.2f, 0.9f, 0.1f);
  g = build_scene_geometry(sc, 1.0);
  for (const Vec3f& c : g.objects[0].colours) EXPECT_EQ(c, Vec3f(0.2f, 0.9f, 0.1f));
  // The grey map is a way to switch depth colour off too.
  sc.view.depth_colour = true;
  sc.view.colour_map = ColourMap::kGrey;
  g = build_scene_geometry(sc, 1.0);
  for (const Vec3f& c : g.objects[0].colours) EXPECT_EQ(c, Vec3f(0.2f, 0.9f, 0.1f));
}

TEST(SceneGeometry, CurvesBecomeTubesAndTheCameraSeesEverything) {
  Scene sc = test::scene_of(test::trefoil(50));
  Curve<4> c4 = lift_to_4d(test::trefoil(40, 0.2));
  for (auto& p : c4.components[0].points) p[3] = p[0];  // a 4D curve with varying w
  SceneObject o;
  o.shape = c4;
  sc.objects.push_back(o);
  sc.view.tube_radius = 0.05;
  const SceneGeometry g = build_scene_geometry(sc, 1.5);
  ASSERT_EQ(g.objects.size(), 2u);
  EXPECT_FALSE(g.objects[0].surface);
  EXPECT_EQ(g.objects[0].mesh.vertex_count(), 50u * kTubeSides);
  EXPECT_EQ(g.objects[1].mesh.vertex_count(), 40u * kTubeSides);
  EXPECT_EQ(g.objects[1].dim, 4);
  EXPECT_FALSE(g.w_range.empty());
  EXPECT_FALSE(g.view_range.empty());
  const Mat4 m = g.camera.projection() * g.camera.view();
  for (const DrawObject& d : g.objects)
    for (const Vec3& p : d.mesh.positions) {
      const Eigen::Vector4d q = m * p.homogeneous();
      ASSERT_GT(q.w(), 0);
      EXPECT_LE(std::abs(q.x() / q.w()), 1.0);
      EXPECT_LE(std::abs(q.y() / q.w()), 1.0);
      EXPECT_LE(std::abs(q.z() / q.w()), 1.0);
    }
  // A bad tube radius falls back to the default instead of producing an empty or inverted tube.
  sc.view.tube_radius = -1;
  EXPECT_EQ(build_scene_geometry(sc, 1.0).objects[0].mesh.vertex_count(), 50u * kTubeSides);
}

// The shadow of two planes of R^4 meeting at the origin: their shadows cross along a segment
// whose two sheets agree in w only at the origin's shadow, where the true point's bead sits.
TEST(SceneGeometry, IntersectionCurvesMarkTheTrueFourDimensionalPoint) {
  Scene sc = test::scene_of(test::crossing_planes());
  sc.frame.rotate(Plane{0, 3}, 0.5);
  sc.frame.rotate(Plane{1, 2}, 0.35);
  sc.frame.rotate(Plane{0, 2}, 0.17);
  EXPECT_TRUE(build_scene_geometry(sc, 1.0).overlays.empty()) << "off by default";
  EXPECT_FALSE(build_scene_geometry(sc, 1.0).intersections.computed);

  sc.view.intersections = true;
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  ASSERT_EQ(g.objects.size(), 1u) << "overlays do not count as objects";
  ASSERT_EQ(g.overlays.size(), 2u) << "the curves with their beads, and the above-below marks";
  EXPECT_TRUE(g.overlays[0].lit);
  EXPECT_FALSE(g.overlays[1].lit) << "the marks keep their colours whatever the light";
  const IntersectionSummary& s = g.intersections;
  EXPECT_TRUE(s.computed);
  EXPECT_EQ(s.curves, 1);
  EXPECT_EQ(s.true_curves, 1);
  EXPECT_EQ(s.shadow_only_curves, 0);
  EXPECT_EQ(s.true_points, 1);
  // The segment ends where one square or the other stops: no pinch point.
  EXPECT_EQ(s.border_ends, 2);
  EXPECT_EQ(s.pinch_points, 0);
  EXPECT_EQ(s.branch_points, 0);
  const DrawObject& o = g.overlays[0];
  ASSERT_GT(o.mesh.vertex_count(), 0u);
  ASSERT_EQ(o.colours.size(), o.mesh.vertex_count());
  double nearest_true = 1e9;
  for (std::size_t v = 0; v < o.mesh.vertex_count(); ++v) {
    EXPECT_TRUE(o.colours[v] == kTrueIntersectionColour || o.colours[v] == kShadowOnlyColour);
    if (o.colours[v] == kTrueIntersectionColour)
      nearest_true = std::min(nearest_true, o.mesh.positions[v].norm());
  }
  for (const Vec3f& c : g.overlays[1].colours) EXPECT_TRUE(c == kAboveColour || c == kBelowColour);
  // The bead (2.5 × half the tube radius, 0.0375) is centred on the origin's shadow.
  EXPECT_LT(nearest_true, 0.06);
  EXPECT_NE(intersection_text(s).find("1 true (1 true point(s)); 0 pinch point(s), 2 curve end(s) at a border"),
            std::string::npos)
      << intersection_text(s);
}

// The plane of a flat sheet in the shadow: unit normal n and offset c (n·p = c on it).
struct ShadowPlane {
  Vec3 n;
  double c;
  double distance(const Vec3& p) const { return std::abs(n.dot(p) - c); }
};
ShadowPlane plane_of(const Surface<4>& s, int triangle, const Frame<4>& frame) {
  const Triangle& t = s.triangles[static_cast<std::size_t>(triangle)];
  const Vec3 a = frame.shadow(s.vertices[t[0]]), b = frame.shadow(s.vertices[t[1]]),
             c = frame.shadow(s.vertices[t[2]]);
  const Vec3 n = (b - a).cross(c - a).normalized();
  return {n, n.dot(a)};
}

// The overlays' vertices of one colour.
std::vector<Vec3> vertices_of(const SceneGeometry& g, const Vec3f& colour) {
  std::vector<Vec3> out;
  for (const DrawObject& o : g.overlays)
    for (std::size_t v = 0; v < o.mesh.vertex_count(); ++v)
      if (o.colours[v] == colour) out.push_back(o.mesh.positions[v]);
  return out;
}

// Two squares crossing in the shadow along the x axis, apart in w. The marks are lines on each
// sheet beside the curve: red on the sheet nearer in w, blue on the other, on both sides of the
// curve, thinner than the curve's tube and clear of it. Swapping the sheets' w swaps the colours:
// the colour follows depth, not the order of the sheets. The same holds for the sheets as two
// surfaces (the finder's pair path) as for one surface (its self path).
TEST(SceneGeometry, AboveBelowMarksAreRedOnTheNearerSheetAndBlueOnTheFarther) {
  for (const bool a_nearer : {true, false})
    for (const bool two_objects : {false, true}) {
      SCOPED_TRACE(std::string(a_nearer ? "A nearer" : "B nearer") + (two_objects ? ", two objects" : ", one"));
      const Surface<4> sheets = a_nearer ? test::sheets_apart_in_w(0.5, -0.5) : test::sheets_apart_in_w(-0.5, 0.5);
      Scene sc;
      if (two_objects) {
        const auto [a, b] = test::split_squares(sheets);
        sc = test::scene_of(a);
        sc.objects.push_back(test::scene_of(b).objects[0]);
        sc.objects[1].name = "B";
      } else {
        sc = test::scene_of(sheets);
      }
      sc.view.intersections = true;
      const SceneGeometry g = build_scene_geometry(sc, 1.0);
      const IntersectionSummary& s = g.intersections;
      EXPECT_EQ(s.curves, 1);
      EXPECT_EQ(s.shadow_only_curves, 1);
      EXPECT_EQ(s.true_points, 0);
      EXPECT_EQ(s.border_ends, 2);
      EXPECT_EQ(s.pinch_points, 0);
      const ShadowPlane plane_a = plane_of(sheets, 0, sc.frame), plane_b = plane_of(sheets, 2, sc.frame);
      const ShadowPlane& near = a_nearer ? plane_a : plane_b;
      const ShadowPlane& far = a_nearer ? plane_b : plane_a;
      const double line = 0.5 * sc.view.tube_radius;  // the curve's tube
      for (const auto& [colour, on, other] : {std::tuple{kAboveColour, near, far}, std::tuple{kBelowColour, far, near}}) {
        const std::vector<Vec3> mark = vertices_of(g, colour);
        ASSERT_GT(mark.size(), 0u);
        int sides[2] = {0, 0};
        for (const Vec3& p : mark) {
          EXPECT_LT(on.distance(p), line) << "on its sheet, thinner than the curve's tube";
          EXPECT_GT(other.distance(p), 1.5 * line) << "beside the curve, clear of its tube";
          EXPECT_GE(p.x(), -0.8 - line);  // within the crossing's extent, x in [-0.8, 1]
          EXPECT_LE(p.x(), 1 + line);
          ++sides[other.n.dot(p) - other.c > 0];
        }
        EXPECT_GT(sides[0], 0) << "a line on each side of the curve";
        EXPECT_GT(sides[1], 0);
      }
    }
}

// Where two sheets truly meet (the planes xy and zw through the origin), their order in w swaps:
// the red line is on one sheet up to the meeting point and on the other after it.
TEST(SceneGeometry, AboveBelowMarksSwapSheetsWhereTheSheetsTrulyMeet) {
  const Surface<4> planes = test::crossing_planes();
  Scene sc = test::scene_of(planes);
  sc.frame.rotate(Plane{0, 3}, 0.5);
  sc.frame.rotate(Plane{1, 2}, 0.35);
  sc.frame.rotate(Plane{0, 2}, 0.17);
  sc.view.intersections = true;
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  const ShadowIntersections r = shadow_intersections(planes, sc.frame);
  const ShadowSegment* met = nullptr;
  for (const ShadowSegment& s : r.segments)
    if (s.true_intersection) met = &s;
  ASSERT_NE(met, nullptr);
  // Sheet A (triangles 0, 1) is nearer in w on the side of p0 when the depth difference is
  // positive there; the depths are affine on each plane, so one side of the meet holds for all.
  ASSERT_LT(met->a, 2);
  ASSERT_GE(met->b, 2);
  const Vec3 toward_p0 = met->p0 - met->meet;
  const bool a_over_at_p0 = met->depth_a0 > met->depth_b0;
  const ShadowPlane plane_a = plane_of(planes, 0, sc.frame), plane_b = plane_of(planes, 2, sc.frame);
  const double line = 0.5 * sc.view.tube_radius;
  int on_a[2] = {0, 0}, on_b[2] = {0, 0};  // red vertices on each sheet, by side of the meet
  for (const Vec3& p : vertices_of(g, kAboveColour)) {
    const double along = (p - met->meet).dot(toward_p0.normalized());
    if (std::abs(along) < line) continue;  // the lines' ends at the meet, within a tube's radius
    const bool p0_side = along > 0;
    if (plane_a.distance(p) < line) {
      ++on_a[p0_side];
      EXPECT_EQ(p0_side, a_over_at_p0) << "red on sheet A only where A is nearer in w";
    } else {
      EXPECT_LT(plane_b.distance(p), line) << "a mark lies on one of the sheets";
      ++on_b[p0_side];
      EXPECT_NE(p0_side, a_over_at_p0) << "red on sheet B only where B is nearer in w";
    }
  }
  EXPECT_GT(on_a[a_over_at_p0], 0);
  EXPECT_GT(on_b[!a_over_at_p0], 0);
}

// The pinch points of a generic shadow of the Clifford torus x(u, v) = (cos u, sin u, cos v,
// sin v) / sqrt 2: the shadow ray d (the frame's w axis) lies in the tangent plane where
// (-sin u, cos u) is parallel to (d0, d1) and (-sin v, cos v) to (d2, d3), two choices each: four
// Whitney umbrellas, joined in pairs by the two double curves (the paper's Fig. 12, where they
// are moved until they cancel).
std::vector<Vec3> clifford_pinch_points(const Frame<4>& frame) {
  const Vec4 d = frame.matrix().col(3);
  std::vector<Vec3> out;
  for (const double du : {0.0, test::kPi})
    for (const double dv : {0.0, test::kPi}) {
      const double u = std::atan2(-d[0], d[1]) + du, v = std::atan2(-d[2], d[3]) + dv;
      out.push_back(frame.shadow(Vec4(std::cos(u), std::sin(u), std::cos(v), std::sin(v)) / std::sqrt(2.0)));
    }
  return out;
}

// In a generic view the finder gives the torus's shadow two open curves. On this symmetric mesh
// the curves pass exactly through mesh edges of both sheets, where the finder also returns
// point-like segments, so its strokes are many more than two (dozens, some of no length): the
// ends are counted with those left out, and come to the four the geometry says, a bead on each,
// within a few hundredths of the smooth torus's pinch points (the mesh spacing is 0.09).
TEST(SceneGeometry, PinchPointsOfTheCliffordTorusAreBeadedAtTheEndsOfItsCurves) {
  for (const auto& turns : {std::vector<std::pair<Plane, double>>{{Plane{0, 3}, 0.52}, {Plane{1, 3}, 0.35}},
                            {{Plane{0, 3}, 0.9}, {Plane{2, 3}, 0.4}, {Plane{1, 2}, 0.3}}}) {
    Scene sc = test::scene_of(test::clifford_torus(48));
    for (const auto& [plane, angle] : turns) sc.frame.rotate(plane, angle);
    sc.view.intersections = true;
    const SceneGeometry g = build_scene_geometry(sc, 1.0);
    const IntersectionSummary& s = g.intersections;
    EXPECT_EQ(s.curves, 2);
    EXPECT_EQ(s.true_curves, 0);
    EXPECT_EQ(s.pinch_points, 4);
    EXPECT_EQ(s.border_ends, 0) << "the torus has no border";
    EXPECT_EQ(s.branch_points, 0);
    const ShadowIntersections r = shadow_intersections(std::get<Surface<4>>(sc.objects[0].shape), sc.frame);
    EXPECT_GT(r.strokes.size(), 4u) << "the finder's strokes are broken at point-like segments";
    for (const ShadowCurve& c : r.curves) EXPECT_FALSE(c.closed);
    // Each analytic pinch point has a bead, and every bead vertex belongs to one of them.
    const std::vector<Vec3> pinches = clifford_pinch_points(sc.frame);
    const std::vector<Vec3> bead = vertices_of(g, kPinchPointColour);
    ASSERT_GT(bead.size(), 0u);
    std::vector<Eigen::Vector3d> centre(4, Eigen::Vector3d::Zero());
    std::vector<int> count(4, 0);
    for (const Vec3& p : bead) {
      std::size_t best = 0;
      for (std::size_t k = 1; k < 4; ++k)
        if ((p - pinches[k]).norm() < (p - pinches[best]).norm()) best = k;
      centre[best] += p;
      ++count[best];
    }
    for (std::size_t k = 0; k < 4; ++k) {
      ASSERT_GT(count[k], 0) << "no bead at pinch point " << k;
      EXPECT_EQ(count[k], count[0]) << "one bead each";
      EXPECT_LT((centre[k] / count[k] - pinches[k]).norm(), 0.03);
    }
    EXPECT_NE(intersection_text(s).find("; 4 pinch point(s)"), std::string::npos) << intersection_text(s);
  }
}

TEST(SceneGeometry, IntersectionCurvesOfTheCliffordTorusAreShadowOnly) {
  Scene sc = test::scene_of(test::clifford_torus(48));
  sc.frame.rotate(Plane{0, 3}, 0.52);
  sc.frame.rotate(Plane{1, 3}, 0.35);
  sc.view.intersections = true;
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  ASSERT_EQ(g.overlays.size(), 2u);
  EXPECT_EQ(g.intersections.true_curves, 0) << "the torus is embedded in R^4";
  EXPECT_GE(g.intersections.shadow_only_curves, 1) << "but its turned shadow crosses itself";
  EXPECT_GT(g.intersections.length, 0.5);
  EXPECT_EQ(g.intersections.coplanar_pairs, 0);
  for (const DrawObject& o : g.overlays)
    for (const Vec3f& c : o.colours)
      EXPECT_TRUE(c == kShadowOnlyColour || c == kAboveColour || c == kBelowColour || c == kPinchPointColour);
  EXPECT_FALSE(vertices_of(g, kAboveColour).empty());
  EXPECT_FALSE(vertices_of(g, kBelowColour).empty());
}

// Where a point is drawn on the screen (normalised device x, y).
Vec2 on_screen(const Camera& cam, const Vec3& p) {
  const Eigen::Vector4d c = cam.projection() * cam.view() * p.homogeneous();
  return c.head<2>() / c.w();
}

// Distance from p to the curve (every component, open or closed).
double distance_to_curve(const Curve<3>& c, const Vec3& p) {
  double best = 1e9;
  for (const auto& poly : c.components)
    for (std::size_t k = 0; k < poly.segment_count(); ++k) {
      const Vec3 a = poly.seg_a(k), b = poly.seg_b(k);
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + t * (b - a) - p).norm());
    }
  return best;
}

// Each crossing of the image is a point of each strand, both drawn on the same pixel, the over
// one nearer the eye: checked through the camera's own matrices, perspective included.
void expect_true_crossings(const Camera& cam, const Curve<3>& drawn,
                           const std::vector<ScreenCrossing>& found) {
  for (const ScreenCrossing& c : found) {
    EXPECT_LT((on_screen(cam, c.over) - on_screen(cam, c.under)).norm(), 1e-9);
    EXPECT_LT(cam.view_depth(c.over), cam.view_depth(c.under));
    EXPECT_LT(distance_to_curve(drawn, c.over), 1e-9);
    EXPECT_LT(distance_to_curve(drawn, c.under), 1e-9);
    EXPECT_EQ(c.object, 0);
  }
}

// The trefoil seen down its axis is its standard diagram: three crossings, each marked by a dot
// in front of the over strand.
TEST(SceneGeometry, CrossingsOfTheTrefoilsImageAreItsDiagram) {
  const Curve<3> k = test::trefoil();
  Scene sc = test::scene_of(k);
  EXPECT_TRUE(build_scene_geometry(sc, 1.0).overlays.empty()) << "off by default";
  sc.view.intersections = true;
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  EXPECT_EQ(g.intersections.curve_objects, 1);
  EXPECT_EQ(g.intersections.crossings, 3);
  EXPECT_EQ(g.intersections.crossing_non_generic, 0);
  EXPECT_EQ(intersection_text(g.intersections), "3 crossing(s) of the curves in this view");
  const ScreenCrossings screen = screen_crossings(sc, g.camera);
  EXPECT_EQ(screen.behind_eye, 0);
  const auto& found = screen.crossings;
  ASSERT_EQ(found.size(), 3u);
  expect_true_crossings(g.camera, k, found);
  ASSERT_EQ(g.overlays.size(), 1u);
  int dots = 0;
  for (std::size_t v = 0; v < g.overlays[0].mesh.vertex_count(); ++v) {
    if (!(g.overlays[0].colours[v] == kCrossingColour)) continue;
    ++dots;
    // Every dot sits in front of (nearer the eye than) a crossing's over strand.
    double best = 1e9;
    for (const ScreenCrossing& c : found) best = std::min(best, (g.overlays[0].mesh.positions[v] - c.over).norm());
    EXPECT_LT(best, 2 * sc.view.tube_radius);
  }
  EXPECT_GT(dots, 0);
}

// The Gauss code of the view is the knot engine's code of the same view: the camera on the +z
// axis sees what Frame<3>() sees, over and under included (the mirror image has them swapped).
TEST(SceneGeometry, GaussCodeOfTheViewIsTheKnotEnginesCode) {
  for (const double mirror : {1.0, -1.0}) {
    Curve<3> k = test::trefoil();
    for (Vec3& p : k.components[0].points) p.z() *= mirror;
    Scene sc = test::scene_of(k);
    sc.view.intersections = true;
    const SceneGeometry g = build_scene_geometry(sc, 1.0);
    const std::string code = diagram_from_curve(k, Frame<3>()).gauss_code();
    EXPECT_EQ(code, mirror > 0 ? "-1, 2, -3, 1, -2, 3" : "1, -2, 3, -1, 2, -3");
    ASSERT_EQ(g.intersections.gauss_codes.size(), 1u);
    EXPECT_EQ(g.intersections.gauss_codes[0], "Gauss code of 'object' in this view: " + code);
  }
}

// Without a whole image (part of the curve behind the eye) or a closed curve, there is no diagram,
// and the line says why.
TEST(SceneGeometry, GaussCodeSaysWhyAViewHasNone) {
  Scene sc = test::scene_of(test::trefoil());
  sc.view.trackball = Eigen::AngleAxisd(0.5, Vec3::UnitX()) * Eigen::AngleAxisd(0.3, Vec3::UnitY());
  sc.view.distance = 0.15;
  sc.view.intersections = true;
  ASSERT_EQ(build_scene_geometry(sc, 1.0).intersections.gauss_codes.size(), 1u);
  EXPECT_EQ(build_scene_geometry(sc, 1.0).intersections.gauss_codes[0],
            "Gauss code of 'object' in this view: none (part of it is behind the eye)");
  Curve<3> open;
  open.components.push_back({{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 1), Vec3(0, -1, 1)}, false});
  Scene so = test::scene_of(open);
  so.view.intersections = true;
  const auto codes = build_scene_geometry(so, 1.0).intersections.gauss_codes;
  ASSERT_EQ(codes.size(), 1u);
  EXPECT_NE(codes[0].find("in this view: none ("), std::string::npos) << codes[0];
}

// Close up and turned, perspective moves the crossings of the image away from those of any
// parallel projection: the crossings found are still where the strands meet on the screen.
TEST(SceneGeometry, CrossingsFollowThePerspectiveOfTheCamera) {
  const Curve<3> k = test::trefoil();
  Scene sc = test::scene_of(k);
  sc.view.trackball = Eigen::AngleAxisd(0.7, Vec3(1, 0.3, 0).normalized()) *
                      Eigen::AngleAxisd(0.4, Vec3::UnitZ());
  sc.view.fov_deg = 70;
  sc.view.zoom = 1.3;
  sc.view.intersections = true;
  const SceneGeometry g = build_scene_geometry(sc, 1.5);
  const auto found = screen_crossings(sc, g.camera).crossings;
  EXPECT_GE(found.size(), 3u) << "a trefoil's diagram has at least three crossings";
  EXPECT_EQ(g.intersections.crossings, static_cast<int>(found.size()));
  expect_true_crossings(g.camera, k, found);
}

// A curve in R^4 is seen through its shadow: the trefoil with any w has the trefoil's diagram.
TEST(SceneGeometry, CrossingsOfACurveInFourDimensionsAreThoseOfItsShadow) {
  const Curve<3> k = test::trefoil();
  Curve<4> lifted;
  Polyline<4> p;
  for (const Vec3& q : k.components[0].points) p.points.push_back(Vec4(q.x(), q.y(), q.z(), 0.3 * q.x() * q.y()));
  lifted.components.push_back(p);
  Scene sc = test::scene_of(lifted);
  sc.view.intersections = true;
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  EXPECT_EQ(g.intersections.crossings, 3);
  expect_true_crossings(g.camera, k, screen_crossings(sc, g.camera).crossings);
}

// With the eye inside the knot, the part behind it has no image: it is left out (and said so),
// and what is counted is still where the visible strands cross.
TEST(SceneGeometry, CrossingsLeaveOutWhatIsBehindTheEye) {
  const Curve<3> k = test::trefoil();
  Scene sc = test::scene_of(k);
  sc.view.trackball = Eigen::AngleAxisd(0.5, Vec3::UnitX()) * Eigen::AngleAxisd(0.3, Vec3::UnitY());
  sc.view.distance = 0.15;
  sc.view.intersections = true;
  const SceneGeometry g = build_scene_geometry(sc, 1.0);
  const ScreenCrossings screen = screen_crossings(sc, g.camera);
  EXPECT_GT(screen.behind_eye, 0);
  EXPECT_LT(screen.behind_eye, static_cast<int>(k.components[0].points.size()));
  EXPECT_EQ(g.intersections.crossing_behind_eye, screen.behind_eye);
  EXPECT_NE(intersection_text(g.intersections).find("behind the eye"), std::string::npos);
  for (const ScreenCrossing& c : screen.crossings) {
    EXPECT_GT(g.camera.view_depth(c.under), g.camera.near_plane);
    EXPECT_GT(g.camera.view_depth(c.over), g.camera.near_plane);
  }
  expect_true_crossings(g.camera, k, screen.crossings);
}

// A strand that comes from behind the eye is cut at the near plane: the part in view still
// crosses. The eye is at (0, 0, 2) looking down -z (near plane 0.5); strand a runs from behind
// it to (0.6, 0, -2), strand b crosses its image at a = 0.3846 of the way (exactly: t = 5/13).
TEST(SceneGeometry, AStrandFromBehindTheEyeStillCrossesWhereItIsSeen) {
  const Camera cam = make_camera(BoundingSphere{Vec3::Zero(), 1.0}, Eigen::Quaterniond::Identity(),
                                 2.0, 35.0, 1.0);
  ASSERT_NEAR(cam.eye().z(), 2.0, 1e-12);
  ASSERT_NEAR(cam.near_plane, 0.5, 1e-12);
  Curve<3> c;
  c.components.push_back({{Vec3(0, 0, 3), Vec3(0.6, 0, -2)}, false});
  c.components.push_back({{Vec3(0.625, -1, -0.5), Vec3(0.625, 1, -0.5)}, false});
  const Scene sc = test::scene_of(c);
  const ScreenCrossings screen = screen_crossings(sc, cam);
  EXPECT_EQ(screen.behind_eye, 1);
  ASSERT_EQ(screen.crossings.size(), 1u);
  const Vec3 expected = Vec3(0, 0, 3) + (5.0 / 13.0) * Vec3(0.6, 0, -5);
  EXPECT_LT((screen.crossings[0].over - expected).norm(), 1e-9) << "strand a is nearer the eye";
  EXPECT_NEAR(screen.crossings[0].under.x(), 0.625, 1e-12);
  EXPECT_LT((screen.crossings[0].over_direction - Vec3(0.6, 0, -5).normalized()).norm(), 1e-12);
  EXPECT_LT((screen.crossings[0].under_direction - Vec3::UnitY()).norm(), 1e-12);
  expect_true_crossings(cam, c, screen.crossings);
}

TEST(SceneGeometry, EmptySceneHasAUsableCamera) {
  const SceneGeometry g = build_scene_geometry(Scene{}, 1.0);
  EXPECT_TRUE(g.objects.empty());
  EXPECT_TRUE(g.camera.view().allFinite());
  EXPECT_TRUE(g.camera.projection().allFinite());
}

// view.slice draws the slice w = c of the R^4 surfaces as one amber overlay over faded surfaces.
TEST(SceneGeometry, TheSliceIsDrawnOverFadedSurfaces) {
  Scene sc;
  SceneObject o;
  o.name = "torus";
  o.shape = clifford_torus(32, 32);
  sc.objects.push_back(o);
  sc.view.opacity = 0.8;
  const SceneGeometry off = build_scene_geometry(sc, 1.0);
  EXPECT_EQ(off.slice_components, -1);
  EXPECT_TRUE(off.overlays.empty());
  EXPECT_DOUBLE_EQ(drawn_opacity(sc.view), 0.8);
  sc.view.slice = true;
  sc.view.slice_level = 0.4;
  const SceneGeometry on = build_scene_geometry(sc, 1.0);
  EXPECT_EQ(on.slice_components, 2);  // two circles: sin v = 0.4
  ASSERT_EQ(on.overlays.size(), 1u);
  EXPECT_FALSE(on.overlays[0].surface);
  for (const Vec3f& c : on.overlays[0].colours) EXPECT_EQ(c, kSliceColour);
  EXPECT_DOUBLE_EQ(drawn_opacity(sc.view), kSliceFadeOpacity);
  sc.view.slice_fade = false;
  EXPECT_DOUBLE_EQ(drawn_opacity(sc.view), 0.8);
  sc.view.slice_level = 3;  // above the torus: nothing to draw
  const SceneGeometry above = build_scene_geometry(sc, 1.0);
  EXPECT_EQ(above.slice_components, 0);
  EXPECT_TRUE(above.overlays.empty());
}

}  // namespace
}  // namespace s4d
