#include "io/recent_files.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace s4d {
namespace {

namespace fs = std::filesystem;

TEST(RecentFiles, NewestFirstWithoutRepeatsBoundedAndOnlyFilesThatExist) {
  const fs::path dir = fs::temp_directory_path() / "s4d_recent_files";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const RecentFiles recent(dir / "state" / "recent.txt");
  EXPECT_TRUE(recent.read().empty());
  std::vector<fs::path> files;
  for (int i = 0; i < 10; ++i) {
    std::string name = std::to_string(i);
    name += ".s4d";
    files.push_back(dir / name);
    std::ofstream(files.back()) << "x";
  }
  for (const fs::path& f : files) ASSERT_TRUE(recent.add(f));
  ASSERT_TRUE(recent.add(files[3]));  // again: it moves to the front, not in twice
  const auto list = recent.read();
  ASSERT_EQ(list.size(), RecentFiles::kMax);
  EXPECT_EQ(list[0], files[3]);
  EXPECT_EQ(list[1], files[9]);
  EXPECT_EQ(std::count(list.begin(), list.end(), files[3]), 1);
  fs::remove(files[9]);  // a vanished file is not offered
  const auto after = recent.read();
  EXPECT_EQ(std::count(after.begin(), after.end(), files[9]), 0);
  EXPECT_EQ(after.size(), RecentFiles::kMax - 1);
}

TEST(RecentFiles, AGarbledListLosesNothingElse) {
  const fs::path dir = fs::temp_directory_path() / "s4d_recent_garbled";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path good = dir / "good.json";
  std::ofstream(good) << "{}";
  {
    std::ofstream list(dir / "recent.txt", std::ios::binary);
    list << "relative/path\n\n" << std::string("a\0b", 3) << "\n" << good.string() << "\n/nonexistent/x.s4d\n";
  }
  const RecentFiles recent(dir / "recent.txt");
  EXPECT_EQ(recent.read(), std::vector<fs::path>{good});
  const RecentFiles unwritable("/proc/s4d-cannot-write/recent.txt");
  EXPECT_FALSE(unwritable.add(good));
}

}  // namespace
}  // namespace s4d
