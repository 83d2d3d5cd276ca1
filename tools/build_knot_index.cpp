// Builds data/knots/knot_index.tsv: every prime knot of Regina's census (up to 14 crossings) with
// the fingerprint of its HOMFLY-PT polynomial, a signature of its minimal diagram, Rolfsen names
// (up to 10 crossings) matched from the braid table data/knots/rolfsen_braids.txt, and, when a
// table of DT codes is given, Dowker-Thistlethwaite names for the knots the census leaves unnamed
// (13 and 14 crossings).
//   build_knot_index --census knot-census.rga --rolfsen rolfsen_braids.txt --out knot_index.tsv
//   build_knot_index ... --dt-names DIR    (Knotscape's 13A.dts, 13N.dts, ...: see data/knots/README.md)
//   build_knot_index ... --dt-names FILE   (lines "13n_5018  <DT code>"; '#' comments)
//   build_knot_index ... --check   (exit 1 if the existing --out file differs)
#include <link/link.h>
#include <packet/packet.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <functional>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "knots/braid_closure.hpp"
#include "knots/knot_index.hpp"
#include "knots/knot_info.hpp"
#include "knots/knot_invariants.hpp"
#include "knots/polynomial.hpp"
#include "knots/regina_link.hpp"

using namespace s4d;

namespace {

// Regina's Laurent2 hides its terms. By Morton's bounds the powers of alpha of an n-crossing
// diagram with s Seifert circles lie within writhe -+ (s - 1), so within [-2n, 2n] (n + 2 was too
// small: 11a_263's HOMFLY-PT has alpha^-14); the powers of z within [0, n].
Laurent2 homfly_of(const regina::Link& link) {
  const auto& p = link.homflyAZ();
  const long bound = 2 * static_cast<long>(link.size()) + 2;
  Laurent2 r;
  for (long i = -bound; i <= bound; ++i)
    for (long j = -bound; j <= bound; ++j)
      if (!p(i, j).isZero()) r.add(i, j, p(i, j).longValue());
  return r;
}

// "9nh_2 (DT: 9n_5)" -> ("9nh_2", "9n_5"); "13ah_123" -> ("13ah_123", "").
std::pair<std::string, std::string> split_label(const std::string& label) {
  const auto sp = label.find(' ');
  if (sp == std::string::npos) return {label, ""};
  std::string dt;
  const auto at = label.find("(DT: ");
  if (at != std::string::npos) {
    const auto end = label.find(')', at);
    dt = label.substr(at + 5, end - at - 5);
  }
  return {label.substr(0, sp), dt};
}

// HOMFLY-PT cannot separate a few pairs (10_25/10_56, 10_40/10_103). Then we look for a census
// diagram among all diagrams reachable from the table's diagram by Reidemeister moves that add at
// most `height` crossings (Regina's rewrite): finding it proves the two are the same knot.
int find_by_rewriting(const regina::Link& from, const std::vector<std::string>& sigs, int max_height) {
  for (int height = 1; height <= max_height; ++height) {
    int found = -1;
    from.rewrite(height, 1, nullptr, [&](const std::string& sig, const regina::Link&) {
      for (std::size_t i = 0; i < sigs.size(); ++i)
        if (sig == sigs[i]) {
          found = static_cast<int>(i);
          return true;
        }
      return false;
    });
    if (found >= 0) return found;
  }
  return -1;
}

// One code of a table of DT codes: its name ("13n_5018") and the code, numerical or alphabetical.
struct DtCode {
  std::string name, code;
};

// A table of DT codes: a file of "NAME CODE" lines ('#' comments; commas and brackets are ignored),
// or a directory of Knotscape's tables as the KnotTheory` package ships them (13A.dts, 13N.dts,
// ...: one alphabetical code per line, line k being 13a_k, 13n_k, ...).
std::vector<DtCode> read_dt_codes(const std::string& path) {
  std::vector<DtCode> codes;
  if (std::filesystem::is_directory(path)) {
    std::vector<std::pair<std::pair<int, char>, std::filesystem::path>> tables;
    for (const auto& f : std::filesystem::directory_iterator(path)) {
      const std::string n = f.path().filename().string();
      std::size_t i = 0;
      while (i < n.size() && std::isdigit(static_cast<unsigned char>(n[i]))) ++i;
      if (i == 0 || i + 5 != n.size() || n.substr(i + 1) != ".dts") continue;
      const char kind = static_cast<char>(std::tolower(static_cast<unsigned char>(n[i])));
      if (kind != 'a' && kind != 'n') continue;
      tables.push_back({{std::stoi(n.substr(0, i)), kind}, f.path()});
    }
    std::sort(tables.begin(), tables.end());
    if (tables.empty()) throw std::runtime_error(path + " holds no Knotscape table (13A.dts, 13N.dts, ...)");
    for (const auto& [key, file] : tables) {
      std::ifstream in(file);
      if (!in) throw std::runtime_error("cannot read " + file.string());
      std::string line;
      int k = 0;
      while (std::getline(in, line)) {
        line.erase(std::remove_if(line.begin(), line.end(), [](unsigned char c) { return std::isspace(c); }),
                   line.end());
        if (line.empty()) continue;
        codes.push_back({std::to_string(key.first) + key.second + "_" + std::to_string(++k), line});
      }
    }
    return codes;
  }
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    for (char& ch : line)
      if (ch == ',' || ch == '[' || ch == ']' || ch == '(' || ch == ')') ch = ' ';
    std::istringstream fields(line);
    std::string name, code, v;
    if (!(fields >> name)) continue;
    while (fields >> v) code += (code.empty() ? "" : " ") + v;
    codes.push_back({canonical_knot_name(name), code});
  }
  return codes;
}

// What matching a table of DT codes with the census did.
struct DtNaming {
  int confirmed = 0;       // codes whose name the census already gives, checked to agree
  int named = 0;           // census knots given a DT name
  int by_homfly = 0;       // ... because HOMFLY-PT left one census knot
  int by_diagram = 0;      // ... because the code's diagram is a census diagram (equal signatures)
  int by_rewriting = 0;    // ... because Reidemeister moves from both reach a common diagram
  int by_covers = 0;       // ... because covers of the knot group left one
  int by_elimination = 0;  // ... because the others of its HOMFLY-PT class were named before
  int unresolved = 0;
};

// Covers of the knot group of index 2..max_index with their homology: tells apart many mutants,
// which HOMFLY-PT cannot.
std::string covers_of(const regina::Link& link, int max_index) {
  return cover_signature(diagram_from_regina(link), max_index);
}

// Each code is matched, up to mirror image, with the census knot it draws: first the census
// knots of its crossing number with its HOMFLY-PT polynomial; where several remain (mutants), the
// code's diagram itself, Reidemeister moves, then covers of the knot group decide, and a code left
// with one unnamed candidate once the others of its class are named takes it. Both tables list
// every prime knot of those crossings once up to mirror image, which is what makes that last step
// sound; the counts printed say whether every census knot was named.
DtNaming name_from_dt_codes(const std::vector<DtCode>& codes, std::vector<KnotTableEntry>& entries,
                            const std::vector<regina::Link>& census_links) {
  DtNaming r;
  std::unordered_map<std::string, std::size_t> by_dt_name;
  std::unordered_multimap<std::uint64_t, std::size_t> free_by_key;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const KnotTableEntry& e = entries[i];
    if (!e.dt_name.empty()) {
      by_dt_name.emplace(e.dt_name, i);
      continue;
    }
    free_by_key.emplace(e.key, i);
    if (e.mirror_key != e.key) free_by_key.emplace(e.mirror_key, i);
  }
  struct Pending {
    std::size_t code;
    regina::Link link;
    std::vector<std::size_t> candidates;
  };
  std::vector<Pending> pending;
  for (std::size_t c = 0; c < codes.size(); ++c) {
    regina::Link link;
    try {
      link = regina::Link::fromDT(codes[c].code);
    } catch (const std::exception& ex) {
      throw std::runtime_error(codes[c].name + ": bad DT code '" + codes[c].code + "' (" + ex.what() + ")");
    }
    const int n = static_cast<int>(link.size());
    const std::uint64_t fp = homfly_fingerprint(homfly_of(link));
    if (const auto named = by_dt_name.find(codes[c].name); named != by_dt_name.end()) {
      const KnotTableEntry& e = entries[named->second];
      if (e.crossings != n || (e.key != fp && e.mirror_key != fp))
        throw std::runtime_error(codes[c].name + ": the DT code does not draw the census knot of that name (" +
                                 e.regina_name + "): the table's numbering differs from the census's");
      ++r.confirmed;
      continue;
    }
    Pending p{c, std::move(link), {}};
    const auto [lo, hi] = free_by_key.equal_range(fp);
    for (auto it = lo; it != hi; ++it)
      if (entries[it->second].crossings == n) p.candidates.push_back(it->second);
    std::sort(p.candidates.begin(), p.candidates.end());
    p.candidates.erase(std::unique(p.candidates.begin(), p.candidates.end()), p.candidates.end());
    pending.push_back(std::move(p));
  }

  // Codes of one HOMFLY-PT class share their candidates: taken together, so that what is worked
  // out for a census knot serves the class and is then dropped.
  std::stable_sort(pending.begin(), pending.end(),
                   [](const Pending& a, const Pending& b) { return a.candidates < b.candidates; });
  std::vector<bool> claimed(entries.size(), false);
  auto name = [&](Pending& p, std::size_t entry, int& how) {
    entries[entry].dt_name = codes[p.code].name;
    claimed[entry] = true;
    p.candidates = {entry};
    ++how;
    ++r.named;
  };
  std::vector<bool> done(pending.size(), false);
  // Codes left with one unclaimed candidate take it; repeated until nothing changes.
  auto propagate = [&](int& how) {
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t k = 0; k < pending.size(); ++k) {
        if (done[k]) continue;
        auto& cand = pending[k].candidates;
        std::erase_if(cand, [&](std::size_t i) { return claimed[i]; });
        if (cand.size() == 1) {
          name(pending[k], cand.front(), how);
          done[k] = changed = true;
        } else if (cand.empty()) {
          done[k] = true;
          ++r.unresolved;
          std::cerr << "build_knot_index: " << codes[pending[k].code].name << " matches no unnamed census knot\n";
        }
      }
    }
  };
  auto left = [&] { return std::count(done.begin(), done.end(), false); };
  auto progress = [&](const char* stage) {
    std::cerr << "build_knot_index: DT codes: after " << stage << ", " << r.named << " named, " << left()
              << " still ambiguous\n";
  };
  propagate(r.by_homfly);
  progress("HOMFLY-PT");
  // A proof for one code of a class, then elimination for the rest of it. `forget` is called
  // between classes (caches of the census side).
  auto decide = [&](const std::function<int(Pending&)>& prove, const std::function<void()>& forget, int& how,
                    const char* stage) {
    const std::vector<std::size_t>* class_of = nullptr;
    std::vector<std::size_t> current;
    int tried = 0;
    for (std::size_t k = 0; k < pending.size(); ++k) {
      if (done[k]) continue;
      Pending& p = pending[k];
      std::erase_if(p.candidates, [&](std::size_t i) { return claimed[i]; });
      if (p.candidates.size() < 2) continue;
      if (!class_of || p.candidates != current) {
        forget();
        current = p.candidates;
        class_of = &current;
      }
      if (++tried % 1000 == 0) std::cerr << "build_knot_index:   " << stage << ": " << tried << " codes tried\n";
      const int i = prove(p);
      if (i < 0) continue;
      name(p, p.candidates[static_cast<std::size_t>(i)], how);
      done[k] = true;
      propagate(r.by_elimination);
    }
    forget();
    progress(stage);
  };
  decide(
      [&](Pending& p) {
        const std::string sig = p.link.knotSig();
        for (std::size_t i = 0; i < p.candidates.size(); ++i)
          if (census_links[p.candidates[i]].knotSig() == sig) return static_cast<int>(i);
        return -1;
      },
      [] {}, r.by_diagram, "equal diagrams");
  std::unordered_map<std::size_t, std::string> census_covers;
  auto by_covers = [&](int max_index) {
    return [&, max_index](Pending& p) {
      const std::string mine = covers_of(p.link, max_index);
      int hit = -1, hits = 0;
      for (std::size_t i = 0; i < p.candidates.size(); ++i) {
        auto it = census_covers.find(p.candidates[i]);
        if (it == census_covers.end())
          it = census_covers.emplace(p.candidates[i], covers_of(census_links[p.candidates[i]], max_index)).first;
        if (it->second == mine) hit = static_cast<int>(i), ++hits;
      }
      return hits == 1 ? hit : -1;
    };
  };
  decide(by_covers(4), [&] { census_covers.clear(); }, r.by_covers, "covers to index 4");
  // Diagrams one Reidemeister move of extra crossing away, from both sides: two minimal diagrams
  // of one knot (flypes apart) often meet there, where a search from one side alone would need
  // twice the height.
  std::unordered_map<std::size_t, std::unordered_set<std::string>> census_near;
  auto near = [](const regina::Link& l) {
    std::unordered_set<std::string> sigs;
    l.rewrite(1, 1, nullptr, [&](const std::string& sig, const regina::Link&) {
      sigs.insert(sig);
      return false;
    });
    return sigs;
  };
  decide(
      [&](Pending& p) {
        const std::unordered_set<std::string> mine = near(p.link);
        int hit = -1, hits = 0;
        for (std::size_t i = 0; i < p.candidates.size(); ++i) {
          auto it = census_near.find(p.candidates[i]);
          if (it == census_near.end()) it = census_near.emplace(p.candidates[i], near(census_links[p.candidates[i]])).first;
          if (std::any_of(it->second.begin(), it->second.end(), [&](const std::string& s) { return mine.count(s); }))
            hit = static_cast<int>(i), ++hits;
        }
        return hits == 1 ? hit : -1;
      },
      [&] { census_near.clear(); }, r.by_rewriting, "Reidemeister moves");
  decide(by_covers(5), [&] { census_covers.clear(); }, r.by_covers, "covers to index 5");
  for (std::size_t k = 0; k < pending.size(); ++k)
    if (!done[k]) {
      ++r.unresolved;
      std::cerr << "build_knot_index: " << codes[pending[k].code].name << " is one of "
                << pending[k].candidates.size() << " census knots:";
      for (std::size_t i : pending[k].candidates) std::cerr << " " << entries[i].regina_name;
      std::cerr << "\n";
    }
  return r;
}

struct Args {
  std::string census, rolfsen, out, dt_names;
  bool check = false;
};

Args parse_args(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(s + " needs a value");
      return argv[++i];
    };
    if (s == "--census") a.census = value();
    else if (s == "--rolfsen") a.rolfsen = value();
    else if (s == "--out") a.out = value();
    else if (s == "--dt-names") a.dt_names = value();
    else if (s == "--check") a.check = true;
    else throw std::runtime_error("unknown argument " + s);
  }
  if (a.census.empty() || a.rolfsen.empty() || a.out.empty())
    throw std::runtime_error(
        "usage: build_knot_index --census FILE --rolfsen FILE --out FILE [--dt-names FILE] [--check]");
  return a;
}

}  // namespace

int main(int argc, char** argv) try {
  const Args args = parse_args(argc, argv);
  const auto t0 = std::chrono::steady_clock::now();

  // [1] The census: one entry per Link packet, in file order (by crossings, then Regina's order).
  const auto root = regina::open(args.census.c_str());
  if (!root) throw std::runtime_error("cannot open the census " + args.census);
  std::vector<KnotTableEntry> entries;
  std::map<std::uint64_t, Laurent2> polys;  // fingerprint -> polynomial, to prove no false collision
  int collisions = 0;
  for (const auto& packet : *root) {
    const auto* held = dynamic_cast<const regina::PacketOf<regina::Link>*>(&packet);
    if (!held) continue;
    const regina::Link& link = *held;
    KnotTableEntry e;
    std::tie(e.regina_name, e.dt_name) = split_label(packet.label());
    // The census pads DT numbers ("12a_0803"); KnotInfo and the Knot Atlas write "12a_803".
    if (!e.dt_name.empty()) e.dt_name = canonical_knot_name(e.dt_name);
    e.crossings = static_cast<int>(link.size());
    const Laurent2 h = homfly_of(link);
    const Laurent2 hm = h.mirror_alpha();
    e.key = homfly_fingerprint(h);
    e.mirror_key = homfly_fingerprint(hm);
    e.homfly_symmetric = h == hm;
    e.alternating = link.isAlternating();
    for (const auto& [k, p] : {std::pair{e.key, h}, std::pair{e.mirror_key, hm}}) {
      const auto [it, fresh] = polys.emplace(k, p);
      if (!fresh && !(it->second == p)) ++collisions;
    }
    entries.push_back(std::move(e));
  }
  if (collisions)
    throw std::runtime_error(std::to_string(collisions) + " fingerprint collisions between different "
                             "polynomials: choose another evaluation point");

  // [2] Rolfsen names: each table braid is matched with the census knots of its crossing number
  // that have the same HOMFLY-PT polynomial up to mirror image.
  std::vector<regina::Link> census_links;  // parallel to entries, for the rare rewriting proofs
  for (const auto& packet : *root)
    if (const auto* held = dynamic_cast<const regina::PacketOf<regina::Link>*>(&packet))
      census_links.push_back(*held);
  const auto table = load_braid_table(args.rolfsen);
  int named = 0, ambiguous = 0;
  for (const auto& b : table) {
    const int n = std::stoi(b.name.substr(0, b.name.find('_')));
    const KnotInvariants inv = compute_invariants(braid_diagram(b.strands, b.word));
    std::vector<KnotTableEntry*> hits;
    for (auto& e : entries)
      if (e.crossings == n && (e.key == inv.fingerprint || e.mirror_key == inv.fingerprint))
        hits.push_back(&e);
    std::vector<KnotTableEntry*> free_hits;
    for (auto* e : hits)
      if (e->rolfsen_name.empty()) free_hits.push_back(e);
    if (free_hits.size() > 1) {
      regina::Link from = to_regina_link(braid_diagram(b.strands, b.word));
      from.intelligentSimplify();
      std::vector<std::string> sigs;
      for (auto* e : free_hits) sigs.push_back(census_links[e - entries.data()].knotSig());
      const int i = find_by_rewriting(from, sigs, 2);
      if (i >= 0) {
        std::cerr << "build_knot_index: " << b.name << " is " << free_hits[i]->regina_name
                  << " (proved by Reidemeister moves)\n";
        free_hits = {free_hits[i]};
      }
    }
    if (free_hits.size() != 1) {
      ++ambiguous;
      std::cerr << "build_knot_index: " << b.name << " matches " << free_hits.size()
                << " unnamed census knots:";
      for (auto* e : free_hits) std::cerr << " " << e->regina_name;
      std::cerr << "\n";
      continue;
    }
    KnotTableEntry& e = *free_hits.front();
    e.rolfsen_name = b.name;
    // Keys are stored as seen in the Rolfsen table's own diagram, so "mirror" means what the
    // Knot Atlas means by it.
    if (e.key != inv.fingerprint) std::swap(e.key, e.mirror_key);
    ++named;
  }

  // [2b] DT names from a table of DT codes, for census knots that have none (13 and 14 crossings);
  // codes of crossing numbers the census already names are checked against those names instead.
  DtNaming dt;
  if (!args.dt_names.empty()) {
    dt = name_from_dt_codes(read_dt_codes(args.dt_names), entries, census_links);
    std::cerr << "build_knot_index: DT codes from " << args.dt_names << ": " << dt.confirmed
              << " census DT names confirmed, " << dt.named << " knots named (" << dt.by_homfly
              << " by HOMFLY-PT alone, " << dt.by_diagram << " by an equal diagram, " << dt.by_rewriting
              << " by Reidemeister moves, " << dt.by_covers << " by covers, " << dt.by_elimination
              << " by elimination), " << dt.unresolved << " unresolved\n";
  }

  // Signatures of each census diagram in the reference chirality (reflected where the Rolfsen
  // table's diagram is the census diagram's mirror image), so the table can draw every knot.
  for (std::size_t i = 0; i < entries.size(); ++i) {
    regina::Link l = census_links[i];
    const std::uint64_t k = homfly_fingerprint(homfly_of(l));
    if (k != entries[i].key) l.reflect();
    entries[i].sig = l.knotSig(false, false);
  }

  // [3] Amphichirality: for HOMFLY-symmetric knots up to kFactorCrossings, look for the mirror
  // diagram among the diagrams reachable by Reidemeister moves (signatures that see reflection).
  int amphichiral = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    KnotTableEntry& e = entries[i];
    if (!e.homfly_symmetric || e.crossings > KnotIndex::kFactorCrossings) continue;
    regina::Link mirror = census_links[i];
    mirror.reflect();
    const std::string target = mirror.knotSig(false, true);
    for (int height = 0; height <= 2 && !e.amphichiral; ++height) {
      if (height == 0) {
        e.amphichiral = census_links[i].knotSig(false, true) == target;
        continue;
      }
      e.amphichiral = census_links[i].rewrite(
          height, 1, nullptr,
          [&](const std::string&, const regina::Link& l) { return l.knotSig(false, true) == target; });
    }
    if (e.amphichiral) ++amphichiral;
    else
      std::cerr << "build_knot_index: " << e.display_name()
                << " has a symmetric HOMFLY-PT polynomial; amphichirality not proven\n";
  }
  std::cerr << "build_knot_index: " << amphichiral << " knots proven amphichiral\n";

  // [4] Mirror keys are only kept where the factor search needs them.
  for (auto& e : entries)
    if (e.crossings > KnotIndex::kFactorCrossings) e.mirror_key = 0;

  std::ostringstream out;
  out << "# shadow4d knot index: prime knots of Regina's knot census (up to 14 crossings; B. A. Burton,\n"
         "# \"The next 350 million knots\", SoCG 2020) with Rolfsen names from "
         "data/knots/rolfsen_braids.txt.\n"
         "# Generated by tools/build_knot_index; do not edit by hand.\n"
         "# key = HOMFLY-PT(alpha, z) at a fixed point mod 2^61-1 (src/knots/polynomial.hpp), hex;\n"
         "# mirror_key likewise for the mirror image (0 above "
      << KnotIndex::kFactorCrossings
      << " crossings); flags: s = HOMFLY-PT symmetric, A = proven amphichiral, a = alternating;\n"
         "# sig = Regina knot signature of a minimal diagram in the chirality of key.\n"
         "# key\tmirror_key\tcrossings\tregina\tdt\trolfsen\tflags\tsig\n";
  for (const auto& e : entries) out << format_index_line(e) << "\n";

  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cerr << "build_knot_index: " << entries.size() << " census knots, " << named << " of "
            << table.size() << " Rolfsen names matched, " << ambiguous << " unresolved, " << secs
            << " s\n";
  if (args.check) {
    std::ifstream in(args.out);
    std::stringstream old;
    old << in.rdbuf();
    if (old.str() != out.str()) {
      std::cerr << "build_knot_index: " << args.out << " is out of date\n";
      return 1;
    }
    std::cerr << "build_knot_index: " << args.out << " is up to date\n";
    return 0;
  }
  std::ofstream f(args.out);
  f << out.str();
  if (!f) throw std::runtime_error("cannot write " + args.out);
  return ambiguous || dt.unresolved ? 1 : 0;
} catch (const std::exception& e) {
  std::cerr << "build_knot_index: " << e.what() << "\n";
  return 1;
}
