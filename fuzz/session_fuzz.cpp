// libFuzzer target: session files, .s4d (io/session_file).
#include <string>

#include "fuzz_target.hpp"
#include "io/session_file.hpp"

S4D_FUZZ_TARGET(text) {
  const std::string t(text);
  try {
    s4d::parse_session_summary(t, "/nonexistent/fuzz.s4d");  // what a start reads of each slot
  } catch (const s4d::Error&) {
  }
  s4d::parse_session(t, "/nonexistent/fuzz.s4d");
}
