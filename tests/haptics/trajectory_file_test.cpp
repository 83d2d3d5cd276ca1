// Trajectory files: exact round trip of every double, clear file:line errors, the background recorder.
#include "haptics/trajectory_file.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) { return fs::temp_directory_path() / ("s4d_haptics_" + name); }

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::string parse_error_of(const std::string& text) {
  const fs::path p = temp_file("bad.traj");
  write_text(p, text);
  try {
    read_trajectory(p);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TrajectoryFile, RoundTripIsBitExact) {
  Trajectory t = circle_trajectory(0.05, 1000, 0.0123456789, 1.7, 0.001);
  t.header.device = "sim";
  t.header.caps.max_force = 3.3;
  t.header.caps.max_force_rate = 1000;
  t.header.caps.outputs_force = true;
  t.header.params = {{"H", 1.0 / 3.0}, {"Kd", 1e-300}, {"max force", 2}};  // a live simulation's names have spaces
  t.header.setup = "cloth_n=8 collisions=0";
  t.ticks[3].force[1] = 2.0 / 3.0;
  t.ticks[4].force[2] = -5e-324;  // denormal
  t.ticks[5].events = kEventDeadlineMissed | kEventDisconnected;
  t.ticks[6].buttons = 0xffffffffu;
  const fs::path p = temp_file("roundtrip.traj");
  write_trajectory(p, t);
  const Trajectory r = read_trajectory(p);
  ASSERT_EQ(r.ticks.size(), t.ticks.size());
  EXPECT_EQ(r.header.device, "sim");
  EXPECT_EQ(r.header.scene, t.header.scene);
  EXPECT_EQ(r.header.setup, "cloth_n=8 collisions=0");
  EXPECT_EQ(r.header.caps.max_force, 3.3);
  EXPECT_TRUE(r.header.caps.outputs_force);
  ASSERT_EQ(r.header.params.size(), 3u);
  EXPECT_EQ(r.header.params[0].second, 1.0 / 3.0);
  EXPECT_EQ(r.header.params[1].second, 1e-300);
  EXPECT_EQ(r.header.params[2].first, "max force");
  EXPECT_EQ(r.header.params[2].second, 2);
  for (std::size_t i = 0; i < t.ticks.size(); ++i)
    ASSERT_EQ(std::memcmp(&r.ticks[i], &t.ticks[i], sizeof(TickRecord)), 0) << "tick " << i;
}

// A device named in words (as real arms are) still writes a file that reads back.
TEST(TrajectoryFile, ANameWithSpacesReadsBackAsOneWord) {
  Trajectory t = circle_trajectory(0.05, 1000, 0.01, 1, 0.001);
  t.header.device = "OpenHaptics Phantom Omni";
  t.header.scene = "";
  const fs::path p = temp_file("spaces.traj");
  write_trajectory(p, t);
  const Trajectory r = read_trajectory(p);
  EXPECT_EQ(r.header.device, "OpenHaptics_Phantom_Omni");
  EXPECT_EQ(r.header.scene, "unnamed");
  EXPECT_EQ(r.ticks.size(), t.ticks.size());
}

TEST(TrajectoryFile, ErrorsNameFileAndLine) {
  const std::string head = "# shadow4d haptic trajectory v1\nrate 1000\n";
  EXPECT_NE(parse_error_of("hello\n").find(":1:"), std::string::npos);
  const std::string bad_number = parse_error_of(head + "tick 0 0 0 1 2 x 0 0 0 0 0 0 0 0 0\n");
  EXPECT_NE(bad_number.find("bad.traj:3:"), std::string::npos) << bad_number;
  EXPECT_NE(bad_number.find("'x'"), std::string::npos) << bad_number;
  EXPECT_NE(parse_error_of(head + "tick 0 0 0 1 2 3\n").find("needs 15 values"), std::string::npos);
  EXPECT_NE(parse_error_of(head + "tick 0 0 0 nan 0 0 0 0 0 0 0 0 0 0 0\n").find("non-finite"),
            std::string::npos);
  EXPECT_NE(parse_error_of(head + "param H\n").find("param needs a name and a value"), std::string::npos);
  EXPECT_NE(parse_error_of(head + "param max force x\n").find("'x'"), std::string::npos);
  EXPECT_NE(parse_error_of(head + "wobble 3\n").find("unknown keyword 'wobble'"), std::string::npos);
  EXPECT_NE(parse_error_of(head + "rate 0\n").find("rate must be"), std::string::npos);
  EXPECT_NE(parse_error_of(head).find("no tick lines"), std::string::npos);
  const std::string order = head + "tick 5 0 0 0 0 0 0 0 0 0 0 0 0 0 0\ntick 5 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n";
  EXPECT_NE(parse_error_of(order).find(":4: tick numbers must increase"), std::string::npos);
  EXPECT_THROW(read_trajectory(temp_file("does-not-exist.traj")), Error);
}

// The fuzz target and the replay device read the same text; errors name the origin given.
TEST(TrajectoryFile, ParsesTextInMemoryLikeAFile) {
  std::string text = format_header(TrajectoryHeader{});
  TickRecord r;
  r.tick = 7;
  r.force[0] = 0.25;
  append_record(text, r);
  const Trajectory t = parse_trajectory(text, "in memory");
  ASSERT_EQ(t.ticks.size(), 1u);
  EXPECT_EQ(t.ticks[0].tick, 7u);
  EXPECT_EQ(t.ticks[0].force[0], 0.25);
  try {
    parse_trajectory("# shadow4d haptic trajectory v1\nrate 5\n", "in memory");
    ADD_FAILURE() << "a rate of 5 Hz was accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("in memory:2: rate must be", 0), 0u) << e.what();
  }
}

TEST(TrajectoryRecorder, WritesEveryPushedTick) {
  const fs::path p = temp_file("recorder.traj");
  TrajectoryHeader h;
  h.params = {{"H", 500}};
  {
    TrajectoryRecorder rec(p, h);
    for (std::uint64_t i = 0; i < 5000; ++i) {
      TickRecord r;
      r.tick = i;
      r.position[0] = 1e-3 * static_cast<double>(i) / 7.0;
      r.force[2] = -static_cast<double>(i) / 3.0;
      ASSERT_TRUE(rec.push(r));
    }
    rec.close();
    EXPECT_EQ(rec.written(), 5000u);
    EXPECT_EQ(rec.dropped(), 0u);
  }
  const Trajectory t = read_trajectory(p);
  ASSERT_EQ(t.ticks.size(), 5000u);
  EXPECT_EQ(t.ticks[4999].position[0], 1e-3 * 4999.0 / 7.0);
  EXPECT_EQ(t.ticks[1234].force[2], -1234.0 / 3.0);
  EXPECT_THROW(TrajectoryRecorder(fs::path("/nonexistent-dir/x.traj"), h), Error);
}

}  // namespace
}  // namespace s4d
