// The window's input file: events parsed with their frames; a malformed line names file and line.
#include "app/window_input.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace s4d {
namespace {

std::filesystem::path write(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / name;
  std::ofstream(p) << text;
  return p;
}

TEST(InputFile, WaitHoldsTheScriptBetweenEvents) {
  const auto events = read_input_file(write("s4d_input_wait.txt", "# a click, then wait\n5 press right\n6 wait\n"
                                                                   "9 dump /tmp/x.json\n"));
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].kind, InputEvent::Kind::press);
  EXPECT_EQ(events[0].button, 1);
  EXPECT_EQ(events[1].kind, InputEvent::Kind::wait);
  EXPECT_EQ(events[1].frame, 6);
  EXPECT_EQ(events[2].kind, InputEvent::Kind::dump);
  EXPECT_EQ(events[2].text, "/tmp/x.json");
}

TEST(InputFile, MalformedLinesSayWhere) {
  try {
    read_input_file(write("s4d_input_bad.txt", "3 move 1 2\n4 wait a while\n"));
    FAIL() << "accepted";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("s4d_input_bad.txt:2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_input_file(write("s4d_input_bad2.txt", "3 hover 1 2\n")), ParseError);
}

}  // namespace
}  // namespace s4d
