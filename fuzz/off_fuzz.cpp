// libFuzzer target: Geomview OFF, 4OFF and nOFF meshes (io/off).
#include "fuzz_target.hpp"
#include "io/off.hpp"

S4D_FUZZ_TARGET(text) { s4d::parse_off(text, "fuzz.off"); }
