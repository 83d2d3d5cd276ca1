// KnotIndex: the prime knots of Regina's census (up to 14 crossings) keyed by the fingerprint of
// their HOMFLY-PT polynomial, read from data/knots/knot_index.tsv (made by tools/build_knot_index).
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace s4d {

struct KnotTableEntry {
  std::string regina_name;   // Regina's census name, e.g. "8ah_11"
  std::string dt_name;       // Dowker-Thistlethwaite name, e.g. "8a_11" (empty above 12 crossings)
  std::string rolfsen_name;  // Rolfsen name up to 10 crossings, e.g. "8_19" (else empty)
  int crossings = 0;
  // Fingerprints (homfly_fingerprint) of the reference diagram and of its mirror image. The
  // reference is the Rolfsen table's (Knot Atlas) diagram when there is a Rolfsen name, else the
  // census diagram. mirror_key is 0 when not stored (only entries up to kFactorCrossings have it).
  std::uint64_t key = 0;
  std::uint64_t mirror_key = 0;
  bool homfly_symmetric = false;  // HOMFLY-PT cannot tell this knot from its mirror image
  bool amphichiral = false;       // proven equal to its mirror image (Reidemeister moves found)
  bool alternating = false;
  // Regina's knot signature (Link::fromKnotSig) of a minimal diagram of this knot in the reference
  // chirality (the one `key` belongs to), so the table can draw it; empty in old index files.
  std::string sig;

  // The name people use: Rolfsen's if any, else the DT name, else Regina's.
  const std::string& display_name() const;
};

class KnotIndex {
 public:
  // Factors of composite knots are searched among entries up to this many crossings.
  static constexpr int kFactorCrossings = 10;

  // The index shipped with the program: $S4D_KNOT_INDEX if set, else knot_index.tsv of the data
  // folder (core/data_paths.hpp). Loaded once (thread-safe); throws Error if missing or malformed.
  static const KnotIndex& shipped();
  static std::filesystem::path shipped_path();
  // Reads an index file; throws ParseError with file and line on malformed lines.
  static KnotIndex load(const std::filesystem::path& path);
  // The same from text (`origin` names it in errors).
  static KnotIndex parse(const std::string& text, const std::string& origin);

  const std::vector<KnotTableEntry>& entries() const { return entries_; }
  // Entries whose reference key equals `key`.
  std::vector<const KnotTableEntry*> with_key(std::uint64_t key) const;
  // Any of the three names, in any usual spelling (canonical_knot_name): "12a_803", "12a_0803",
  // "K12a803" and "12a803" are one knot.
  const KnotTableEntry* find_name(const std::string& name) const;
  int max_crossings() const { return max_crossings_; }

 private:
  std::vector<KnotTableEntry> entries_;
  std::unordered_multimap<std::uint64_t, int> by_key_;
  std::unordered_map<std::string, int> by_name_;
  int max_crossings_ = 0;
};

// The one spelling of a table name: a leading "K" dropped, the underscore put in and the number's
// leading zeros dropped ("K11n34" -> "11n_34", "12a_0803" -> "12a_803", "13nh_0517" ->
// "13nh_517"); Rolfsen names ("3_1") and anything else are returned trimmed but unchanged.
std::string canonical_knot_name(const std::string& name);

// One line of the index file (the tool writes with it, the loader reads with it):
// key  mirror_key  crossings  regina  dt  rolfsen  flags  [sig]  ('-' for an empty field; keys in
// hex; flags: 's' HOMFLY-symmetric, 'A' proven amphichiral, 'a' alternating, '-' none; sig as
// KnotTableEntry::sig, absent from old files).
std::string format_index_line(const KnotTableEntry& e);

}  // namespace s4d
