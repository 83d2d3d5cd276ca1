// libFuzzer target: session files, .s4d (io/session_file).
#include <string>

#include "fuzz_target.hpp"
#include "io/session_file.hpp"

S4D_FUZZ_TARGET(text) { s4d::parse_session(std::string(text), "/nonexistent/fuzz.s4d"); }
