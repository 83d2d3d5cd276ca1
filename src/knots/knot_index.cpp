// Loading and querying the knot index file.
#include "knots/knot_index.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <sstream>

#include "core/data_paths.hpp"
#include "core/error.hpp"

namespace s4d {

const std::string& KnotTableEntry::display_name() const {
  if (!rolfsen_name.empty()) return rolfsen_name;
  if (!dt_name.empty()) return dt_name;
  return regina_name;
}

std::string format_index_line(const KnotTableEntry& e) {
  std::ostringstream out;
  auto field = [](const std::string& s) { return s.empty() ? std::string("-") : s; };
  out << std::hex << e.key << '\t' << e.mirror_key << std::dec << '\t' << e.crossings << '\t'
      << field(e.regina_name) << '\t' << field(e.dt_name) << '\t' << field(e.rolfsen_name) << '\t'
      << (e.homfly_symmetric ? "s" : "") << (e.amphichiral ? "A" : "")
      << (e.alternating ? "a" : "") << (!e.homfly_symmetric && !e.alternating ? "-" : "");
  if (!e.sig.empty()) out << '\t' << e.sig;
  return out.str();
}

std::string canonical_knot_name(const std::string& name) {
  const auto first = name.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  std::string s = name.substr(first, name.find_last_not_of(" \t") - first + 1);
  std::string t = s;
  if (t.size() > 1 && (t[0] == 'K' || t[0] == 'k') && std::isdigit(static_cast<unsigned char>(t[1])))
    t.erase(0, 1);
  // crossings, then letters (a/n, and Regina's h/t/s), then an optional '_', then the number
  std::size_t i = 0;
  while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i;
  const std::size_t letters = i;
  while (i < t.size() && std::isalpha(static_cast<unsigned char>(t[i]))) ++i;
  if (letters == 0 || i == letters || i == t.size()) return s;
  const std::string head = t.substr(0, i);
  if (head[letters] != 'a' && head[letters] != 'n') return s;
  if (t[i] == '_') ++i;
  const std::string digits = t.substr(i);
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return s;
  const auto nz = digits.find_first_not_of('0');
  return head + "_" + (nz == std::string::npos ? "0" : digits.substr(nz));
}

KnotIndex KnotIndex::parse(const std::string& text, const std::string& origin) {
  KnotIndex index;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string key, mirror, crossings, regina, dt, rolfsen, flags, sig, extra;
    if (!(fields >> key >> mirror >> crossings >> regina >> dt >> rolfsen >> flags))
      throw ParseError(origin, line_no, "expected 7 or 8 tab-separated fields");
    fields >> sig;
    if (fields >> extra) throw ParseError(origin, line_no, "expected 7 or 8 tab-separated fields");
    KnotTableEntry e;
    try {
      std::size_t used = 0;
      e.key = std::stoull(key, &used, 16);
      if (used != key.size()) throw std::invalid_argument("key");
      e.mirror_key = std::stoull(mirror, &used, 16);
      if (used != mirror.size()) throw std::invalid_argument("mirror key");
      e.crossings = std::stoi(crossings, &used);
      if (used != crossings.size() || e.crossings < 0) throw std::invalid_argument("crossings");
    } catch (const std::exception&) {
      throw ParseError(origin, line_no, "bad key or crossing count");
    }
    auto opt = [](const std::string& s) { return s == "-" ? std::string() : s; };
    e.regina_name = opt(regina);
    e.dt_name = opt(dt);
    e.rolfsen_name = opt(rolfsen);
    e.sig = sig;
    for (char f : flags) {
      if (f == 's') e.homfly_symmetric = true;
      else if (f == 'A') e.amphichiral = true;
      else if (f == 'a') e.alternating = true;
      else if (f != '-') throw ParseError(origin, line_no, std::string("unknown flag '") + f + "'");
    }
    const int i = static_cast<int>(index.entries_.size());
    index.by_key_.emplace(e.key, i);
    for (const auto* n : {&e.regina_name, &e.dt_name, &e.rolfsen_name})
      if (!n->empty()) index.by_name_.emplace(canonical_knot_name(*n), i);
    if (e.crossings > index.max_crossings_) index.max_crossings_ = e.crossings;
    index.entries_.push_back(std::move(e));
  }
  if (index.entries_.empty()) throw ParseError(origin, 0, "the knot index is empty");
  return index;
}

KnotIndex KnotIndex::load(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read the knot index " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), path.string());
}

std::filesystem::path KnotIndex::shipped_path() {
  if (const char* env = std::getenv("S4D_KNOT_INDEX"); env && *env) return env;
  return data_dirs().knots / "knot_index.tsv";
}

const KnotIndex& KnotIndex::shipped() {
  static const KnotIndex index = load(shipped_path());  // C++ guarantees one thread-safe load
  return index;
}

std::vector<const KnotTableEntry*> KnotIndex::with_key(std::uint64_t key) const {
  std::vector<const KnotTableEntry*> out;
  const auto [lo, hi] = by_key_.equal_range(key);
  for (auto it = lo; it != hi; ++it) out.push_back(&entries_[it->second]);
  return out;
}

const KnotTableEntry* KnotIndex::find_name(const std::string& name) const {
  const auto it = by_name_.find(canonical_knot_name(name));
  return it == by_name_.end() ? nullptr : &entries_[it->second];
}

}  // namespace s4d
