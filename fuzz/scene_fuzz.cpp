// libFuzzer target: scene JSON (io/scene). Mesh paths resolve beside a file that does not exist,
// so relative ones are refused as missing and the run reads no file of the machine by accident.
#include <string>

#include "fuzz_target.hpp"
#include "io/scene.hpp"

S4D_FUZZ_TARGET(text) { s4d::parse_scene(std::string(text), "/nonexistent/fuzz.json"); }
