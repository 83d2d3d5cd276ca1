// libFuzzer target: a knot sketch's stroke file (`shadow4d knot sketch FILE --knot`): a text curve
// of (x, y, u) samples, made into the sketched knot as the command does (knots/sketch).
#include <variant>

#include "fuzz_target.hpp"
#include "io/curve_text.hpp"
#include "knots/sketch.hpp"

S4D_FUZZ_TARGET(text) {
  const s4d::Shape shape = s4d::parse_curve_text(text, "fuzz.txt");
  if (const auto* curve = std::get_if<s4d::Curve<3>>(&shape))
    s4d::knot_from_sketch(s4d::stroke_from_curve(*curve, 0.01));
}
