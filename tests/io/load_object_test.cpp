// load_object / load_scene_or_object: files by extension, generator calls, and clear refusals.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/object_file.hpp"
#include "io/scene.hpp"
#include "io_test_util.hpp"

namespace s4d {
namespace {

using test::data_dir;

TEST(LoadObject, FilesByExtension) {
  const SceneObject a = load_object((data_dir() / "tetra.off").string());
  EXPECT_TRUE(std::holds_alternative<Surface<3>>(a.shape));
  EXPECT_EQ(a.name, "tetra");
  EXPECT_FALSE(a.generator.has_value());
  EXPECT_FALSE(a.source_path.empty());
  EXPECT_TRUE(
      std::holds_alternative<Surface<4>>(load_object((data_dir() / "square_4d.4off").string()).shape));
  EXPECT_TRUE(std::holds_alternative<Curve<3>>(load_object((data_dir() / "trefoil.vect").string()).shape));
  EXPECT_TRUE(std::holds_alternative<Curve<4>>(load_object((data_dir() / "link_4d.4vect").string()).shape));
  EXPECT_TRUE(
      std::holds_alternative<Curve<3>>(load_object((data_dir() / "two_components.txt").string()).shape));
}

TEST(LoadObject, ExtensionsAreCaseInsensitive) {
  test::TempDir dir;
  std::filesystem::copy_file(data_dir() / "tetra.off", dir / "T.OFF");
  EXPECT_TRUE(std::holds_alternative<Surface<3>>(load_object((dir / "T.OFF").string()).shape));
}

TEST(LoadObject, GeneratorCalls) {
  const SceneObject o = load_object("sphere:n=6,radius=0.5");
  ASSERT_TRUE(o.generator.has_value());
  EXPECT_EQ(o.name, "sphere");
  EXPECT_EQ(o.generator->params.at("radius"), 0.5);
  const auto& s = std::get<Surface<4>>(o.shape);
  for (const Vec4& v : s.vertices) EXPECT_NEAR(v.norm(), 0.5, 1e-12);
  EXPECT_TRUE(std::holds_alternative<Curve<3>>(load_object("torus-knot").shape));
}

// "SPEC@x,y,z[,w]" places the object, as a scene's "offset" does (what Create > Add to scene's
// position writes): a second sphere beside the first instead of on it.
TEST(LoadObject, AnOffsetAfterAtPlacesTheObject) {
  const SceneObject here = load_object("sphere:n=8,radius=0.5");
  const SceneObject there = load_object("sphere:n=8,radius=0.5@1.5,-1,0");
  EXPECT_EQ(there.placement.offset, Vec4(1.5, -1, 0, 0));
  ASSERT_TRUE(there.generator.has_value());
  EXPECT_EQ(there.generator->params.at("radius"), 0.5);
  const auto& a = std::get<Surface<4>>(here.shape).vertices;
  const auto& b = std::get<Surface<4>>(there.shape).vertices;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(b[i] - a[i], Vec4(1.5, -1, 0, 0));
  EXPECT_EQ(load_object("cloth:n=4@0,0,0,0.25").placement.offset, Vec4(0, 0, 0, 0.25)) << "four numbers: w too";
  const SceneObject file = load_object((data_dir() / "tetra.off").string() + "@0,0,2");
  EXPECT_EQ(std::get<Surface<3>>(file.shape).vertices[0].z(),
            std::get<Surface<3>>(load_object((data_dir() / "tetra.off").string()).shape).vertices[0].z() + 2);
  EXPECT_THROW(load_object("sphere@1,2"), Error) << "two numbers are no offset: a generator name with '@' is unknown";
  EXPECT_THROW(load_object("sphere@1,inf,0"), Error);
}

TEST(LoadObject, RefusalsAreErrorsWithASentence) {
  test::TempDir dir;
  const auto odd = dir.write("mesh.stl", "solid x\n");
  try {
    load_object(odd.string());
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown file type"), std::string::npos) << e.what();
  }
  try {
    load_object((dir / "missing.4off").string());
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_object("teapot"), Error);
  EXPECT_THROW(load_object("sphere:n=two"), Error);
  EXPECT_THROW(load_object(""), Error);
}

TEST(LoadObject, SceneOrObject) {
  const Scene a = load_scene_or_object("clifford-torus:n=8,m=8");
  ASSERT_EQ(a.objects.size(), 1u);
  EXPECT_EQ(std::get<Surface<4>>(a.objects[0].shape).vertices.size(), 64u);
  test::TempDir dir;
  const auto file =
      dir.write("s.JSON", R"({"version": 1, "objects": [{"generator": "sphere", "params": {"n": 4}}]})");
  EXPECT_EQ(load_scene_or_object(file.string()).objects.size(), 1u);
  EXPECT_THROW(load_scene_or_object((dir / "none.json").string()), ParseError);
}

TEST(ObjectFile, WriteByExtensionChecksTheKind) {
  test::TempDir dir;
  const Shape surface = load_object((data_dir() / "tetra.off").string()).shape;
  const Shape curve = load_object((data_dir() / "trefoil.vect").string()).shape;
  EXPECT_THROW(write_shape_file(surface, dir / "x.vect"), Error);
  EXPECT_THROW(write_shape_file(curve, dir / "x.off"), Error);
  write_shape_file(curve, dir / "x.xyz");
  EXPECT_EQ(std::get<Curve<3>>(read_shape_file(dir / "x.xyz")).point_count(), 5u);
  write_shape_file(curve, dir / "x.vect");
  EXPECT_EQ(std::get<Curve<3>>(read_shape_file(dir / "x.vect")).point_count(), 5u);
}

TEST(ObjectFile, OffsetKeepsR3UnlessWIsUsed) {
  Surface<3> s;
  s.vertices = {Vec3(1, 2, 3)};
  Placement p;
  p.offset = Vec4(1, 1, 1, 0);
  const Shape a = placed(s, p);
  EXPECT_EQ(std::get<Surface<3>>(a).vertices[0], Vec3(2, 3, 4));
  p.offset = Vec4(0, 0, 0, -2);
  const Shape b = placed(s, p);
  EXPECT_EQ(std::get<Surface<4>>(b).vertices[0], Vec4(1, 2, 3, -2));
}

}  // namespace
}  // namespace s4d

namespace s4d {
namespace {

TEST(LoadObject, AFileNamedLikeAGeneratorDoesNotHideIt) {
  test::TempDir dir;
  dir.write("chain", "not a mesh\n");
  const auto old = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  SceneObject o;
  EXPECT_NO_THROW(o = load_object("chain"));
  std::filesystem::current_path(old);
  EXPECT_TRUE(o.generator.has_value());
}

}  // namespace
}  // namespace s4d
