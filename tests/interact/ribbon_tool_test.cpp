// The ribbon tool on a headless Session: a stroke through a sphere's shadow, shift held on the
// way out, becomes a ribbon passing above then below in w, added to the scene and simulated.
#include <gtest/gtest.h>

#include "interact/ribbon_tool.hpp"
#include "interact/session.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

void sphere_session(Session& s) {
  Document d;
  SceneObject o;
  o.name = "sphere";
  o.generator = GeneratorCall{"sphere", {{"n", 12}, {"radius", 0.5}}};
  o.shape = generate("sphere", o.generator->params);
  d.scene.objects.push_back(o);
  SessionOptions opt;
  opt.threaded = false;
  opt.async_physics = false;
  s.open(std::move(d), opt);

}

TEST(RibbonTool, AStrokeThroughASphereIsThreadedAboveThenBelow) {
  Session s;
  sphere_session(s);
  ASSERT_TRUE(s.simulating()) << s.physics_error();
  RibbonTool tool;
  tool.options.width = 0.1;
  ToolInput in;
  in.view.eye = Vec3(-1, 0.2, 5);
  in.view.ray = Vec3(0, 0, -1);
  in.view.centre = Vec3::Zero();
  in.view.window = Vec2(800, 600);
  in.view.pixel_size = 0.005;
  ASSERT_TRUE(tool.press(in, s));
  for (int i = 1; i <= 100; ++i) {
    in.view.eye = Vec3(-1 + 0.02 * i, 0.2, 5);
    in.time = 0.01 * i;
    in.shift = in.view.eye.x() > 0;  // below on the way out
    tool.drag(in, s);
  }
  tool.release(in, s);
  ASSERT_NE(tool.last(), nullptr) << tool.take_message();
  const SketchedRibbon& r = *tool.last();
  ASSERT_EQ(r.passages.size(), 2u);
  EXPECT_FALSE(r.passages[0].below);
  EXPECT_TRUE(r.passages[1].below);
  EXPECT_LT(r.passages[0].place.x(), 0);
  EXPECT_GT(r.passages[1].place.x(), 0);
  ASSERT_EQ(s.scene().objects.size(), 2u);
  EXPECT_EQ(s.scene().objects[1].name, "ribbon");
  EXPECT_TRUE(s.simulating()) << "the simulation restarted with the ribbon: " << s.physics_error();
  EXPECT_GE(s.first_vertex(1), 0) << "the ribbon is a body";
  EXPECT_NE(tool.take_message().find("1 above and 1 below"), std::string::npos);
}

TEST(RibbonTool, AClickIsNoRibbonAndBadStrokesSayWhy) {
  Session s;
  sphere_session(s);
  RibbonTool tool;
  ToolInput in;
  in.view.ray = Vec3(0, 0, -1);
  tool.press(in, s);
  tool.release(in, s);
  EXPECT_EQ(tool.last(), nullptr);
  EXPECT_NE(tool.take_message().find("a click is not a stroke"), std::string::npos);
  EXPECT_EQ(s.scene().objects.size(), 1u);
}

}  // namespace
}  // namespace s4d
