// Stepped scenario runs: their state hashes after a fixed number of steps are pinned (behaviour
// unchanged is a test), and verdicts tell a scenario done from one not done.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "knots/slice_naming.hpp"
#include "scenario/scenario_run.hpp"
#include "shape/level_set.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;
const fs::path kScenarios = fs::path(S4D_SOURCE_DIR) / "scenarios";
constexpr int kHashSteps = 200;
const fs::path kHashFile = fs::path(S4D_SOURCE_DIR) / "tests" / "scenario" / "data" / "state_hashes.tsv";

std::string hex(std::uint64_t h) {
  char b[32];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

std::map<std::string, std::string> stored_hashes() {
  std::map<std::string, std::string> m;
  std::ifstream in(kHashFile);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string name, hash;
    ls >> name >> hash;
    m[name] = hash;
  }
  return m;
}

// A change that moves these hashes changes what every scenario does: say why in the commit. A new
// scenario has no stored hash yet. Both write the table afresh with (CONTRIBUTING.md):
//   S4D_WRITE_STATE_HASHES=1 build-test/tests/scenario_tests --gtest_filter=ScenarioRun.StateHashesArePinned
TEST(ScenarioRun, StateHashesArePinned) {
  const auto stored = stored_hashes();
  std::map<std::string, std::string> now;
  for (const auto& e : fs::directory_iterator(kScenarios)) {
    if (e.path().extension() != ".json") continue;
    const Scenario sc = load_scenario(e.path());
    const auto run = ScenarioRun::make(sc);
    for (int i = 0; i < kHashSteps; ++i) run->step();
    now[sc.name] = hex(run->state_hash());
  }
  ASSERT_FALSE(now.empty()) << "no scenario in " << kScenarios;
  if (std::getenv("S4D_WRITE_STATE_HASHES")) {
    std::ofstream out(kHashFile);
    out << "# scenario name, World::state_hash() after " << kHashSteps
        << " steps (tests/scenario/scenario_run_test.cpp writes it: see CONTRIBUTING.md)\n";
    for (const auto& [name, hash] : now) out << name << "\t" << hash << "\n";
    ASSERT_TRUE(out.good()) << "cannot write " << kHashFile;
    GTEST_SKIP() << "wrote " << now.size() << " hashes to " << kHashFile;
  }
  for (const auto& [name, hash] : now) {
    const auto it = stored.find(name);
    if (it == stored.end()) {
      ADD_FAILURE() << "no stored hash for " << name << " (after " << kHashSteps << " steps it is " << hash
                    << "): write the table with S4D_WRITE_STATE_HASHES=1 (CONTRIBUTING.md)";
      continue;
    }
    EXPECT_EQ(hash, it->second) << name << " after " << kHashSteps << " steps";
  }
  for (const auto& [name, hash] : stored)
    EXPECT_TRUE(now.count(name)) << "a hash is stored for " << name << ", which is not in " << kScenarios;
}

TEST(ScenarioRun, TheSameRunGivesTheSameHashAndAnotherDoesNot) {
  Scenario sc = load_scenario(kScenarios / "spun-trefoil-tighten.json");
  auto a = ScenarioRun::make(sc), b = ScenarioRun::make(sc);
  for (int i = 0; i < 50; ++i) {
    a->step();
    b->step();
  }
  EXPECT_EQ(a->state_hash(), b->state_hash());
  for (ScriptAction& a : sc.script)
    if (a.kind == "pull") a.stiffness *= 1.01;
  auto c = ScenarioRun::make(sc);
  for (int i = 0; i < 50; ++i) c->step();
  EXPECT_NE(a->state_hash(), c->state_hash());
}

TEST(ScenarioRun, TheVerdictTellsDoneFromNotDone) {
  Scenario sc = load_scenario(kScenarios / "ribbon-falls-apart-4d.json");
  auto run = ScenarioRun::make(sc);
  EXPECT_FALSE(run->verdict().pass) << "at the start the ends are close: it has not fallen apart";
  while (!run->done()) run->step();
  const VerdictResult v = run->verdict();
  EXPECT_TRUE(v.pass) << v.detail;
  EXPECT_EQ(run->check().intersections, 0);
  EXPECT_GT(run->check().min_gap, 0);
  EXPECT_EQ(run->steps(), 4000);
  EXPECT_NEAR(run->time(), 4.0, 1e-9);

  sc.script.clear();  // nobody pulls: it stays where it is
  auto idle = ScenarioRun::make(sc);
  for (int i = 0; i < 500; ++i) idle->step();
  EXPECT_FALSE(idle->verdict().pass) << idle->verdict().detail;
}

TEST(ScenarioRun, CurrentSceneCarriesThePositions) {
  const Scenario sc = load_scenario(kScenarios / "spun-trefoil-tighten.json");
  auto run = ScenarioRun::make(sc);
  for (int i = 0; i < 300; ++i) run->step();
  const Scene now = run->current_scene();
  const auto& s = std::get<Surface<4>>(now.objects[0].shape);
  const std::vector<Vec4> x = run->positions();
  ASSERT_EQ(s.vertices.size(), x.size());
  EXPECT_EQ(s.vertices[0], x[0]);
  EXPECT_NE(s.vertices[0], std::get<Surface<4>>(sc.scene.objects[0].shape).vertices[0]) << "the pole was pulled";
}

// Issue 37: a slice's name does not change while the surface is pulled. The spun trefoil's poles
// pulled apart as its scenario does: its slice by the hyperplane w = 0 (the spinning plane, in the
// unturned frame) stays the square knot, 3_1 # 3_1 mirror, at every frame of the pull. A slice
// can change its knot only where the surface passes through itself, or as a critical level crosses
// it; the pull in the shadow (w free) does neither.
TEST(ScenarioRun, ASlicesNameHoldsWhileTheSurfaceIsPulled) {
  const Scenario sc = load_scenario(kScenarios / "spun-trefoil-tighten.json");
  const auto run = ScenarioRun::make(sc);
  const std::vector<Vec4> start = run->positions();
  const Frame<4> unturned;
  for (int frame = 0; frame <= 6; ++frame) {
    const Scene now = run->current_scene();
    const auto& surface = std::get<Surface<4>>(now.objects.at(0).shape);
    const SliceNaming n = name_slice(level_set(surface, unturned, 0.0).curve, 0.0);
    EXPECT_EQ(n.name, "3_1 # 3_1 mirror") << "at " << run->time() << " s: " << n.headline();
    EXPECT_EQ(n.components, 1);
    for (int i = 0; i < 250; ++i) run->step();
  }
  double moved = 0;
  const std::vector<Vec4> end = run->positions();
  for (std::size_t v = 0; v < end.size(); ++v) moved = std::max(moved, (end[v] - start[v]).norm());
  EXPECT_GT(moved, 0.5) << "the pull deformed the sphere";
}

}  // namespace
}  // namespace s4d
