// Every malformed sample under tests/data/io/bad must give a ParseError at the right line with a
// message that names the problem; none may crash or be accepted.
#include <gtest/gtest.h>

#include "io/curve_text.hpp"
#include "io/off.hpp"
#include "io/scene.hpp"
#include "io/vect.hpp"
#include "io_test_util.hpp"

namespace s4d {
namespace {

struct BadFile {
  const char* name;
  int line;  // 0: the error is not tied to a line
  const char* fragment;
};

void load_any(const std::filesystem::path& p) {
  const std::string ext = p.extension().string();
  if (ext == ".off") read_off(p);
  else if (ext == ".vect" || ext == ".4vect") read_vect(p);
  else if (ext == ".txt") read_curve_text(p);
  else if (ext == ".json") load_scene(p);
  else FAIL() << "no reader for " << p;
}

class Malformed : public ::testing::TestWithParam<BadFile> {};

TEST_P(Malformed, ThrowsParseErrorAtTheRightLine) {
  const BadFile& b = GetParam();
  const auto path = test::data_dir() / "bad" / b.name;
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  test::expect_parse_error([&] { load_any(path); }, b.line, b.fragment);
  try {
    load_any(path);
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), path.string());
  }
}

const BadFile kBadFiles[] = {
    {"empty.off", 1, "empty file"},
    {"blank.off", 1, "empty file"},
    {"bad_header.off", 1, "not an OFF file"},
    {"truncated.off", 5, "unexpected end of file"},
    {"truncated_face.off", 6, "unexpected end of file"},
    {"index_out_of_range.off", 6, "vertex index is 3"},
    {"nan_vertex.off", 4, "'nan'"},
    {"inf_vertex.off", 5, "'1e999'"},
    {"negative_count.off", 2, "vertex count is -3"},
    {"huge_count.off", 2, "cannot fit"},
    {"negative_face.off", 6, "vertex count is -3"},
    {"extra_face.off", 7, "unexpected data after the last face"},
    {"bad_dimension.off", 1, "dimension 7"},
    {"binary.off", 1, "binary OFF"},
    {"fractional_index.off", 6, "'2.5'"},
    {"bad_grid.off", 2, "malformed '#! grid"},
    {"junk.off", 2, "the vertex count"},
    {"vect_count_mismatch.vect", 3, "more than the declared 5"},
    {"vect_single_vertex.vect", 3, "at least 2"},
    {"vect_bad_colours.vect", 4, "has 2 colours"},
    {"vect_truncated.vect", 6, "unexpected end of file"},
    {"vect_inf.4vect", 6, "'inf'"},
    {"curve_mixed_dims.txt", 3, "has 4 coordinates"},
    {"curve_one_point.txt", 4, "at least 2"},
    {"curve_2d.txt", 1, "this line has 2"},
    {"curve_nan.txt", 2, "'nan'"},
    {"curve_five.txt", 2, "too many coordinates"},
    {"curve_dangling_directive.txt", 3, "not followed"},
    {"curve_unknown_directive.txt", 1, "unknown directive"},
    {"curve_empty.txt", 0, "no points"},
    {"scene_syntax.json", 4, "JSON syntax error"},
    {"scene_version.json", 0, "unsupported scene version 2"},
    {"scene_negative_radius.json", 0, "view.tube_radius"},
    {"scene_time_step.json", 0, "physics.time_step"},
    {"scene_inf.json", 2, "overflow"},
    {"scene_unknown_generator.json", 0, "unknown generator 'teapot'"},
    {"scene_missing_mesh.json", 0, "mesh file not found"},
    {"scene_wrong_type.json", 0, "view.wireframe: must be true or false"},
    {"scene_bad_plane.json", 0, "unknown rotation plane 'xq'"},
    {"scene_bad_matrix.json", 0, "not a rotation"},
    {"scene_bad_param.json", 0, "parameter radius"},
    {"scene_unknown_key.json", 0, "unknown key 'colour'"},
    {"scene_not_object.json", 0, "must be a JSON object"},
};

INSTANTIATE_TEST_SUITE_P(SampleFiles, Malformed, ::testing::ValuesIn(kBadFiles),
                         [](const ::testing::TestParamInfo<BadFile>& info) {
                           std::string n = info.param.name;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(MalformedFiles, EverySampleIsListed) {
  std::size_t listed = std::size(kBadFiles), on_disk = 0;
  for (const auto& e : std::filesystem::directory_iterator(test::data_dir() / "bad"))
    on_disk += e.is_regular_file();
  EXPECT_EQ(on_disk, listed) << "a file in tests/data/io/bad has no expectation (or one is missing)";
}

TEST(MalformedFiles, MissingFileIsAParseErrorNamingIt) {
  test::expect_parse_error([] { read_off(test::data_dir() / "nope.off"); }, 0, "nope.off");
  test::expect_parse_error([] { read_curve_text(test::data_dir()); }, 0, "directory");
}

}  // namespace
}  // namespace s4d
