// Inputs that once crashed a parser or set off a sanitizer (tests/data/fuzz_regressions/<target>/,
// named after the fuzz/ target that reads them): each is now refused with an s4d::Error that names
// the file. scripts/fuzz.sh seeds its runs with them too.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include "core/error.hpp"
#include "io/curve_text.hpp"
#include "io/off.hpp"
#include "io/scene.hpp"
#include "io/session_file.hpp"
#include "io/vect.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

TEST(FuzzRegressions, EveryInputIsRefusedWithAnError) {
  const std::map<std::string, std::function<void(const fs::path&)>> readers{
      {"off", [](const fs::path& p) { read_off(p); }},
      {"vect", [](const fs::path& p) { read_vect(p); }},
      {"curve_text", [](const fs::path& p) { read_curve_text(p); }},
      {"scene", [](const fs::path& p) { load_scene(p); }},
      {"session", [](const fs::path& p) { read_session(p); }},
  };
  const fs::path root = fs::path(S4D_TEST_DATA) / "fuzz_regressions";
  int inputs = 0;
  for (const auto& [target, read] : readers) {
    if (!fs::is_directory(root / target)) continue;
    for (const fs::directory_entry& e : fs::directory_iterator(root / target)) {
      ++inputs;
      try {
        read(e.path());
        ADD_FAILURE() << e.path() << " was accepted";
      } catch (const Error& err) {
        EXPECT_NE(std::string(err.what()).find(e.path().filename().string()), std::string::npos) << err.what();
      }
    }
  }
  EXPECT_GE(inputs, 2);
}

}  // namespace
}  // namespace s4d
