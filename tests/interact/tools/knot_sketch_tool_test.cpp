// The window's sketch tool without a window: cursor pixels map onto the sketch plane exactly as
// the camera draws it, and a stroke drawn through the camera becomes its knot where it was drawn.
#include "interact/tools/knot_sketch_tool.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "knots/knot_identify.hpp"

namespace s4d {
namespace {

const Vec2 kWindow(800, 600);

Camera turned_camera() {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.6, Vec3(1, 2, 0.5).normalized()));
  return make_camera(BoundingSphere{Vec3(0.3, -0.2, 1.0), 2.0}, q, 0, 40, kWindow.x() / kWindow.y(), 1.2);
}

// Window pixels (y down) of a point, through the camera's own matrices.
Vec2 pixel_of(const Camera& c, const Vec3& p) {
  const Eigen::Vector4d clip = c.projection() * c.view() * p.homogeneous();
  const Vec2 ndc = clip.head<2>() / clip.w();
  return Vec2((ndc.x() + 1) / 2 * kWindow.x(), (1 - ndc.y()) / 2 * kWindow.y());
}

TEST(SketchTool, CursorPixelsLandOnThePlaneWhereTheCameraDrawsThem) {
  const Camera c = turned_camera();
  const SketchPlane plane(c);
  for (const Vec2& local : {Vec2(0, 0), Vec2(0.7, -0.4), Vec2(-1.1, 0.9)}) {
    const Vec3 p = plane.to_shadow(Vec3(local.x(), local.y(), 0));
    Vec2 at;
    ASSERT_TRUE(plane.cursor_to_plane(c, pixel_of(c, p), kWindow, at));
    EXPECT_LT((at - local).norm(), 1e-9);
  }
  Vec2 at;
  EXPECT_FALSE(plane.cursor_to_plane(c, Vec2(1, 1), Vec2(0, 0), at)) << "no window";
}

// The trefoil's shadow drawn through the camera, with shift held where it passes under.
void draw_trefoil(SketchTool& tool, const Camera& c, double scale) {
  const SketchPlane plane(c);
  const int n = 240;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * 0.99 * i / (n - 1);
    const Vec3 local(scale * (std::sin(t) + 2 * std::sin(2 * t)), scale * (std::cos(t) - 2 * std::cos(2 * t)), 0);
    const Vec2 px = pixel_of(c, plane.to_shadow(local));
    const bool under = -std::sin(3 * t) < 0;
    if (i == 0) tool.begin(c, px, kWindow, 10.0, under);
    else tool.add(px, kWindow, 10.0 + i / 120.0, under);
  }
}

TEST(SketchTool, AStrokeBecomesItsKnotWhereItWasDrawn) {
  const Camera c = turned_camera();
  SketchTool tool;
  draw_trefoil(tool, c, 0.3);
  EXPECT_TRUE(tool.drawing());
  ASSERT_EQ(tool.screen().size(), 240u);
  std::vector<Vec2> tool_screen;
  for (const auto& s : tool.screen()) tool_screen.push_back(s.first);
  const Curve<3> k = tool.finish();
  EXPECT_FALSE(tool.drawing());
  EXPECT_EQ(identify_knot(k).name, "3_1 (DT 3a_1)");
  // Objects of R^3 are drawn as they are: the knot lies where it was drawn, and each point falls
  // near the stroke on the screen.
  const SketchPlane plane(c);
  for (const Vec3& p : k.components[0].points) {
    EXPECT_LT(std::abs((p - plane.centre).dot(plane.toward_eye)), 0.2) << "near the sketch plane";
    EXPECT_LT((p - plane.centre).norm(), 0.3 * 3.2) << "within the drawing";
    double best = 1e9;
    for (const auto& s : tool_screen) best = std::min(best, (s - pixel_of(c, p)).norm());
    EXPECT_LT(best, 12.0) << "pixels from the stroke";
  }
}

TEST(SketchTool, AClickIsNoStroke) {
  SketchTool tool;
  const Camera c = turned_camera();
  tool.begin(c, Vec2(400, 300), kWindow, 0.0, false);
  tool.add(Vec2(400, 300), kWindow, 0.1, false);
  EXPECT_EQ(tool.screen().size(), 1u) << "a sample where the last one was is not kept";
  EXPECT_THROW(tool.finish(), Error);
  EXPECT_FALSE(tool.drawing());
}

}  // namespace
}  // namespace s4d

#include "interact/session/session.hpp"

namespace s4d {
namespace {

// The same stroke through the Tool type, as the window (or its input file) drives it: the knot
// joins the session's scene, its crossings shown.
TEST(CursorKnotSketchTool, PressDragReleaseAddsTheKnotToTheScene) {
  Session session;  // an empty document: nothing to simulate, knots are curves
  session.open(Document{}, SessionOptions{});
  const Camera c = turned_camera();
  const SketchPlane plane(c);
  CursorKnotSketchTool tool;
  ToolInput in;
  in.view.camera = c;
  in.view.window = kWindow;
  const int n = 240;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * 0.99 * i / (n - 1);
    const Vec3 local(0.3 * (std::sin(t) + 2 * std::sin(2 * t)), 0.3 * (std::cos(t) - 2 * std::cos(2 * t)), 0);
    in.view.cursor = pixel_of(c, plane.to_shadow(local));
    in.shift = -std::sin(3 * t) < 0;
    in.time = i / 120.0;
    if (i == 0) ASSERT_TRUE(tool.press(in, session));
    else tool.drag(in, session);
  }
  Overlay o;
  tool.overlay(o, session);
  EXPECT_EQ(o.screen_lines.size(), static_cast<std::size_t>(n - 1)) << "the stroke is drawn as it goes";
  tool.release(in, session);
  ASSERT_EQ(session.scene().objects.size(), 1u);
  EXPECT_EQ(session.scene().objects[0].name, "sketch-1");
  EXPECT_TRUE(session.scene().view.intersections);
  EXPECT_EQ(identify_knot(std::get<Curve<3>>(session.scene().objects[0].shape)).name, "3_1 (DT 3a_1)");
  EXPECT_TRUE(tool.has_last_stroke());
  EXPECT_EQ(tool.last_stroke_curve().point_count(), static_cast<std::size_t>(n));
  // A click makes nothing, and says so.
  in.view.cursor = Vec2(400, 300);
  tool.press(in, session);
  tool.release(in, session);
  EXPECT_EQ(session.scene().objects.size(), 1u);
  EXPECT_NE(tool.take_message().find("a click is not a stroke"), std::string::npos);
}

}  // namespace
}  // namespace s4d
