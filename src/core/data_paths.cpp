#include "core/data_paths.hpp"

#include <cstdlib>
#include <fstream>
#include <system_error>

#include "core/error.hpp"

namespace s4d {

namespace fs = std::filesystem;

namespace {

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

std::string env_data_dir() {
  const char* env = std::getenv("S4D_DATA_DIR");
  return env ? env : "";
}

constexpr const char* kLayouts =
    "a data folder holds knots/, scenarios/ and scenes/ (share/shadow4d of an install) or is a "
    "source checkout (data/knots/, scenarios/, scenes/)";

}  // namespace

std::optional<DataDirs> data_dirs_in(const fs::path& root) {
  if (root.empty()) return std::nullopt;
  if (is_dir(root / "knots")) return DataDirs{root, root / "knots", root / "scenarios", root / "scenes", {}};
  if (is_dir(root / "data" / "knots"))
    return DataDirs{root, root / "data" / "knots", root / "scenarios", root / "scenes", {}};
  return std::nullopt;
}

fs::path installed_data_root(const fs::path& executable) {
  return (executable.parent_path() / ".." / "share" / "shadow4d").lexically_normal();
}

fs::path build_tree_source(const fs::path& executable) {
  std::ifstream in(executable.parent_path() / kBuildTreeMarker);
  std::string line;
  if (!in || !std::getline(in, line)) return {};
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line;
}

DataDirs find_data_dirs(const fs::path& executable, const std::string& env_dir) {
  std::string tried;
  auto note = [&tried](const std::string& s) { tried += (tried.empty() ? "" : "; ") + s; };
  if (executable.empty()) {
    note("beside the executable (/proc/self/exe could not be read)");
  } else {
    const fs::path installed = installed_data_root(executable);
    if (auto d = data_dirs_in(installed)) {
      d->found_by = "installed beside " + executable.string();
      return *d;
    }
    note(installed.string() + " (beside " + executable.string() + ": " +
         (is_dir(installed) ? "no knots/ in it)" : "no such folder)"));
  }
  if (!env_dir.empty()) {
    if (auto d = data_dirs_in(env_dir)) {
      d->found_by = "S4D_DATA_DIR";
      return *d;
    }
    note("S4D_DATA_DIR=" + env_dir + " (" + (is_dir(env_dir) ? "no knots/ or data/knots/ in it)" : "no such folder)"));
  } else {
    note("S4D_DATA_DIR (not set)");
  }
  if (!executable.empty()) {
    const fs::path source = build_tree_source(executable);
    if (auto d = data_dirs_in(source)) {
      d->found_by = "the source tree of the build at " + executable.parent_path().string();
      return *d;
    }
    if (!source.empty()) note(source.string() + " (the source tree of this build: no data/knots/ in it)");
  }
  throw Error("cannot find shadow4d's data (the knot tables, scenarios and scenes): looked in " + tried +
              ". Reinstall shadow4d, or set S4D_DATA_DIR to its data folder: " + kLayouts + ".");
}

fs::path executable_path() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : p;
}

DataDirs data_dirs() { return find_data_dirs(executable_path(), env_data_dir()); }

std::optional<DataDirs> try_data_dirs(std::string* why) {
  try {
    return data_dirs();
  } catch (const Error& e) {
    if (why) *why = e.what();
    return std::nullopt;
  }
}

fs::path find_example(const std::string& spec) {
  const fs::path given = spec;
  std::error_code ec;
  if (spec.empty() || given.is_absolute() || fs::exists(given, ec)) return given;
  const std::optional<DataDirs> d = try_data_dirs();
  if (!d) return given;  // missing as given, which its reader says
  for (const fs::path& folder : {d->root, d->scenes, d->scenarios})
    if (is_file(folder / given)) return (folder / given).lexically_normal();
  return given;
}

}  // namespace s4d
