// Scenario files: every shipped one reads as a scene plus its scenario section; malformed
// sections are refused with the place and the reason.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.hpp"
#include "scenario/scenario.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;
const fs::path kScenarios = fs::path(S4D_SOURCE_DIR) / "scenarios";

std::string error_of(const std::string& text) {
  try {
    scenario_of_scene(parse_scene(text, "t.json"), "t.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Scenario, EveryShippedScenarioReads) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(kScenarios)) {
    if (e.path().extension() != ".json") continue;
    SCOPED_TRACE(e.path().string());
    const Scenario s = load_scenario(e.path());
    EXPECT_EQ(s.name, e.path().stem().string());
    EXPECT_FALSE(s.instruction.empty()) << "each scenario says what to do by hand";
    EXPECT_FALSE(s.description.empty());
    EXPECT_GE(s.object_index(s.verdict.object), 0);
    bool in_r4 = false;
    for (const SceneObject& o : s.scene.objects) in_r4 = in_r4 || (is_surface(o.shape) && ambient_dim(o.shape) == 4);
    EXPECT_EQ(s.dim, in_r4 ? 4 : 3) << "the dimension follows the surfaces";
    ++n;
  }
  EXPECT_GT(n, 0) << "no scenario in " << kScenarios;
}

TEST(Scenario, PlacementAndMassComeFromTheScene) {
  const Scenario s = load_scenario(kScenarios / "cloth-slides-off-ribbon.json");
  const SceneObject& cloth = s.scene.objects[static_cast<std::size_t>(s.object_index("cloth"))];
  ASSERT_TRUE(cloth.placement.matrix.has_value());
  EXPECT_EQ(cloth.placement.offset, Vec4(0.22, 0.05, 0.02, 0));
  EXPECT_EQ(s.scene.physics.friction, 0.0);
  EXPECT_EQ(s.scene.physics.bending_scale, 0.05);
  // The cloth's placed vertices lie in y = 0.05 (its matrix drops y, the offset lifts it).
  for (const Vec4& p : std::get<Surface<4>>(cloth.shape).vertices) EXPECT_NEAR(p.y(), 0.05, 1e-12);
}

TEST(Scenario, APlainSceneIsNoScenario) {
  try {
    load_scenario(fs::path(S4D_SOURCE_DIR) / "scenes" / "spun-trefoil.json");
    FAIL() << "a scene without a scenario section was taken";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("a scene, not a scenario"), std::string::npos) << e.what();
  }
}

TEST(Scenario, MalformedSectionsSayWhereAndWhy) {
  const std::string head = R"({"version": 1, "objects": [{"name": "s", "generator": "sphere", "params": {"n": 6}}], )";
  EXPECT_NE(error_of(head + R"("scenario": {"name": "x", "duration": 1, "verdict": {"kind": "deforms", "object": "s"}, "colour": 1}})")
                .find("scenario.: unknown key 'colour'"),
            std::string::npos);
  EXPECT_NE(error_of(head + R"("scenario": {"name": "x", "duration": 1, "verdict": {"kind": "melts", "object": "s"}}})")
                .find("scenario.verdict.kind: must be untied"),
            std::string::npos);
  EXPECT_NE(error_of(head + R"("scenario": {"name": "x", "duration": 1, "verdict": {"kind": "deforms", "object": "t"}}})")
                .find("scenario.verdict.object: no object named 't'"),
            std::string::npos);
  EXPECT_NE(error_of(head + R"("scenario": {"name": "x", "duration": 1,
      "script": [{"action": "pull", "select": {"object": "s", "all": true}, "by": [1, 0, 0]}],
      "verdict": {"kind": "deforms", "object": "s"}}})")
                .find("scenario.script[0].by: must be an array of 4 numbers"),
            std::string::npos)
      << "a sphere of R^4 is simulated in R^4: the motion has four components";
  EXPECT_NE(error_of(head + R"("scenario": {"name": "x", "duration": -1, "verdict": {"kind": "deforms", "object": "s"}}})")
                .find("scenario.duration: must be in"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"version": 1, "objects": [{"generator": "torus-knot"}], "scenario": {"name": "x", "duration": 1,
      "verdict": {"kind": "deforms", "object": "torus-knot"}}})")
                .find("needs at least one surface"),
            std::string::npos);
  // The verdict indexes points by this axis: one outside R^4 was read past the end of a point.
  for (const char* axis : {"4", "-1", "1.5", "1e300"})
    EXPECT_NE(error_of(head + R"("scenario": {"name": "x", "duration": 1,
        "verdict": {"kind": "slides-off", "object": "s", "numbers": {"axis": )" + axis + "}}}}")
                  .find("scenario.verdict.numbers.axis: must be"),
              std::string::npos)
        << axis;
}

TEST(Scenario, TheOldFormatIsRefusedWithTheVersionMissing) {
  const std::string old = R"({"name": "x", "dim": 4, "duration": 1, "objects": []})";
  try {
    parse_scene(old, "old.json");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown key 'name'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace s4d
