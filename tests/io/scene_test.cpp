// Scene JSON: defaults, every section, frame rotations, paths relative to the scene, errors, and
// save -> load round trips (generated, loaded and edited objects).
#include "io/scene.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "io/off.hpp"
#include "io_test_util.hpp"

namespace s4d {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Scene, MinimalSceneTakesDefaults) {
  const Scene s = parse_scene(R"({"version": 1})", "mem.json");
  EXPECT_TRUE(s.objects.empty());
  EXPECT_EQ(s.frame.matrix(), Mat<4>::Identity());
  const ViewSettings v;
  EXPECT_EQ(s.view.fov_deg, v.fov_deg);
  EXPECT_EQ(s.view.colour_map, v.colour_map);
  EXPECT_EQ(s.physics.time_step, PhysicsSettings{}.time_step);
  EXPECT_EQ(s.physics.integrator, "symplectic-euler");
}

TEST(Scene, GeneratedObjectWithOffsetAndColour) {
  const Scene s = parse_scene(R"({"version": 1, "objects": [
      {"name": "ball", "generator": "sphere", "params": {"n": 8, "radius": 2},
       "offset": [1, 2, 3, 4], "colour": [0.5, 0.25, 1]}]})",
                              "mem.json");
  ASSERT_EQ(s.objects.size(), 1u);
  const SceneObject& o = s.objects[0];
  EXPECT_EQ(o.name, "ball");
  ASSERT_TRUE(o.generator.has_value());
  EXPECT_EQ(o.generator->name, "sphere");
  EXPECT_EQ(o.generator->params.at("n"), 8);
  EXPECT_EQ(o.placement.offset, Vec4(1, 2, 3, 4));
  ASSERT_TRUE(o.colour.has_value());
  EXPECT_EQ(*o.colour, Vec3f(0.5f, 0.25f, 1.0f));
  const auto ref = std::get<Surface<4>>(generate("sphere", {{"n", 8}, {"radius", 2}}));
  const auto& got = std::get<Surface<4>>(o.shape);
  ASSERT_EQ(got.vertices.size(), ref.vertices.size());
  for (std::size_t i = 0; i < ref.vertices.size(); ++i)
    EXPECT_EQ(got.vertices[i], ref.vertices[i] + Vec4(1, 2, 3, 4));
  EXPECT_EQ(got.triangles, ref.triangles);
}

TEST(Scene, OffsetWithWLiftsAnR3Object) {
  const Scene s = parse_scene(
      R"({"version": 1, "objects": [{"generator": "torus-knot", "offset": [0, 0, 0, 0.5]},
                                    {"generator": "torus-knot", "offset": [1, 0, 0]}]})",
      "mem.json");
  ASSERT_TRUE(std::holds_alternative<Curve<4>>(s.objects[0].shape));
  EXPECT_EQ(std::get<Curve<4>>(s.objects[0].shape).components[0].points[0].w(), 0.5);
  EXPECT_TRUE(std::holds_alternative<Curve<3>>(s.objects[1].shape));
  EXPECT_EQ(s.objects[0].name, "torus-knot");
  EXPECT_EQ(s.objects[1].name, "torus-knot-2");  // default names are made unique
}

TEST(Scene, DuplicateNamesAreRejected) {
  test::expect_parse_error([] {
    parse_scene(R"({"version": 1, "objects": [{"name": "a", "generator": "sphere", "params": {"n": 4}},
                                              {"name": "a", "generator": "sphere", "params": {"n": 4}}]})",
                "dup.json");
  }, 0, "duplicate object name 'a'");
}

TEST(Scene, RotationsApplyInTheOrderWritten) {
  Frame<4> expect;
  expect.rotate(*parse_plane("xy", 4), kPi / 2);
  expect.rotate(*parse_plane("xw", 4), kPi / 6);
  const Scene a = parse_scene(R"({"version": 1, "frame": {"rotate": {"xy": 90, "xw": 30}}})", "a.json");
  EXPECT_LT((a.frame.matrix() - expect.matrix()).norm(), 1e-12);
  const Scene b = parse_scene(R"({"version": 1, "frame": {"rotate": {"xw": 30, "xy": 90}}})", "b.json");
  EXPECT_GT((b.frame.matrix() - a.frame.matrix()).norm(), 0.1);
  // "wx" is the same plane turning the other way.
  const Scene c = parse_scene(R"({"version": 1, "frame": {"rotate": {"wx": -30}}})", "c.json");
  const Scene d = parse_scene(R"({"version": 1, "frame": {"rotate": {"xw": 30}}})", "d.json");
  EXPECT_LT((c.frame.matrix() - d.frame.matrix()).norm(), 1e-15);
  EXPECT_NEAR(d.frame.matrix()(0, 0), std::cos(kPi / 6), 1e-15);
}

TEST(Scene, MatrixFrameIsReadAndChecked) {
  const Scene s = parse_scene(
      R"({"version": 1, "frame": {"matrix": [[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}})",
      "m.json");
  EXPECT_EQ(s.frame.matrix()(1, 0), 1.0);
  EXPECT_EQ(s.frame.matrix()(0, 1), -1.0);
  test::expect_parse_error(
      [] {
        parse_scene(R"({"version": 1, "frame": {"matrix": [[-1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}})",
                    "r.json");
      },
      0, "reflection");
  test::expect_parse_error([] {
    parse_scene(R"({"version": 1, "frame": {"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0]]}})", "r.json");
  }, 0, "4 rows");
  test::expect_parse_error([] {
    parse_scene(R"({"version": 1, "frame": {"matrix": [], "rotate": {}}})", "r.json");
  }, 0, "not both");
}

TEST(Scene, ViewAndPhysicsFields) {
  const Scene s = parse_scene(R"({"version": 1,
    "view": {"trackball": [2, 0, 0, 0], "distance": 5, "fov_deg": 50, "depth_colour": false,
             "colour_map": "rainbow", "wireframe": true, "shadow": true, "intersections": true,
             "tube_radius": 0.05,
             "background": [1, 1, 1]},
    "physics": {"time_step": 0.002, "thickness": 0.01, "gravity": [0, -9.81, 0], "mass": 0.01,
                "stiffness": 80, "beta": 0.5, "damping": 0.1, "friction": 0, "integrator": "explicit-euler"}})",
                              "v.json");
  EXPECT_EQ(s.view.trackball.w(), 1.0);  // normalised
  EXPECT_EQ(s.view.distance, 5);
  EXPECT_EQ(s.view.fov_deg, 50);
  EXPECT_FALSE(s.view.depth_colour);
  EXPECT_EQ(s.view.colour_map, ColourMap::kRainbow);
  EXPECT_TRUE(s.view.wireframe);
  EXPECT_TRUE(s.view.shadow);
  EXPECT_TRUE(s.view.intersections);
  EXPECT_EQ(s.view.tube_radius, 0.05);
  EXPECT_EQ(s.view.background, Vec3f(1, 1, 1));
  EXPECT_EQ(s.physics.time_step, 0.002);
  EXPECT_EQ(s.physics.gravity, Vec4(0, -9.81, 0, 0));
  EXPECT_EQ(s.physics.beta, 0.5);
  EXPECT_EQ(s.physics.integrator, "explicit-euler");
}

TEST(Scene, AbsurdValuesAreRejected) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"version": 1, "view": {"fov_deg": 0}})", "view.fov_deg"},
      {R"({"version": 1, "view": {"distance": -1}})", "view.distance"},
      {R"({"version": 1, "view": {"trackball": [0, 0, 0, 0]}})", "must not be zero"},
      {R"({"version": 1, "view": {"background": [0, 2, 0]}})", "view.background[1]"},
      {R"({"version": 1, "view": {"colour_map": "plaid"}})", "unknown colour map"},
      {R"({"version": 1, "physics": {"time_step": -1e-3}})", "physics.time_step"},
      {R"({"version": 1, "physics": {"mass": 0}})", "physics.mass"},
      {R"({"version": 1, "physics": {"thickness": -0.1}})", "physics.thickness"},
      {R"({"version": 1, "physics": {"beta": -1}})", "physics.beta"},
      {R"({"version": 1, "physics": {"gravity": [0, 1e300, 0, 0]}})", "physics.gravity"},
      {R"({"version": 1, "physics": {"integrator": "Euler!"}})", "physics.integrator"},
      {R"({"version": 1, "physics": {"damping": "lots"}})", "must be a number"},
      {R"({"version": 1.5})", "unsupported scene version"},
      {R"({"objects": []})", "missing \"version\""},
      {R"({"version": 1, "objects": {}})", "objects: must be an array"},
      {R"({"version": 1, "objects": [{"name": "x"}]})", "exactly one of"},
      {R"({"version": 1, "objects": [{"generator": "sphere", "path": "a.off"}]})", "exactly one of"},
      {R"({"version": 1, "objects": [{"path": "a.off", "params": {}}]})", "only allowed with"},
      {R"({"version": 1, "objects": [{"generator": "sphere", "params": {"n": null}}]})",
       "objects[0].params.n"},
      {R"({"version": 1, "objects": [{"generator": "sphere", "offset": [1, 2]}]})", "3 or 4 numbers"},
      {R"({"version": 1, "objects": [{"generator": "sphere", "params": {"n": 1e400}}]})", "overflow"},
  };
  for (const auto& [text, fragment] : cases) {
    SCOPED_TRACE(text);
    test::expect_parse_error([&text = text] { parse_scene(text, "bad.json"); }, 0, fragment);
  }
}

TEST(Scene, JsonSyntaxErrorsCarryTheLine) {
  test::expect_parse_error(
      [] { parse_scene("{\n\"version\": 1,\n\n\"view\": {\"fov_deg\": 40,,}\n}", "s.json"); }, 4,
      "s.json:4:");
  test::expect_parse_error([] { parse_scene("", "e.json"); }, 1, "JSON syntax error");
}

TEST(Scene, CommentsAreAllowed) {
  const Scene s = parse_scene("// a scene\n{\"version\": 1 /* the format */}", "c.json");
  EXPECT_TRUE(s.objects.empty());
}

TEST(Scene, MeshPathsAreRelativeToTheSceneFile) {
  test::TempDir dir;
  std::filesystem::create_directories(dir / "meshes");
  std::filesystem::copy_file(test::data_dir() / "square_4d.4off", dir / "meshes" / "sq.4off");
  const auto scene_file = dir.write("s.json", R"({"version": 1, "objects": [
      {"path": "meshes/sq.4off", "offset": [0, 0, 0, 1]}]})");
  const Scene s = load_scene(scene_file);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].name, "sq");
  EXPECT_FALSE(s.objects[0].generator.has_value());
  EXPECT_EQ(std::filesystem::path(s.objects[0].source_path), (dir / "meshes" / "sq.4off").lexically_normal());
  EXPECT_EQ(std::get<Surface<4>>(s.objects[0].shape).vertices[1], Vec4(0, 0, 1, 1));
}

TEST(Scene, MalformedMeshReportsTheMeshFileAndLine) {
  test::TempDir dir;
  dir.write("m.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  const auto scene_file = dir.write("s.json", R"({"version": 1, "objects": [{"path": "m.off"}]})");
  test::expect_parse_error([&] { load_scene(scene_file); }, 6, "m.off:6:");
}

TEST(Scene, SaveThenLoadRoundTrip) {
  test::TempDir dir;
  std::filesystem::copy_file(test::data_dir() / "tetra.off", dir / "tetra.off");
  Scene s;
  s.objects.push_back(load_object("sphere:n=6"));
  s.objects[0].name = "ball";
  s.objects[0].colour = Vec3f(0.25f, 0.5f, 0.75f);
  SceneObject loaded = load_object((dir / "tetra.off").string());
  s.objects.push_back(loaded);
  SceneObject edited;
  edited.name = "my edit/1";  // not file-name safe on purpose
  Surface<4> mesh;
  mesh.vertices = {Vec4(0.1, 0.2, 0.3, 0.4), Vec4(1, 0, 0, 0), Vec4(0, 1, 0, 1.0 / 3)};
  mesh.triangles = {{0, 1, 2}};
  edited.shape = mesh;
  s.objects.push_back(edited);
  Curve<3> knot = std::get<Curve<3>>(generate("torus-knot", {{"n", 40}}));
  knot.components[0].closed = false;
  s.objects.push_back({"open knot", std::nullopt, "", knot, std::nullopt, {}});
  s.frame.rotate(*parse_plane("xw", 4), 0.3);
  s.frame.rotate(*parse_plane("yz", 4), -1.1);
  s.view.colour_map = ColourMap::kGrey;
  s.view.tube_radius = 0.07;
  s.view.intersections = true;
  s.view.trackball = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY()));
  s.physics.gravity = Vec4(0, 0, 0, -9.81);
  s.physics.stiffness = 123.5;

  std::filesystem::create_directories(dir / "out");
  const auto file = dir / "out" / "scene.json";
  save_scene(s, file);
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "scene.my_edit_1.4off"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "scene.open_knot.curve"));
  const Scene r = load_scene(file);

  ASSERT_EQ(r.objects.size(), 4u);
  EXPECT_EQ(r.objects[0].name, "ball");
  ASSERT_TRUE(r.objects[0].generator.has_value());
  EXPECT_EQ(r.objects[0].generator->params, s.objects[0].generator->params);
  EXPECT_EQ(r.objects[0].colour, s.objects[0].colour);
  EXPECT_EQ(std::get<Surface<4>>(r.objects[0].shape).vertices,
            std::get<Surface<4>>(s.objects[0].shape).vertices);
  EXPECT_EQ(r.objects[1].name, "tetra");
  EXPECT_EQ(std::filesystem::path(r.objects[1].source_path), (dir / "tetra.off").lexically_normal());
  EXPECT_EQ(std::get<Surface<3>>(r.objects[1].shape).vertices, std::get<Surface<3>>(loaded.shape).vertices);
  EXPECT_EQ(r.objects[2].name, "my edit/1");
  EXPECT_EQ(std::get<Surface<4>>(r.objects[2].shape).vertices, mesh.vertices);
  EXPECT_EQ(std::get<Surface<4>>(r.objects[2].shape).triangles, mesh.triangles);
  const auto& rk = std::get<Curve<3>>(r.objects[3].shape);
  EXPECT_FALSE(rk.components[0].closed);
  EXPECT_EQ(rk.components[0].points, knot.components[0].points);

  EXPECT_LT((r.frame.matrix() - s.frame.matrix()).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_EQ(r.view.colour_map, ColourMap::kGrey);
  EXPECT_EQ(r.view.tube_radius, 0.07);
  EXPECT_TRUE(r.view.intersections);
  EXPECT_LT(r.view.trackball.angularDistance(s.view.trackball), 1e-14);
  EXPECT_EQ(r.view.background, s.view.background);
  EXPECT_EQ(r.physics.gravity, s.physics.gravity);
  EXPECT_EQ(r.physics.stiffness, 123.5);
  EXPECT_EQ(r.physics.integrator, s.physics.integrator);

  // Saving the loaded scene again gives the same text: the format is stable.
  const auto again = dir / "out" / "again.json";
  save_scene(r, again);
  Scene r2 = load_scene(again);
  EXPECT_EQ(r2.objects.size(), 4u);
}

// view.opacity: read, kept within [0.05, 1] with the key named in the message, written back.
TEST(Scene, OpacityIsReadCheckedAndSavedBack) {
  EXPECT_EQ(parse_scene(R"({"version": 1})", "o.json").view.opacity, 1.0) << "opaque by default";
  Scene s = parse_scene(R"({"version": 1, "view": {"opacity": 0.4}})", "o.json");
  EXPECT_EQ(s.view.opacity, 0.4);
  EXPECT_EQ(parse_scene(R"({"version": 1, "view": {"opacity": 0.05}})", "o.json").view.opacity, 0.05);
  for (const char* bad : {"0.04", "0", "1.01", "-1"}) {
    SCOPED_TRACE(bad);
    test::expect_parse_error(
        [&] { parse_scene(std::string(R"({"version": 1, "view": {"opacity": )") + bad + "}}", "o.json"); }, 0,
        "view.opacity: " + std::string(bad) + " is out of range: must be in [0.05, 1]");
  }
  test::expect_parse_error([] { parse_scene(R"({"version": 1, "view": {"opacity": "half"}})", "o.json"); }, 0,
                           "view.opacity: must be a number");
  test::TempDir dir;
  save_scene(s, dir / "o.json");
  EXPECT_EQ(load_scene(dir / "o.json").view.opacity, 0.4);
}

// view.curve_mode: tubes by default, the three names read, anything else refused with the names
// to use, and the mode written back.
TEST(Scene, CurveModeIsReadCheckedAndSavedBack) {
  EXPECT_EQ(parse_scene(R"({"version": 1})", "m.json").view.curve_mode, CurveMode::kTubes);
  for (const CurveMode m : {CurveMode::kTubes, CurveMode::kShadow, CurveMode::kDiagram}) {
    const std::string name = curve_mode_name(m);
    SCOPED_TRACE(name);
    EXPECT_EQ(parse_curve_mode(name), m);
    const Scene s = parse_scene(R"({"version": 1, "view": {"curve_mode": ")" + name + R"("}})", "m.json");
    EXPECT_EQ(s.view.curve_mode, m);
    test::TempDir dir;
    save_scene(s, dir / "m.json");
    EXPECT_EQ(load_scene(dir / "m.json").view.curve_mode, m);
    const std::string written = "\"curve_mode\": \"" + name + "\"";
    EXPECT_NE(scene_text(s, dir / "m.json", ObjectStorage::kByRecipe).find(written), std::string::npos);
  }
  EXPECT_EQ(parse_curve_mode("Tubes"), std::nullopt);
  test::expect_parse_error([] { parse_scene(R"({"version": 1, "view": {"curve_mode": "ribbon"}})", "m.json"); }, 0,
                           "view.curve_mode: unknown curve mode 'ribbon' (use tubes, shadow or diagram)");
  test::expect_parse_error([] { parse_scene(R"({"version": 1, "view": {"curve_mode": 2}})", "m.json"); }, 0,
                           "view.curve_mode: must be a string");
}

TEST(Scene, SaveIntoAMissingFolderFailsCleanly) {
  test::TempDir dir;
  EXPECT_THROW(save_scene(Scene{}, dir / "no" / "such" / "s.json"), Error);
}

}  // namespace
}  // namespace s4d
