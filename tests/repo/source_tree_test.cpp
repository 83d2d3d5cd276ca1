// The source tree keeps its own promises: the layers' includes point down only (the order
// docs/architecture.md draws), and a file's index of sections names exactly the sections below it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
const fs::path kRoot = S4D_SOURCE_DIR;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> sources(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && (e.path().extension() == ".cpp" || e.path().extension() == ".hpp")) out.push_back(e.path());
  return out;
}

// The layer a file of src/ belongs to: its folder, with interact's three sub-layers apart.
std::string layer_of(const std::string& relative) {
  const std::string first = relative.substr(0, relative.find('/'));
  if (first != "interact") return first;
  const std::size_t slash = relative.find('/', first.size() + 1);
  return slash == std::string::npos ? first : relative.substr(0, slash);
}

// What each layer may include besides itself: the layers directly below it; the closure is taken
// below. The same order as CMakeLists.txt's s4d_layer calls.
const std::map<std::string, std::set<std::string>> kBelow = {
    {"core", {}},
    {"shape", {"core"}},
    {"proximity", {"shape"}},
    {"knots", {"proximity"}},
    {"io", {"shape"}},
    {"physics", {"proximity"}},
    {"haptics", {"core"}},
    {"audio", {"core"}},
    {"scenario", {"physics", "knots", "io"}},
    {"view", {"io", "proximity"}},
    {"interact/live", {"scenario", "haptics", "audio"}},
    {"interact/session", {"interact/live"}},
    {"interact/tools", {"interact/session", "view"}},
    {"render", {"view", "knots"}},
    {"app", {"render", "interact/tools"}},
};

std::set<std::string> reachable(const std::string& layer) {
  std::set<std::string> out;
  std::vector<std::string> todo{layer};
  while (!todo.empty()) {
    const std::string l = todo.back();
    todo.pop_back();
    const auto it = kBelow.find(l);
    if (it == kBelow.end()) continue;
    for (const std::string& b : it->second)
      if (out.insert(b).second) todo.push_back(b);
  }
  return out;
}

TEST(SourceTree, EveryLayerIncludesOnlyLayersBelowIt) {
  const std::regex include(R"re(#include "([a-z_]+(/(live|session|tools))?)/)re");
  int checked = 0;
  for (const fs::path& p : sources(kRoot / "src")) {
    const std::string rel = fs::relative(p, kRoot / "src").generic_string();
    const std::string layer = layer_of(rel);
    ASSERT_TRUE(kBelow.count(layer)) << rel << " is in a folder no layer names: add it to CMakeLists.txt, "
                                     << "docs/architecture.md and this test";
    const std::set<std::string> allowed = reachable(layer);
    const std::string text = read(p);
    for (std::sregex_iterator m(text.begin(), text.end(), include), end; m != end; ++m) {
      const std::string target = (*m)[1];
      if (target == layer || !kBelow.count(target)) continue;  // itself, or a library's header
      EXPECT_TRUE(allowed.count(target)) << rel << " includes " << target << "/, which is not below " << layer;
      ++checked;
    }
  }
  EXPECT_GT(checked, 300) << "the includes were not found: has the include style changed?";
}

// The name a [SECTION] mention gives: what follows the tag up to a colon, comma, bracket, full stop
// or a run of spaces.
std::string section_name(const std::string& after_tag) {
  std::string name;
  for (std::size_t i = 0; i < after_tag.size(); ++i) {
    const char c = after_tag[i];
    if (c == ':' || c == ',' || c == '(' || c == '.' || c == ';' || c == '[') break;
    if (c == ' ' && i + 1 < after_tag.size() && after_tag[i + 1] == ' ') break;
    name += c;
  }
  while (!name.empty() && name.back() == ' ') name.pop_back();
  return name;
}

struct Sections {
  std::vector<std::string> index;     // named in the file's opening comment
  std::vector<std::string> headings;  // "// [SECTION] name" lines below it
};

Sections sections_of(const std::string& text) {
  Sections s;
  std::istringstream in(text);
  std::string line;
  bool opening = true;  // the comment block the file starts with
  const std::string tag = "[SECTION] ";
  while (std::getline(in, line)) {
    const std::size_t first = line.find_first_not_of(' ');
    const bool comment = first != std::string::npos && line.compare(first, 2, "//") == 0;
    if (opening && !comment) opening = false;
    if (opening) {
      for (std::size_t at = line.find(tag); at != std::string::npos; at = line.find(tag, at + 1))
        s.index.push_back(section_name(line.substr(at + tag.size())));
    } else if (comment && line.compare(first, 2 + 1 + tag.size(), "// " + tag) == 0) {
      s.headings.push_back(section_name(line.substr(first + 3 + tag.size())));
    }
  }
  return s;
}

TEST(SourceTree, SectionIndexesNameExactlyTheSectionsBelowThem) {
  int indexed = 0;
  for (const fs::path& dir : {kRoot / "src", kRoot / "apps", kRoot / "tools", kRoot / "bench", kRoot / "tests"}) {
    for (const fs::path& p : sources(dir)) {
      const Sections s = sections_of(read(p));
      const std::string rel = fs::relative(p, kRoot).generic_string();
      if (s.index.empty()) {
        EXPECT_LT(s.headings.size(), 2u) << rel << " has sections but no index of them in its opening comment";
        continue;
      }
      ++indexed;
      const std::set<std::string> index(s.index.begin(), s.index.end()), headings(s.headings.begin(), s.headings.end());
      for (const std::string& name : index)
        EXPECT_TRUE(headings.count(name)) << rel << ": the index names [SECTION] " << name << ", which is not below";
      for (const std::string& name : headings)
        EXPECT_TRUE(index.count(name)) << rel << ": [SECTION] " << name << " is missing from the index at the top";
    }
  }
  EXPECT_GT(indexed, 5);
}

TEST(SourceTree, ASectionNameEndsWhereItsDescriptionBegins) {
  EXPECT_EQ(section_name("rows: the resampled stroke"), "rows");
  EXPECT_EQ(section_name("Dialogs (open, save,"), "Dialogs");
  EXPECT_EQ(section_name("Opening   [SECTION] Menu bar"), "Opening");
  EXPECT_EQ(section_name("the loop"), "the loop");
  const Sections s = sections_of("// a: [SECTION] one, [SECTION] two\n#include <x>\n// [SECTION] one\n  // [SECTION] two (more)\n");
  EXPECT_EQ(s.index, (std::vector<std::string>{"one", "two"}));
  EXPECT_EQ(s.headings, (std::vector<std::string>{"one", "two"}));
}

}  // namespace
