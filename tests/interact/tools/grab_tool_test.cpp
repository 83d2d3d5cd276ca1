// Picking and the grab tool on a headless Session: every sheet under the cursor is found in
// order, Tab reaches each, and a press holds the vertex of the sheet chosen.
#include <gtest/gtest.h>

#include <algorithm>

#include "interact/tools/grab_tool.hpp"
#include "view/pick.hpp"
#include "interact/session/session.hpp"
#include "view/view_crossings.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

// Two unit squares in the plane z = 0 of the shadow, apart in w (one at w = +0.5, one at -0.5):
// the shadow folds them onto each other, the surface does not meet itself.
Scene two_sheets() {
  Scene s;
  for (int k = 0; k < 2; ++k) {
    SceneObject o;
    o.name = k == 0 ? "upper" : "lower";
    Surface<4> c = std::get<Surface<4>>(generate("cloth", {{"n", 5}, {"size", 1}}));
    for (Vec4& p : c.vertices) {
      p.w() = k == 0 ? 0.5 : -0.5;
      p.z() = k == 0 ? 0.2 : -0.2;  // and apart along the line of sight too: one is nearer the eye
    }
    o.shape = c;
    s.objects.push_back(o);
  }
  return s;
}

TEST(Pick, EverySheetUnderTheRayNearestFirstOneHitEach) {
  const Scene s = two_sheets();
  // Straight down the z axis through (0.1, 0.1): both squares.
  const std::vector<SheetHit> hits = pick_sheets(s, Vec3(0.1, 0.1, 5), Vec3(0, 0, -1));
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].object, 0) << "the upper square is nearer the eye (z = 0.2)";
  EXPECT_NEAR(hits[0].distance, 4.8, 1e-12);
  EXPECT_NEAR(hits[0].w, 0.5, 1e-12);
  EXPECT_EQ(hits[1].object, 1);
  EXPECT_NEAR(hits[1].w, -0.5, 1e-12);
  // Through a grid vertex (0, 0) six triangles meet: still one hit a sheet, at that vertex.
  const std::vector<SheetHit> at_vertex = pick_sheets(s, Vec3(0, 0, 5), Vec3(0, 0, -1));
  ASSERT_EQ(at_vertex.size(), 2u);
  const auto& v = std::get<Surface<4>>(s.objects[0].shape).vertices[static_cast<std::size_t>(at_vertex[0].vertex)];
  EXPECT_NEAR(v.x(), 0, 1e-12);
  EXPECT_NEAR(v.y(), 0, 1e-12);
  EXPECT_TRUE(pick_sheets(s, Vec3(3, 3, 5), Vec3(0, 0, -1)).empty());
  EXPECT_TRUE(pick_sheets(s, Vec3(0, 0, 5), Vec3(0, 0, 0)).empty()) << "no direction, no hit";
}

TEST(Pick, ObjectsOfR4AreSeenThroughTheFrame) {
  Scene s = two_sheets();
  s.frame.rotate(Plane{2, 3}, 1.5707963267948966);  // zw: the view's z is now the world's -w
  const std::vector<SheetHit> hits = pick_sheets(s, Vec3(0.1, 0.1, 5), Vec3(0, 0, -1));
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(std::abs(hits[0].point.z()), 0.5, 1e-12) << "the sheets are now 1 apart along the line of sight";
}

// Issue 34: the same pixel gives the same vertex. The hits do not depend on the order the mesh
// lists its triangles (or their corners) in, and the vertex taken is the hit triangle's corner
// nearest the hit, on the Clifford torus seen as the pinch scenario sees it (its shadow folds
// two and four sheets onto each other).
TEST(Pick, TheSameRayGivesTheSameSheetsWhateverTheMeshsOrder) {
  Scene a;
  SceneObject o;
  o.name = "torus";
  o.shape = generate("clifford-torus", {{"n", 24}, {"m", 24}});
  a.objects.push_back(o);
  a.frame.rotate(Plane{2, 3}, 1.5707963267948966);
  a.frame.rotate(Plane{1, 3}, 0.2617993877991494);
  Scene b = a;
  auto& tris = std::get<Surface<4>>(b.objects[0].shape).triangles;
  std::reverse(tris.begin(), tris.end());
  for (auto& t : tris) std::rotate(t.begin(), t.begin() + 1, t.end());
  const auto& p = std::get<Surface<4>>(a.objects[0].shape).vertices;
  int rays = 0, layered = 0;
  for (double x = -1.4; x <= 1.4; x += 0.1)
    for (double y = -1.4; y <= 1.4; y += 0.1) {
      const Vec3 eye(x, y, 6), dir(0.01, -0.02, -1);
      const auto ha = pick_sheets(a, eye, dir), hb = pick_sheets(b, eye, dir), again = pick_sheets(a, eye, dir);
      ASSERT_EQ(ha.size(), hb.size());
      ASSERT_EQ(ha.size(), again.size());
      rays += !ha.empty();
      layered += ha.size() > 1;
      for (std::size_t i = 0; i < ha.size(); ++i) {
        EXPECT_EQ(ha[i].vertex, hb[i].vertex) << x << " " << y << " hit " << i;
        EXPECT_EQ(ha[i].vertex, again[i].vertex);
        EXPECT_NEAR(ha[i].distance, hb[i].distance, 1e-9);
        if (i > 0) {
          EXPECT_LE(ha[i - 1].distance, ha[i].distance) << "nearest the eye first";
        }
        const Vec3 at = a.frame.to_view(p[static_cast<std::size_t>(ha[i].vertex)]).head<3>();
        for (int c : std::get<Surface<4>>(a.objects[0].shape).triangles[static_cast<std::size_t>(ha[i].triangle)]) {
          const Vec3 q = a.frame.to_view(p[static_cast<std::size_t>(c)]).head<3>();
          EXPECT_LE((at - ha[i].point).norm(), (q - ha[i].point).norm() + 1e-12) << "the nearest corner";
        }
      }
    }
  EXPECT_GT(rays, 150);
  EXPECT_GT(layered, 100) << "most rays cross several sheets";
}

// Issue 37: the Clifford torus in a generic 4D view, seen in perspective from a 4D eye at w = d.
Scene perspective_torus(double d) {
  Scene s;
  SceneObject o;
  o.name = "torus";
  o.shape = generate("clifford-torus", {{"n", 16}, {"m", 16}});
  s.objects.push_back(o);
  s.frame.rotate(Plane{0, 3}, 0.5);   // xw
  s.frame.rotate(Plane{2, 3}, 0.35);  // zw
  if (d > 0) s.frame.set_perspective(d);
  return s;
}

// The vertex of R^4 nearest p, by brute force.
int nearest_vertex(const Surface<4>& s, const Vec4& p) {
  int best = -1;
  for (int v = 0; v < static_cast<int>(s.vertices.size()); ++v)
    if (best < 0 || (s.vertices[static_cast<std::size_t>(v)] - p).norm() < (s.vertices[static_cast<std::size_t>(best)] - p).norm())
      best = v;
  return best;
}

// In perspective, the ray from the eye through where a vertex is drawn hits its sheet at that
// vertex, and the hit lifted back to R^4 is the vertex (the nearest one, by brute force).
TEST(Pick, InPerspectiveTheRayThroughAVertexsShadowHitsThatVertex) {
  const Scene s = perspective_torus(2.5);
  const Surface<4>& t = std::get<Surface<4>>(s.objects[0].shape);
  const Vec3 eye(0.2, -0.1, 6);
  int checked = 0, magnified = 0;
  for (std::size_t v = 0; v < t.vertices.size(); v += 3) {
    const Vec3 at = s.frame.shadow(t.vertices[v]);
    const double w = s.frame.depth(t.vertices[v]);
    magnified += std::abs(s.frame.magnification(w) - 1) > 0.1;
    const std::vector<SheetHit> hits = pick_sheets(s, eye, at - eye);
    const auto it = std::find_if(hits.begin(), hits.end(), [&](const SheetHit& h) {
      return std::abs(h.distance - (at - eye).norm()) < 1e-9 && std::abs(h.w - w) < 1e-9;
    });
    ASSERT_NE(it, hits.end()) << "vertex " << v << ": no sheet at its shadow";
    EXPECT_EQ(it->vertex, static_cast<int>(v));
    const Vec4 back = s.frame.to_world(s.frame.lift(it->point, it->w));
    EXPECT_LT((back - t.vertices[v]).norm(), 1e-9) << v;
    EXPECT_EQ(nearest_vertex(t, back), static_cast<int>(v));
    ++checked;
  }
  EXPECT_GT(checked, 80);
  EXPECT_GT(magnified, 20) << "the perspective must matter for the test to mean something";
}

// A point inside a triangle of R^4 comes back from its pixel: the depth read off the shadow is
// perspective-correct (a linear reading of w would miss it by a few hundredths here).
TEST(Pick, InPerspectiveAPointOfATriangleComesBackFromItsShadow) {
  const Scene s = perspective_torus(2.0);
  const Surface<4>& t = std::get<Surface<4>>(s.objects[0].shape);
  const Vec3 eye(0, 0, 6);
  double worst = 0;
  for (std::size_t k = 0; k < t.triangles.size(); k += 5) {
    const Triangle& tri = t.triangles[k];
    const Vec4 p = 0.2 * t.vertices[static_cast<std::size_t>(tri[0])] + 0.3 * t.vertices[static_cast<std::size_t>(tri[1])] +
                   0.5 * t.vertices[static_cast<std::size_t>(tri[2])];
    const Vec3 at = s.frame.shadow(p);
    const std::vector<SheetHit> hits = pick_sheets(s, eye, at - eye);
    const auto it = std::find_if(hits.begin(), hits.end(), [&](const SheetHit& h) { return h.triangle == static_cast<int>(k); });
    ASSERT_NE(it, hits.end()) << "triangle " << k;
    EXPECT_NEAR(it->w, s.frame.depth(p), 1e-9);
    worst = std::max(worst, (s.frame.to_world(s.frame.lift(it->point, it->w)) - p).norm());
  }
  EXPECT_LT(worst, 1e-9);
}

// Far away the perspective picks what the orthographic shadow picks.
TEST(Pick, AFarPerspectivePicksAsTheOrthographicShadow) {
  Scene far = perspective_torus(1e6), ortho = far;
  ortho.frame.set_orthographic();
  for (double x = -1.2; x <= 1.2; x += 0.3)
    for (double y = -1.2; y <= 1.2; y += 0.3) {
      const Vec3 eye(x, y, 6), dir(0.01, -0.02, -1);
      const auto a = pick_sheets(far, eye, dir), b = pick_sheets(ortho, eye, dir);
      ASSERT_EQ(a.size(), b.size()) << x << " " << y;
      for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].vertex, b[i].vertex);
        EXPECT_NEAR(a[i].w, b[i].w, 1e-5);
      }
    }
}

// A press where a vertex is drawn in perspective holds that vertex, and a drag moves its shadow
// with the hand: the hand's point in the shadow is lifted to the vertex's own depth (a hand taken
// as view coordinates would leave it off by the magnification, here a quarter of the way).
TEST(GrabTool, InPerspectiveAPressHoldsTheVertexUnderTheCursorAndItsShadowFollows) {
  for (double d_eye : {0.0, 2.5}) {
  SCOPED_TRACE(d_eye);
  Document d;
  d.scene = perspective_torus(d_eye);
  SessionOptions o;
  o.threaded = false;
  o.async_physics = false;
  Session session;
  session.open(std::move(d), o);
  ASSERT_TRUE(session.simulating()) << session.physics_error();
  session.loop()->run_ticks(1);
  session.refresh();
  const Scene& s = session.scene();
  const Surface<4>& t = std::get<Surface<4>>(s.objects[0].shape);
  const Vec3 eye(0.1, 0.05, 6);
  // A vertex drawn in front of every other sheet at its pixel, well off w = 0 (magnified).
  int v = -1;
  for (int c = 0; c < static_cast<int>(t.vertices.size()) && v < 0; ++c) {
    const Vec3 at = session.vertex_shadow(c);
    const double w = s.frame.depth(t.vertices[static_cast<std::size_t>(c)]);
    const auto hits = pick_sheets(s, eye, at - eye);
    if (!hits.empty() && hits[0].vertex == c && (d_eye == 0 || std::abs(s.frame.magnification(w) - 1) > 0.2)) v = c;
  }
  ASSERT_GE(v, 0);
  const Vec3 at = session.vertex_shadow(v);
  ToolInput in;
  in.view.eye = eye;
  in.view.ray = (at - eye).normalized();
  in.view.cursor = Vec2(100, 100);
  GrabTool tool;
  tool.hover(in, session);
  session.loop()->run_ticks(500);  // the mouse's proxy comes to rest under the cursor, as a person's would
  session.refresh();
  ASSERT_TRUE(tool.press(in, session));
  session.loop()->run_ticks(2);
  session.refresh();
  ASSERT_EQ(session.snapshot()->status.held_vertex, v) << "the vertex under the cursor";
  // The cursor moves; the hand goes to where its ray meets the drag plane through the vertex.
  const Vec3 to = at + Vec3(0.12, -0.08, 0);
  in.view.ray = (to - eye).normalized();
  for (int k = 0; k < 40; ++k) {
    tool.drag(in, session);
    session.loop()->run_ticks(50);
    session.refresh();
  }
  const Vec3 now = session.vertex_shadow(v);
  EXPECT_LT((now - to).norm(), 0.25 * (to - at).norm()) << "the vertex's shadow went to the hand: " << now.transpose()
                                                         << " for " << to.transpose() << " from " << at.transpose()
                                                         << " w " << s.frame.depth(std::get<Surface<4>>(s.objects[0].shape).vertices[v]);
  tool.release(in, session);
  }
}

TEST(GrabTool, TabReachesEverySheetAndThePressHoldsTheChosenOne) {
  Document d;
  d.scene = two_sheets();
  SessionOptions o;
  o.threaded = false;
  o.async_physics = false;
  Session session;
  session.open(std::move(d), o);
  ASSERT_TRUE(session.simulating()) << session.physics_error();
  session.loop()->run_ticks(1);
  session.refresh();

  ToolInput in;
  in.view.eye = Vec3(0.1, 0.1, 5);
  in.view.ray = Vec3(0, 0, -1);
  in.view.cursor = Vec2(100, 100);
  GrabTool tool;
  tool.hover(in, session);
  ASSERT_EQ(tool.hits().size(), 2u);
  EXPECT_EQ(tool.sheet(), 0);
  tool.key(ToolKey::kTab, in, session);
  EXPECT_EQ(tool.sheet(), 1);
  tool.hover(in, session);
  EXPECT_EQ(tool.sheet(), 1) << "the choice holds while the cursor stays";
  tool.key(ToolKey::kTab, in, session);
  EXPECT_EQ(tool.sheet(), 0) << "and wraps round";
  tool.key(ToolKey::kTab, in, session);
  ASSERT_TRUE(tool.press(in, session));
  session.loop()->run_ticks(2);
  session.refresh();
  const int held = session.snapshot()->status.held_vertex;
  EXPECT_EQ(session.object_of_vertex(held), 1) << "the lower sheet, chosen with Tab";
  tool.release(in, session);
  session.loop()->run_ticks(1);
  session.refresh();
  EXPECT_EQ(session.snapshot()->status.held_vertex, -1);

  // P pins the vertex under the cursor; again unpins it.
  tool.hover(in, session);
  tool.key(ToolKey::kPin, in, session);
  session.loop()->run_ticks(1);
  session.refresh();
  EXPECT_EQ(session.snapshot()->status.pinned, 1);
  tool.key(ToolKey::kPin, in, session);
  session.loop()->run_ticks(1);
  session.refresh();
  EXPECT_EQ(session.snapshot()->status.pinned, 0);

  // Away from the surfaces a press is no grab: the view turns instead.
  in.view.eye = Vec3(4, 4, 5);
  EXPECT_FALSE(tool.press(in, session));
}

// Issue 34: a press takes the sheet nearest the eye, the same every time at the same pixel; Tab
// chooses another for the next press only, and the status says which of how many it is.
TEST(GrabTool, APressTakesTheNearestSheetEveryTimeAndTabChoosesForOnePress) {
  Document d;
  d.scene = two_sheets();
  SessionOptions o;
  o.threaded = false;
  o.async_physics = false;
  Session session;
  session.open(std::move(d), o);
  ASSERT_TRUE(session.simulating()) << session.physics_error();
  session.loop()->run_ticks(1);
  session.refresh();
  ToolInput in;
  in.view.eye = Vec3(0.1, 0.1, 5);
  in.view.ray = Vec3(0, 0, -1);
  in.view.cursor = Vec2(100, 100);
  ToolInput away = in;
  away.view.eye = Vec3(-0.3, 0.2, 5);
  away.view.cursor = Vec2(60, 110);
  GrabTool tool;
  auto press_and_release = [&](const ToolInput& at) {
    EXPECT_TRUE(tool.press(at, session));
    session.loop()->run_ticks(2);
    session.refresh();
    const int held = session.snapshot()->status.held_vertex;
    tool.release(at, session);
    session.loop()->run_ticks(1);
    session.refresh();
    return held;
  };
  const int first = press_and_release(in);
  EXPECT_EQ(session.object_of_vertex(first), 0) << "the upper sheet, nearer the eye";
  for (int k = 0; k < 3; ++k) {
    tool.hover(away, session);
    tool.key(ToolKey::kTab, away, session);  // a choice made elsewhere is not this pixel's
    tool.hover(in, session);
    EXPECT_EQ(press_and_release(in), first) << "the same vertex every time at the same pixel";
  }
  tool.hover(in, session);
  EXPECT_NE(tool.help().find("sheet 1 of 2 under the cursor"), std::string::npos) << tool.help();
  tool.key(ToolKey::kTab, in, session);
  EXPECT_NE(tool.take_message().find("sheet 2 of 2 under the cursor"), std::string::npos);
  EXPECT_NE(tool.help().find("sheet 2 of 2 under the cursor"), std::string::npos) << tool.help();
  const int lower = press_and_release(in);
  EXPECT_EQ(session.object_of_vertex(lower), 1) << "Tab chose the lower sheet for this press";
  EXPECT_EQ(press_and_release(in), first) << "and the next press takes the nearest again";
}

// A knot's strands are picked on the screen: within a few pixels of the cursor, one hit a strand,
// the nearer first where two cross; the press holds the strand's point (a chain in World<3>).
TEST(GrabTool, AKnotsStrandIsTakenUnderTheCursorTheNearerFirst) {
  Document d;
  SceneObject o;
  o.name = "trefoil";
  o.shape = generate("torus-knot", {{"n", 120}});
  d.scene.objects.push_back(o);
  SessionOptions opt;
  opt.threaded = false;
  opt.async_physics = false;
  Session session;
  session.open(std::move(d), opt);
  ASSERT_TRUE(session.simulating()) << session.physics_error();
  session.loop()->run_ticks(1);
  session.refresh();

  ToolInput in;
  in.view.camera.distance = 10;
  in.view.camera.aspect = 1;
  in.view.window = Vec2(400, 400);
  in.view.eye = in.view.camera.eye();
  const auto& pts = std::get<Curve<3>>(session.scene().objects[0].shape).components[0].points;
  auto pixel = [&](const Vec3& p) {
    const Vec2 n = in.view.camera.ndc(p);
    return Vec2((n.x() + 1) / 2 * 400, (1 - n.y()) / 2 * 400);
  };
  // Point 7, between crossings: one strand under the cursor.
  in.view.cursor = pixel(pts[7]) + Vec2(3, 0);
  in.view.ray = (in.view.camera.eye() - pts[7]).normalized() * -1;
  GrabTool tool;
  tool.hover(in, session);
  ASSERT_EQ(tool.hits().size(), 1u);
  EXPECT_NEAR(tool.hits()[0].vertex, 7, 1);
  EXPECT_TRUE(pick_strands(session.scene(), in.view.camera, pixel(Vec3::Zero()), in.view.window, 10).empty())
      << "nothing in the hole of the knot";
  // A crossing of the view: both strands, the nearer the eye first.
  const ScreenCrossings crossings = screen_crossings(session.scene(), in.view.camera);
  ASSERT_EQ(crossings.crossings.size(), 3u);
  in.view.cursor = pixel(crossings.crossings[0].over);
  tool.hover(in, session);
  ASSERT_EQ(tool.hits().size(), 2u);
  EXPECT_LT(tool.hits()[0].distance, tool.hits()[1].distance);
  ASSERT_TRUE(tool.press(in, session));
  session.loop()->run_ticks(2);
  session.refresh();
  const int held = session.snapshot()->status.held_vertex;
  EXPECT_EQ(held, tool.hits()[0].vertex) << "the nearer strand's point";
  EXPECT_GT(pts[static_cast<std::size_t>(held)].z(), pts[static_cast<std::size_t>(tool.hits()[1].vertex)].z());
  tool.release(in, session);
}

TEST(Session, AScenePhysicsCannotRunStaysViewable) {
  Document d;
  d.scene = two_sheets();
  std::get<Surface<4>>(d.scene.objects[1].shape).vertices = std::get<Surface<4>>(d.scene.objects[0].shape).vertices;
  SessionOptions o;
  o.threaded = false;
  Session session;
  session.open(std::move(d), o);
  EXPECT_FALSE(session.simulating());
  EXPECT_NE(session.physics_error().find("intersects itself"), std::string::npos) << session.physics_error();
  EXPECT_EQ(session.scene().objects.size(), 2u) << "the document is kept";
  session.refresh();  // harmless without a simulation
  EXPECT_EQ(session.snapshot(), nullptr);
}

TEST(Session, ADeviceThatCannotOpenFallsBackToTheMouse) {
  Document d;
  d.scene = two_sheets();
  SessionOptions o;
  o.threaded = false;
  o.device = "replay:/nonexistent/trajectory.txt";
  Session session;
  session.open(std::move(d), o);
  EXPECT_TRUE(session.simulating());
  EXPECT_NE(session.device_error().find("using the mouse"), std::string::npos) << session.device_error();
  EXPECT_EQ(session.device_spec(), "mouse");
}

}  // namespace
}  // namespace s4d
