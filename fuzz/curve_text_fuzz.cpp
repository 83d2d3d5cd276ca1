// libFuzzer target: plain-text curves, one point a line (io/curve_text).
#include "fuzz_target.hpp"
#include "io/curve_text.hpp"

S4D_FUZZ_TARGET(text) { s4d::parse_curve_text(text, "fuzz.curve"); }
