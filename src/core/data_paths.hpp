// Where the program's data is at run time: the knot tables, the example scenarios and scenes.
// One search for every reader, so that an installed program, a build run in place and a copy
// moved elsewhere all find the same files, and a failure names every folder tried. Nothing here
// is compiled in from the source tree: an installed program finds its data beside itself.
#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace s4d {

// The data folders found. A data root has one of two layouts: installed (share/shadow4d with
// knots/, scenarios/, scenes/) or a source checkout (data/knots/, scenarios/, scenes/).
struct DataDirs {
  std::filesystem::path root;
  std::filesystem::path knots;      // knot_index.tsv, link_table.tsv, rolfsen_braids.txt
  std::filesystem::path scenarios;  // the paper's scenarios (*.json)
  std::filesystem::path scenes;     // the example scenes
  std::string found_by;             // which rule found it, for messages and --version
};

// The data in `root` if it has either layout (its knots folder exists), else nothing.
std::optional<DataDirs> data_dirs_in(const std::filesystem::path& root);

// The data root installed beside an executable: <exe's folder>/../share/shadow4d.
std::filesystem::path installed_data_root(const std::filesystem::path& executable);

// The file a CMake build writes beside each of its executables, holding the source tree's path,
// so that a program run in the build tree (the tests, the demo) reads the checkout's data.
// `cmake --install` and the package copy the executable without it.
inline constexpr const char* kBuildTreeMarker = "shadow4d-source-data";
// The source tree named by the marker beside `executable`; empty when there is none.
std::filesystem::path build_tree_source(const std::filesystem::path& executable);

// The search, in order: the data installed beside `executable`; `env_dir` ($S4D_DATA_DIR) when
// not empty; the source tree named by the build-tree marker beside `executable`. Throws Error
// naming each folder tried and why it was passed over.
DataDirs find_data_dirs(const std::filesystem::path& executable, const std::string& env_dir);

// This process's executable (/proc/self/exe), or empty where it cannot be read.
std::filesystem::path executable_path();

// find_data_dirs for this process: its executable and $S4D_DATA_DIR.
DataDirs data_dirs();
// The same, or nothing with the reason in `why` (for a window that goes on without examples).
std::optional<DataDirs> try_data_dirs(std::string* why = nullptr);

// A file the user named, else one of the examples: `spec` when it exists, is absolute or no data
// is found; otherwise the first existing of <root>/spec, <scenes>/spec, <scenarios>/spec. So
// `shadow4d render scenes/cloth.json` or `shadow4d cloth.json` opens the example from any
// folder. When nothing matches, `spec` unchanged, for its reader to report as missing.
std::filesystem::path find_example(const std::string& spec);

}  // namespace s4d
