// Data paths: an installed program reads share/shadow4d beside its bin/, before $S4D_DATA_DIR and
// before the build's marker; a failure names every folder tried; examples are found by name.
#include "core/data_paths.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "core/error.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the test's temporary folder, emptied first.
fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("s4d_data_paths_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

void touch(const fs::path& p, const std::string& text = "x") {
  if (p.has_parent_path()) fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

// An install: <prefix>/bin/shadow4d and <prefix>/share/shadow4d/{knots,scenarios,scenes}.
fs::path make_install(const fs::path& prefix) {
  touch(prefix / "bin" / "shadow4d");
  touch(prefix / "share" / "shadow4d" / "knots" / "knot_index.tsv");
  touch(prefix / "share" / "shadow4d" / "scenarios" / "spun-trefoil-tighten.json");
  touch(prefix / "share" / "shadow4d" / "scenes" / "cloth.json");
  return prefix / "bin" / "shadow4d";
}

// A checkout: <root>/data/knots, scenarios, scenes.
fs::path make_checkout(const fs::path& root) {
  touch(root / "data" / "knots" / "knot_index.tsv");
  touch(root / "scenarios" / "a.json");
  touch(root / "scenes" / "b.json");
  return root;
}

TEST(DataPaths, AnInstalledProgramReadsTheShareFolderBesideItsBin) {
  const fs::path prefix = scratch("install");
  const fs::path exe = make_install(prefix);
  const DataDirs d = find_data_dirs(exe, "");
  EXPECT_EQ(d.root, prefix / "share" / "shadow4d");
  EXPECT_EQ(d.knots, prefix / "share" / "shadow4d" / "knots");
  EXPECT_EQ(d.scenarios, prefix / "share" / "shadow4d" / "scenarios");
  EXPECT_EQ(d.scenes, prefix / "share" / "shadow4d" / "scenes");
  EXPECT_NE(d.found_by.find("installed beside"), std::string::npos);
}

TEST(DataPaths, TheInstalledDataComesBeforeTheEnvironmentAndTheBuildMarker) {
  const fs::path prefix = scratch("first");
  const fs::path exe = make_install(prefix);
  const fs::path checkout = make_checkout(scratch("first_checkout"));
  touch(exe.parent_path() / kBuildTreeMarker, checkout.string() + "\n");
  EXPECT_EQ(find_data_dirs(exe, checkout.string()).root, prefix / "share" / "shadow4d");
}

TEST(DataPaths, AProgramMovedAloneReadsTheEnvironmentsFolderInEitherLayout) {
  const fs::path exe = scratch("alone") / "bin" / "shadow4d";
  touch(exe);
  const fs::path checkout = make_checkout(scratch("env_checkout"));
  const DataDirs a = find_data_dirs(exe, checkout.string());
  EXPECT_EQ(a.knots, checkout / "data" / "knots");
  EXPECT_EQ(a.found_by, "S4D_DATA_DIR");
  const fs::path share = make_install(scratch("env_install")).parent_path().parent_path() / "share" / "shadow4d";
  EXPECT_EQ(find_data_dirs(exe, share.string()).knots, share / "knots");
}

TEST(DataPaths, ABuildTreeProgramReadsTheCheckoutItsMarkerNames) {
  const fs::path checkout = make_checkout(scratch("marked_checkout"));
  const fs::path exe = scratch("marked_build") / "apps" / "shadow4d" / "shadow4d";
  touch(exe);
  touch(exe.parent_path() / kBuildTreeMarker, checkout.string() + "\n");
  EXPECT_EQ(build_tree_source(exe), checkout);
  const DataDirs d = find_data_dirs(exe, "");
  EXPECT_EQ(d.knots, checkout / "data" / "knots");
  EXPECT_NE(d.found_by.find("source tree of the build"), std::string::npos);
}

TEST(DataPaths, WithNoDataTheErrorNamesEveryFolderTriedAndTheWayOut) {
  const fs::path exe = scratch("none") / "bin" / "shadow4d";
  touch(exe);
  touch(exe.parent_path() / kBuildTreeMarker, "/nonexistent/checkout\n");
  try {
    find_data_dirs(exe, "/nonexistent/data");
    FAIL() << "no data, yet found";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find((exe.parent_path().parent_path() / "share" / "shadow4d").string()), std::string::npos) << m;
    EXPECT_NE(m.find("S4D_DATA_DIR=/nonexistent/data (no such folder)"), std::string::npos) << m;
    EXPECT_NE(m.find("/nonexistent/checkout"), std::string::npos) << m;
    EXPECT_NE(m.find("set S4D_DATA_DIR"), std::string::npos) << m;
  }
}

TEST(DataPaths, ThisTestProgramReadsTheCheckoutThroughItsMarker) {
  // The build writes the marker beside every executable; nothing of the source is compiled in.
  const fs::path exe = executable_path();
  ASSERT_FALSE(exe.empty());
  EXPECT_EQ(fs::canonical(build_tree_source(exe)), fs::canonical(S4D_SOURCE_DIR));
  unsetenv("S4D_DATA_DIR");
  EXPECT_EQ(fs::canonical(data_dirs().knots), fs::canonical(fs::path(S4D_SOURCE_DIR) / "data" / "knots"));
}

TEST(DataPaths, ExamplesAreFoundFromAnyFolderByTheirPathInTheDataOrTheirFileName) {
  const fs::path here = fs::current_path();
  fs::current_path(scratch("elsewhere"));
  unsetenv("S4D_DATA_DIR");
  const fs::path root = fs::canonical(S4D_SOURCE_DIR);
  EXPECT_EQ(fs::canonical(find_example("scenes/cloth.json")), root / "scenes" / "cloth.json");
  EXPECT_EQ(fs::canonical(find_example("cloth.json")), root / "scenes" / "cloth.json");
  EXPECT_EQ(fs::canonical(find_example("spun-trefoil-tighten.json")), root / "scenarios" / "spun-trefoil-tighten.json");
  // A file of the working folder wins over the example of the same name; a missing one is left
  // as given, for its reader to report.
  touch("cloth.json");
  EXPECT_EQ(find_example("cloth.json"), fs::path("cloth.json"));
  EXPECT_EQ(find_example("no-such-example.json"), fs::path("no-such-example.json"));
  fs::current_path(here);
}

}  // namespace
}  // namespace s4d
