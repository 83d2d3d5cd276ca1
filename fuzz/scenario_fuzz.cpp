// libFuzzer target: scenario files, a scene with a "scenario" section (scenario/scenario):
// the scene read first, then the script and the verdict.
#include <string>

#include "fuzz_target.hpp"
#include "io/scene.hpp"
#include "scenario/scenario.hpp"

S4D_FUZZ_TARGET(text) {
  const char* origin = "/nonexistent/fuzz.json";
  s4d::Scene scene = s4d::parse_scene(std::string(text), origin);
  if (s4d::is_scenario(scene)) s4d::scenario_of_scene(std::move(scene), origin);
}
