// The one world builder: bodies in scene order, the dimension from the surfaces, clear refusals,
// and live settings that keep the state.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "scenario/world_builder.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

SceneObject object(const std::string& name, const std::string& generator, Params params) {
  SceneObject o;
  o.name = name;
  o.generator = GeneratorCall{generator, params};
  o.shape = generate(generator, params);
  return o;
}

std::string error_of(const Scene& s) {
  try {
    build_world<4>(s);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(WorldBuilder, BodiesFollowTheSceneAndCurvesAreSkipped) {
  Scene s;
  s.objects.push_back(object("knot", "torus-knot", {{"n", 40}}));
  s.objects.push_back(object("a", "sphere", {{"n", 6}}));
  SceneObject b = object("b", "sphere", {{"n", 6}});
  b.placement.offset = Vec4(5, 0, 0, 0);
  b.shape = placed(b.shape, b.placement);
  b.mass = 0.5;
  s.objects.push_back(b);
  EXPECT_EQ(simulation_dimension(s), 4);
  SceneWorld<4> w = build_world<4>(s);
  const int na = static_cast<int>(std::get<Surface<4>>(s.objects[1].shape).vertices.size());
  EXPECT_EQ(w.first, (std::vector<int>{-1, 0, na}));
  EXPECT_EQ(w.count[0], 0);
  EXPECT_EQ(w.world.vertex_count(), 2 * na);
  EXPECT_EQ(w.world.positions()[static_cast<std::size_t>(na)], std::get<Surface<4>>(b.shape).vertices[0]);
  EXPECT_EQ(w.world.model().mass[static_cast<std::size_t>(na)], 0.5);
  EXPECT_EQ(w.world.model().mass[0], s.physics.mass);
  EXPECT_EQ(w.object_of_vertex(na + 1), 2);
  std::vector<int> first, count;
  body_vertex_ranges(s, first, count);
  EXPECT_EQ(first, w.first);
  EXPECT_EQ(count, w.count);
}

TEST(WorldBuilder, DimensionFollowsTheSurfaces) {
  Scene s;
  EXPECT_EQ(simulation_dimension(s), 0);
  s.objects.push_back(object("r", "trefoil-ribbon-3d", {}));
  EXPECT_EQ(simulation_dimension(s), 3);
  EXPECT_NO_THROW(build_world<3>(s));
  s.objects.push_back(object("t", "clifford-torus", {{"n", 8}, {"m", 8}}));
  EXPECT_EQ(simulation_dimension(s), 4) << "one surface of R^4 takes the others along at w = 0";
  EXPECT_THROW(build_world<3>(s), Error);
}

// Without surfaces, the curves are the bodies (a knot is a chain): their points in order, moved
// back into the scene by copy_positions_into, rebuilt by apply_settings.
TEST(WorldBuilder, WithoutSurfacesTheCurvesAreTheBodies) {
  Scene s;
  s.objects.push_back(object("trefoil", "torus-knot", {{"n", 60}}));
  SceneObject far = object("ring", "torus-knot", {{"p", 1}, {"q", 1}, {"n", 30}});
  far.placement.offset = Vec4(10, 0, 0, 0);
  far.shape = placed(far.shape, far.placement);
  s.objects.push_back(far);
  EXPECT_EQ(surface_dimension(s), 0);
  EXPECT_TRUE(curves_are_bodies(s));
  EXPECT_EQ(simulation_dimension(s), 3);
  SceneWorld<3> w = build_world<3>(s);
  EXPECT_EQ(w.first, (std::vector<int>{0, 60}));
  EXPECT_EQ(w.count, (std::vector<int>{60, 30}));
  EXPECT_TRUE(w.world.model().curves());
  EXPECT_EQ(w.world.model().segments.size(), 90u);
  EXPECT_EQ(w.world.positions()[60], std::get<Curve<3>>(s.objects[1].shape).components[0].points[0]);
  std::vector<Vec3> x(w.world.positions().begin(), w.world.positions().end());
  for (Vec3& p : x) p += Vec3(0, 0, 1);
  Scene moved = s;
  copy_positions_into<3>(w, x, moved);
  EXPECT_EQ(std::get<Curve<3>>(moved.objects[1].shape).components[0].points[5], x[65]);
  PhysicsSettings stiffer = s.physics;
  stiffer.stiffness = 400;
  w.apply_settings(stiffer);
  EXPECT_EQ(w.world.model().springs[0].k, 400);
  // With a surface, curves are drawn but not simulated.
  s.objects.push_back(object("a", "sphere", {{"n", 6}}));
  EXPECT_FALSE(curves_are_bodies(s));
  EXPECT_EQ(build_world<4>(s).first, (std::vector<int>{-1, -1, 0}));
}

TEST(WorldBuilder, RefusalsSayWhatIsWrong) {
  Scene empty;
  EXPECT_NE(error_of(empty).find("no surface"), std::string::npos);

  Scene fan;  // three triangles on one edge: not a surface
  SceneObject o;
  o.name = "fan";
  Surface<4> m;
  m.vertices = {Vec4(0, 0, 0, 0), Vec4(1, 0, 0, 0), Vec4(0, 1, 0, 0), Vec4(0, -1, 0, 0), Vec4(0, 0, 1, 0)};
  m.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}};
  o.shape = m;
  fan.objects.push_back(o);
  EXPECT_NE(error_of(fan).find("cannot simulate 'fan': its edge between vertices 0 and 1 is shared by more than two"),
            std::string::npos)
      << error_of(fan);

  Scene twice;  // the same sphere twice, on top of itself
  twice.objects.push_back(object("a", "sphere", {{"n", 6}}));
  twice.objects.push_back(object("b", "sphere", {{"n", 6}}));
  EXPECT_NE(error_of(twice).find("intersects itself"), std::string::npos) << error_of(twice);

  Scene bad;
  bad.objects.push_back(object("a", "sphere", {{"n", 6}}));
  bad.physics.integrator = "runge-kutta";
  EXPECT_NE(error_of(bad).find("unknown integrator 'runge-kutta'"), std::string::npos) << error_of(bad);
}

TEST(WorldBuilder, SettingsApplyLiveKeepingTheState) {
  Scene s;
  s.objects.push_back(object("c", "cloth", {{"n", 6}, {"size", 1}}));
  s.physics.gravity = Vec4(0, -9.81, 0, 0);
  SceneWorld<4> w = build_world<4>(s);
  w.world.pin(0);
  for (int i = 0; i < 50; ++i) w.world.step();
  const std::vector<Vec4> x(w.world.positions().begin(), w.world.positions().end());
  const std::vector<Vec4> initial = w.world.model().initial;
  PhysicsSettings p = s.physics;
  p.stiffness = 400;
  p.gravity = Vec4(0, 0, 0, -2);
  w.apply_settings(p);
  EXPECT_EQ(std::vector<Vec4>(w.world.positions().begin(), w.world.positions().end()), x);
  EXPECT_EQ(w.world.model().initial, initial) << "a reset still goes back to the start";
  EXPECT_TRUE(w.world.is_pinned(0));
  EXPECT_EQ(w.world.model().params.gravity, Vec4(0, 0, 0, -2));
  EXPECT_EQ(w.world.model().springs[0].k, 400);
  p.thickness = -1;
  EXPECT_THROW(w.apply_settings(p), Error);
  EXPECT_EQ(w.world.model().springs[0].k, 400) << "a refused setting changes nothing";
}

}  // namespace
}  // namespace s4d
