// LinkTable: Thistlethwaite's table of prime non-split links of 2 to 11 crossings (KnotInfo's
// LinkInfo), read from data/knots/link_table.tsv (made by tools/build_link_table): each link's PD
// code and the HOMFLY-PT fingerprints of all its orientations and of their mirror images.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace s4d {

struct LinkTableEntry {
  std::string name;   // Thistlethwaite's, as KnotInfo writes it: "L6a4"
  std::string alias;  // a common name ("Borromean rings"), or ""
  int crossings = 0;
  int components = 0;
  // Fingerprints (homfly_fingerprint) of the table's diagram with every choice of orientations
  // (each component but the first reversed or not), deduplicated; and of their mirror images.
  std::vector<std::uint64_t> keys;
  std::vector<std::uint64_t> mirror_keys;
  // The components' knot types up to mirror image ("unknot", "3_1"), sorted; "?" where the knot
  // index could not name one.
  std::vector<std::string> component_knots;
  std::vector<int> abs_linking;  // |lk| of every pair of components, sorted
  // PD code of the table's diagram (KnotInfo's, first orientation), edges numbered along the
  // components as Regina's Link::fromPD reads them: "[[1,5,2,4],[3,1,4,6],...]".
  std::string pd;

  // "L6a4 (Borromean rings)" or "L7n1".
  std::string label() const { return alias.empty() ? name : name + " (" + alias + ")"; }
};

// A table link that a fingerprint matches, as drawn or as the mirror image (or both, when the
// HOMFLY-PT polynomial cannot tell the link from its mirror image).
struct LinkMatch {
  const LinkTableEntry* entry = nullptr;
  bool as_table = false;
  bool mirror = false;
};

class LinkTable {
 public:
  // The table shipped with the program: $S4D_LINK_TABLE if set, else link_table.tsv of the data
  // folder (core/data_paths.hpp). Loaded once (thread-safe); throws Error if missing or malformed.
  static const LinkTable& shipped();
  static std::filesystem::path shipped_path();
  static LinkTable load(const std::filesystem::path& path);
  // Reads the text of a table file (`origin` names it in errors); throws ParseError.
  static LinkTable parse(const std::string& text, const std::string& origin);

  const std::vector<LinkTableEntry>& entries() const { return entries_; }
  // "L6a4", "l6a4", "L6a_4", "L6a4{1,0}", "L6a4++" or the alias ("borromean rings"); null if none.
  const LinkTableEntry* find_name(const std::string& name) const;
  // Every entry one of whose orientations, or their mirror images, has this fingerprint.
  std::vector<LinkMatch> with_key(std::uint64_t key) const;
  int max_crossings() const { return max_crossings_; }

 private:
  std::vector<LinkTableEntry> entries_;
  std::unordered_multimap<std::uint64_t, int> by_key_;         // keys: entry index
  std::unordered_multimap<std::uint64_t, int> by_mirror_key_;  // mirror_keys: entry index
  std::unordered_map<std::string, int> by_name_;               // lower-case name and alias
  int max_crossings_ = 0;
};

// The table's spelling of a link name, orientation suffixes dropped: "l6a_4{1,0}" -> "L6a4",
// "L2a_1+-" -> "L2a1"; "" when `name` is not of the form L<crossings><a|n><number>.
std::string canonical_link_name(const std::string& name);

// One line of the table file (the tool writes with it, the loader reads with it), tab-separated:
// name  crossings  components  alias  keys  mirror_keys  component_knots  abs_linking  pd
// ('-' for an empty alias; keys in hex and lists joined by ',').
std::string format_link_line(const LinkTableEntry& e);

}  // namespace s4d
