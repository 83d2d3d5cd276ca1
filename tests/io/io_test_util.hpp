// Helpers shared by the io tests: a per-test temporary folder and ParseError expectations.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>

#include "core/error.hpp"

namespace s4d::test {

inline std::filesystem::path data_dir() { return std::filesystem::path(S4D_TEST_DATA) / "io"; }

// A fresh folder under the system temp dir, removed when the test ends.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("s4d_io_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name, std::ios::binary) << text;
    return path_ / name;
  }

 private:
  std::filesystem::path path_;
};

// Runs `fn`, which must throw ParseError at `line` (0: any) with `fragment` in its message.
inline void expect_parse_error(const std::function<void()>& fn, int line, const std::string& fragment) {
  try {
    fn();
    ADD_FAILURE() << "expected ParseError containing '" << fragment << "', nothing was thrown";
  } catch (const ParseError& e) {
    if (line > 0) {
      EXPECT_EQ(e.line(), line) << e.what();
    }
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
        << "message '" << e.what() << "' lacks '" << fragment << "'";
    EXPECT_FALSE(e.file().empty());
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected ParseError, got another exception: " << e.what();
  }
}

}  // namespace s4d::test
