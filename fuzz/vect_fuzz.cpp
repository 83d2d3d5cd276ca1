// libFuzzer target: Geomview VECT, 4VECT and nVECT polylines (io/vect).
#include "fuzz_target.hpp"
#include "io/vect.hpp"

S4D_FUZZ_TARGET(text) { s4d::parse_vect(text, "fuzz.vect"); }
