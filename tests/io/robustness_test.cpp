// Fuzz-style robustness: thousands of random mutations of valid files go through every reader,
// which may accept them or throw ParseError — anything else (crash, other exception) fails.
#include <gtest/gtest.h>

#include <random>

#include "io/curve_text.hpp"
#include "io/off.hpp"
#include "io/scene.hpp"
#include "io/text_scanner.hpp"
#include "io/vect.hpp"
#include "io_test_util.hpp"

namespace s4d {
namespace {

// Mutations that hit the weak spots of text formats: counts, signs, exponents, separators,
// truncation, binary bytes, duplicated and deleted spans.
std::string mutate(std::string s, std::mt19937& rng) {
  static const char* const kSnippets[] = {"-",  "9", "99999999999", "e999", "nan",  "inf", " ",
                                          "\n", "#", "#!",          "-1",   "0",    ".",   "1e-400",
                                          "\"", "{", "]",           ",",    "\x00", "\xff"};
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    const std::size_t n = s.size();
    const std::size_t at = n ? rng() % n : 0;
    switch (rng() % 7) {
      case 0:
        if (n) s[at] = static_cast<char>(rng() & 0xff);
        break;
      case 1: s.insert(at, kSnippets[rng() % std::size(kSnippets)]); break;
      case 2:
        if (n) s.erase(at, 1 + rng() % 8);
        break;
      case 3:
        if (n) s.resize(at);  // truncation
        break;
      case 4:
        if (n) s.insert(at, s.substr(rng() % n, 1 + rng() % 16));
        break;
      case 5:
        if (n && std::isdigit(static_cast<unsigned char>(s[at]))) s[at] = static_cast<char>('0' + rng() % 10);
        break;
      default:
        if (n) s[at] = "0123456789 -\n"[rng() % 13];
        break;
    }
  }
  return s;
}

struct Counts {
  int accepted = 0;
  int rejected = 0;
};

Counts fuzz(const std::string& valid, int rounds, unsigned seed,
            const std::function<void(const std::string&)>& read) {
  std::mt19937 rng(seed);
  Counts c;
  for (int i = 0; i < rounds; ++i) {
    const std::string text = mutate(valid, rng);
    try {
      read(text);
      ++c.accepted;
    } catch (const ParseError& e) {
      ++c.rejected;
      EXPECT_NE(std::string(e.what()).find(':'), std::string::npos);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "non-ParseError exception " << e.what() << " for input:\n" << text;
      return c;
    }
  }
  return c;
}

std::string sample(const std::string& name) { return read_text_file(test::data_dir() / name); }

constexpr int kRounds = 3000;

TEST(Robustness, OffReaderSurvivesMutations) {
  const auto read = [](const std::string& t) { parse_off(t, "fuzz.off"); };
  for (const char* name : {"tetra.off", "square_4d.4off", "cube_noff.off", "homogeneous.off"}) {
    SCOPED_TRACE(name);
    const Counts c = fuzz(sample(name), kRounds, 11, read);
    EXPECT_GT(c.rejected, kRounds / 4);  // the mutations do reach the validation
  }
  Surface<3> grid;
  for (int i = 0; i < 12; ++i) grid.vertices.push_back(Vec3(i % 4, i / 4, 0.5 * i));
  grid.triangles = {{0, 1, 4}, {1, 5, 4}, {5, 6, 9}};
  grid.grid = Grid{3, 4, true, false};
  fuzz(format_off(grid), kRounds, 12, read);
}

TEST(Robustness, VectReaderSurvivesMutations) {
  const auto read = [](const std::string& t) { parse_vect(t, "fuzz.vect"); };
  for (const char* name : {"trefoil.vect", "link_4d.4vect"}) {
    SCOPED_TRACE(name);
    const Counts c = fuzz(sample(name), kRounds, 21, read);
    EXPECT_GT(c.rejected, kRounds / 4);
  }
}

TEST(Robustness, CurveTextReaderSurvivesMutations) {
  const auto read = [](const std::string& t) { parse_curve_text(t, "fuzz.txt"); };
  const Counts c = fuzz(sample("two_components.txt"), kRounds, 31, read);
  EXPECT_GT(c.rejected, kRounds / 10);
  EXPECT_GT(c.accepted, 0);
}

TEST(Robustness, SceneParserSurvivesMutations) {
  test::TempDir dir;
  std::filesystem::copy_file(test::data_dir() / "square_4d.4off", dir / "sq.4off");
  std::filesystem::copy_file(test::data_dir() / "trefoil.vect", dir / "k.vect");
  // No generator objects: a mutated parameter could legitimately ask for millions of vertices.
  const std::string scene = R"({
  "version": 1,
  "objects": [
    {"name": "square", "path": "sq.4off", "offset": [0, 0.5, 0, -1], "colour": [1, 0.5, 0]},
    {"path": "k.vect"}
  ],
  "frame": {"rotate": {"xw": 30, "yz": -15}},
  "view": {"trackball": [1, 0, 0, 0], "distance": 4, "fov_deg": 40, "depth_colour": true,
           "colour_map": "coolwarm", "wireframe": false, "shadow": false, "tube_radius": 0.03,
           "background": [0.1, 0.1, 0.1]},
  "physics": {"time_step": 0.001, "thickness": 0.02, "gravity": [0, -9.81, 0, 0], "mass": 0.001,
              "stiffness": 50, "beta": 0, "damping": 0.02, "friction": 0.3, "integrator": "symplectic-euler"}
})";
  ASSERT_NO_THROW(parse_scene(scene, dir / "s.json"));
  const auto origin = dir / "s.json";
  const Counts c = fuzz(scene, kRounds, 41, [&](const std::string& t) { parse_scene(t, origin); });
  EXPECT_GT(c.rejected, kRounds / 4);
}

}  // namespace
}  // namespace s4d
