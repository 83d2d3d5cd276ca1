// libFuzzer target: a ribbon sketch's stroke file (`shadow4d sketch-ribbon`): "x y z u" samples,
// made into a ribbon with nothing else in the scene (interact/ribbon_sketch).
#include "fuzz_target.hpp"
#include "interact/tools/ribbon_sketch.hpp"

S4D_FUZZ_TARGET(text) {
  const auto stroke = s4d::parse_ribbon_stroke(text, "fuzz.txt", 0.01);
  s4d::ribbon_from_sketch(stroke, {}, s4d::Frame<4>(), s4d::Vec3(0, 0, 1));
}
