// Loading and querying the link table file.
#include "knots/link_table.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/data_paths.hpp"
#include "core/error.hpp"
#include "knots/knot_index.hpp"

namespace s4d {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::size_t a = 0;
  for (;;) {
    const auto b = s.find(sep, a);
    out.push_back(s.substr(a, b == std::string::npos ? std::string::npos : b - a));
    if (b == std::string::npos) return out;
    a = b + 1;
  }
}

template <typename T, typename F>
std::string join(const std::vector<T>& v, F&& text) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) s += ',';
    s += text(v[i]);
  }
  return s;
}

std::string hex(std::uint64_t k) {
  std::ostringstream o;
  o << std::hex << k;
  return o.str();
}

}  // namespace

std::string canonical_link_name(const std::string& name_in) {
  const auto first = name_in.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  std::string s = name_in.substr(first, name_in.find_last_not_of(" \t") - first + 1);
  // Orientation suffixes: KnotInfo's "{1,0}", knotpy's "++" / "+-".
  if (const auto brace = s.find('{'); brace != std::string::npos && s.back() == '}') s.erase(brace);
  while (!s.empty() && (s.back() == '+' || s.back() == '-')) s.pop_back();
  if (s.size() < 4 || (s[0] != 'L' && s[0] != 'l')) return {};
  std::size_t i = 1;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  if (i == 1 || i >= s.size()) return {};
  const char kind = static_cast<char>(std::tolower(static_cast<unsigned char>(s[i])));
  if (kind != 'a' && kind != 'n') return {};
  const std::string crossings = s.substr(1, i - 1);
  ++i;
  if (i < s.size() && s[i] == '_') ++i;
  const std::string digits = s.substr(i);
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return {};
  const auto nz = digits.find_first_not_of('0');
  if (nz == std::string::npos) return {};
  return "L" + crossings + kind + digits.substr(nz);
}

std::string format_link_line(const LinkTableEntry& e) {
  const auto same = [](const std::string& x) { return x; };
  const auto num = [](int x) { return std::to_string(x); };
  std::ostringstream out;
  out << e.name << '\t' << e.crossings << '\t' << e.components << '\t' << (e.alias.empty() ? "-" : e.alias)
      << '\t' << join(e.keys, hex) << '\t' << join(e.mirror_keys, hex) << '\t'
      << join(e.component_knots, same) << '\t' << join(e.abs_linking, num) << '\t' << e.pd;
  return out.str();
}

LinkTable LinkTable::parse(const std::string& text, const std::string& origin) {
  LinkTable table;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const auto f = split(line, '\t');
    if (f.size() != 9) throw ParseError(origin, line_no, "expected 9 tab-separated fields");
    LinkTableEntry e;
    e.name = canonical_link_name(f[0]);
    if (e.name.empty() || e.name != f[0]) throw ParseError(origin, line_no, "bad link name '" + f[0] + "'");
    e.alias = f[3] == "-" ? "" : f[3];
    try {
      std::size_t used = 0;
      e.crossings = std::stoi(f[1], &used);
      if (used != f[1].size() || e.crossings < 2) throw std::invalid_argument("crossings");
      e.components = std::stoi(f[2], &used);
      if (used != f[2].size() || e.components < 2) throw std::invalid_argument("components");
      for (int side = 0; side < 2; ++side)
        for (const auto& k : split(f[4 + side], ',')) {
          (side ? e.mirror_keys : e.keys).push_back(std::stoull(k, &used, 16));
          if (used != k.size()) throw std::invalid_argument("key");
        }
      for (const auto& l : split(f[7], ',')) {
        e.abs_linking.push_back(std::stoi(l, &used));
        if (used != l.size() || e.abs_linking.back() < 0) throw std::invalid_argument("linking");
      }
    } catch (const std::exception&) {
      throw ParseError(origin, line_no, "bad number in " + e.name);
    }
    e.component_knots = split(f[6], ',');
    e.pd = f[8];
    if (static_cast<int>(e.component_knots.size()) != e.components ||
        static_cast<int>(e.abs_linking.size()) != e.components * (e.components - 1) / 2)
      throw ParseError(origin, line_no, e.name + ": the component lists do not match its components");
    if (e.pd.size() < 2 || e.pd.front() != '[' || e.pd.back() != ']')
      throw ParseError(origin, line_no, e.name + ": the PD code is not a [[...],...] list");
    const int i = static_cast<int>(table.entries_.size());
    for (auto k : e.keys) table.by_key_.emplace(k, i);
    for (auto k : e.mirror_keys) table.by_mirror_key_.emplace(k, i);
    table.by_name_.emplace(lower(e.name), i);
    if (!e.alias.empty()) table.by_name_.emplace(lower(e.alias), i);
    if (e.crossings > table.max_crossings_) table.max_crossings_ = e.crossings;
    table.entries_.push_back(std::move(e));
  }
  if (table.entries_.empty()) throw ParseError(origin, 0, "the link table is empty");
  return table;
}

LinkTable LinkTable::load(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read the link table " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), path.string());
}

std::filesystem::path LinkTable::shipped_path() {
  if (const char* env = std::getenv("S4D_LINK_TABLE"); env && *env) return env;
  return data_dirs().knots / "link_table.tsv";
}

const LinkTable& LinkTable::shipped() {
  static const LinkTable table = load(shipped_path());  // C++ guarantees one thread-safe load
  return table;
}

const LinkTableEntry* LinkTable::find_name(const std::string& name) const {
  std::string key = canonical_link_name(name);
  if (key.empty()) {
    const auto a = name.find_first_not_of(" \t");
    key = a == std::string::npos ? "" : name.substr(a, name.find_last_not_of(" \t") - a + 1);
  }
  const auto it = by_name_.find(lower(key));
  return it == by_name_.end() ? nullptr : &entries_[it->second];
}

std::vector<LinkMatch> LinkTable::with_key(std::uint64_t key) const {
  std::vector<LinkMatch> out;
  auto at = [&](int i) -> LinkMatch& {
    for (auto& m : out)
      if (m.entry == &entries_[i]) return m;
    out.push_back({&entries_[i], false, false});
    return out.back();
  };
  for (auto [lo, hi] = by_key_.equal_range(key); lo != hi; ++lo) at(lo->second).as_table = true;
  for (auto [lo, hi] = by_mirror_key_.equal_range(key); lo != hi; ++lo) at(lo->second).mirror = true;
  return out;
}

}  // namespace s4d
