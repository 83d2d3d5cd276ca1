// The scripted tool and the by-hand set-up: Play script (and `shadow4d run`) plays every action but
// the "only" ones; a person doing the scenario by hand keeps the set-up ("keep", "until-grabbed",
// "only"), and an "until-grabbed" hold lets go for good when the user's hand takes one of its vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "core/error.hpp"
#include "scenario/script_driver.hpp"

namespace s4d {
namespace {

// A 4 × 4 cloth with one action of each kind on its corners and edges.
Scenario scenario_with_every_kind() {
  const std::string text = R"({
    "version": 1,
    "objects": [{"name": "cloth", "generator": "cloth", "params": {"n": 4, "size": 1}}],
    "physics": {"gravity": [0, -9.81, 0, 0]},
    "scenario": {
      "name": "kinds", "duration": 1,
      "script": [
        {"action": "hold", "select": {"object": "cloth", "vertices": [0]}, "from": 0, "by_hand": "keep"},
        {"action": "hold", "select": {"object": "cloth", "vertices": [3]}, "from": 0, "by_hand": "until-grabbed"},
        {"action": "hold", "select": {"object": "cloth", "vertices": [12]}, "from": 0, "by_hand": "only"},
        {"action": "move", "select": {"object": "cloth", "vertices": [15]}, "from": 0, "to": 0.5, "by": [0, 1, 0, 0]}
      ],
      "verdict": {"kind": "deforms", "object": "cloth", "numbers": {"min_displacement": 0.1}}
    }
  })";
  return scenario_of_scene(parse_scene(text, "kinds.json"), "kinds.json");
}

std::vector<int> pinned(const World<4>& w) {
  std::vector<int> out;
  for (int v = 0; v < w.vertex_count(); ++v)
    if (w.is_pinned(v)) out.push_back(v);
  return out;
}

TEST(ScriptDriver, TheByHandValuesAreRead) {
  const Scenario sc = scenario_with_every_kind();
  ASSERT_EQ(sc.script.size(), 4u);
  EXPECT_EQ(sc.script[0].by_hand, ByHand::kKeep);
  EXPECT_EQ(sc.script[1].by_hand, ByHand::kUntilGrabbed);
  EXPECT_EQ(sc.script[2].by_hand, ByHand::kOnly);
  EXPECT_EQ(sc.script[3].by_hand, ByHand::kSkip) << "the scripted hand's move is skipped by hand by default";
}

TEST(ScriptDriver, TheScriptPlaysAllButTheByHandOnlyActions) {
  const Scenario sc = scenario_with_every_kind();
  SceneWorld<4> sw = build_world<4>(sc.scene);
  ScriptDriver<4> script(sc, sw, ScriptMode::kScript);
  script.apply(sw.world, 0.001);
  EXPECT_EQ(pinned(sw.world), (std::vector<int>{0, 3, 15}));
  const auto& tool = script.tool_vertices();
  EXPECT_EQ(tool[12], 0) << "the by-hand-only hold is no tool of the script";
  EXPECT_EQ(tool[15], 1);
}

TEST(ScriptDriver, ByHandTheSetUpHoldsAndTheScriptedHandIsTheUsers) {
  const Scenario sc = scenario_with_every_kind();
  SceneWorld<4> sw = build_world<4>(sc.scene);
  const Vec4 start15 = sw.world.positions()[15];
  ScriptDriver<4> setup(sc, sw, ScriptMode::kByHand);
  EXPECT_FALSE(setup.empty());
  setup.apply(sw.world, 0);
  EXPECT_EQ(pinned(sw.world), (std::vector<int>{0, 3, 12})) << "in force at the start, before any step";
  for (int k = 1; k <= 200; ++k) {
    setup.apply(sw.world, k * 1e-3);
    sw.world.step();
  }
  EXPECT_FALSE(sw.world.is_pinned(15)) << "the scripted move is the user's to make";
  EXPECT_LT(sw.world.positions()[15].y(), start15.y() - 1e-4) << "nobody carries vertex 15 up: it sags";
  EXPECT_EQ(sw.world.positions()[3], build_world<4>(sc.scene).world.positions()[3]) << "held";

  EXPECT_FALSE(setup.hand_takes(sw.world, 0)) << "a kept hold stays when the user grabs it";
  EXPECT_TRUE(sw.world.is_pinned(0));
  EXPECT_TRUE(setup.hand_takes(sw.world, 3)) << "the user's hand takes over the until-grabbed hold";
  EXPECT_FALSE(sw.world.is_pinned(3));
  for (int k = 201; k <= 400; ++k) {
    setup.apply(sw.world, k * 1e-3);
    sw.world.step();
  }
  EXPECT_FALSE(sw.world.is_pinned(3)) << "let go for good: it does not engage again";
  EXPECT_FALSE(setup.hand_takes(sw.world, 3));
  EXPECT_EQ(pinned(sw.world), (std::vector<int>{0, 12}));
}

TEST(ScriptDriver, AScenarioWithoutSetUpHasNothingByHand) {
  Scenario sc = scenario_with_every_kind();
  for (ScriptAction& a : sc.script) a.by_hand = ByHand::kSkip;
  SceneWorld<4> sw = build_world<4>(sc.scene);
  EXPECT_TRUE(ScriptDriver<4>(sc, sw, ScriptMode::kByHand).empty());
}

// Each shipped scenario done by hand keeps what its instruction assumes: the ribbon the cloth hangs
// on, the held poles, the chain's hold until the user takes it, the end the user does not pull.
TEST(ScriptDriver, EveryShippedScenarioSaysWhatIsHeldByHand) {
  namespace fs = std::filesystem;
  const std::map<std::string, int> held_by_hand{
      {"chain-4d", 17},           {"ribbon-lifts-sphere", 8},    {"cloth-slides-off-ribbon", 16},
      {"spun-trefoil-loosen", 2}, {"spun-trefoil-tighten", 1},   {"ribbon-falls-apart-4d", 3},
      {"ribbon-stays-knotted-3d", 3}, {"clifford-torus-pinch", 8}};
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(S4D_SOURCE_DIR) / "scenarios")) {
    if (e.path().extension() != ".json") continue;
    const Scenario sc = load_scenario(e.path());
    SCOPED_TRACE(sc.name);
    int pins = 0;
    if (sc.dim == 4) {
      SceneWorld<4> sw = build_world<4>(sc.scene);
      ScriptDriver<4>(sc, sw, ScriptMode::kByHand).apply(sw.world, 0);
      for (int v = 0; v < sw.world.vertex_count(); ++v) pins += sw.world.is_pinned(v);
    } else {
      SceneWorld<3> sw = build_world<3>(sc.scene);
      ScriptDriver<3>(sc, sw, ScriptMode::kByHand).apply(sw.world, 0);
      for (int v = 0; v < sw.world.vertex_count(); ++v) pins += sw.world.is_pinned(v);
    }
    if (held_by_hand.count(sc.name)) {
      EXPECT_EQ(pins, held_by_hand.at(sc.name));
    }
    if (pins > 0) {
      EXPECT_NE(sc.instruction.find("orange"), std::string::npos) << "the instruction says where the holds are";
    }
    ++n;
  }
  EXPECT_GE(n, static_cast<int>(held_by_hand.size()));
}

TEST(ScriptDriver, ABadByHandValueIsRefusedWithThePlace) {
  const std::string text = R"({"version": 1,
    "objects": [{"name": "cloth", "generator": "cloth", "params": {"n": 4}}],
    "scenario": {"name": "x", "duration": 1,
      "script": [{"action": "hold", "select": {"object": "cloth", "all": true}, "by_hand": "sometimes"}],
      "verdict": {"kind": "deforms", "object": "cloth"}}})";
  try {
    scenario_of_scene(parse_scene(text, "x.json"), "x.json");
    FAIL() << "taken";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("script[0].by_hand: must be skip, keep, until-grabbed or only"), std::string::npos)
        << e.what();
  }
}

// A move with rings carries the patch around its vertex, each vertex by its weight, as the
// Touch tool's carry does (the same physics/patch.hpp).
TEST(ScriptDriver, AMoveWithRingsCarriesThePatchByItsWeights) {
  const std::string text = R"({
    "version": 1,
    "objects": [{"name": "cloth", "generator": "cloth", "params": {"n": 5, "size": 1}}],
    "physics": {"gravity": [0, 0, 0, 0]},
    "scenario": {
      "name": "carry", "duration": 1,
      "script": [{"action": "move", "select": {"object": "cloth", "vertices": [12]}, "rings": 1, "from": 0,
                  "to": 0.1, "by": [0, 0, 0.3, 0]}],
      "verdict": {"kind": "deforms", "object": "cloth", "numbers": {"min_displacement": 0.1}}
    }
  })";
  const Scenario sc = scenario_of_scene(parse_scene(text, "carry.json"), "carry.json");
  ASSERT_EQ(sc.script.size(), 1u);
  EXPECT_EQ(sc.script[0].rings, 1);
  SceneWorld<4> sw = build_world<4>(sc.scene);
  const std::vector<Vec4> start(sw.world.positions().begin(), sw.world.positions().end());
  ScriptDriver<4> script(sc, sw);
  for (int k = 1; k <= 150; ++k) {
    script.apply(sw.world, k * 1e-3);
    sw.world.step();
  }
  const auto x = sw.world.positions();
  // The middle of a 5 x 5 cloth: its 6 neighbours along the mesh's edges (ring 1 of 1, weight
  // (1 - (1/2)^2)^2), nothing two edges away.
  EXPECT_NEAR(x[12].z() - start[12].z(), 0.3, 1e-9);
  EXPECT_NEAR(x[13].z() - start[13].z(), 0.5625 * 0.3, 1e-9);
  EXPECT_TRUE(sw.world.is_pinned(13));
  EXPECT_FALSE(sw.world.is_pinned(14)) << "two edges away, outside the patch";
  int pinned = 0;
  for (int v = 0; v < 25; ++v) pinned += sw.world.is_pinned(v) ? 1 : 0;
  EXPECT_EQ(pinned, 7);
  const auto& tool = script.tool_vertices();
  EXPECT_EQ(tool[13], 1);
  EXPECT_EQ(tool[0], 0);
}

// The old "radius" (scene units along the surface) is refused with what to write instead.
TEST(ScriptDriver, AMoveWithARadiusIsRefusedWithTheRingsToWrite) {
  const std::string text = R"({
    "version": 1,
    "objects": [{"name": "cloth", "generator": "cloth", "params": {"n": 5, "size": 1}}],
    "scenario": {
      "name": "carry", "duration": 1,
      "script": [{"action": "move", "select": {"object": "cloth", "vertices": [12]}, "radius": 0.6, "from": 0,
                  "to": 0.1, "by": [0, 0, 0.3, 0]}],
      "verdict": {"kind": "deforms", "object": "cloth", "numbers": {"min_displacement": 0.1}}
    }
  })";
  try {
    scenario_of_scene(parse_scene(text, "carry.json"), "carry.json");
    FAIL() << "taken";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("\"rings\": N"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace s4d
