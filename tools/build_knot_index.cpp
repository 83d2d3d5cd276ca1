// Builds data/knots/knot_index.tsv: every prime knot of Regina's census (up to 14 crossings) with
// the fingerprint of its HOMFLY-PT polynomial, a signature of its minimal diagram, Rolfsen names
// (up to 10 crossings) matched from the braid table data/knots/rolfsen_braids.txt, and, when a
// table of DT codes is given, Dowker-Thistlethwaite names for the knots the census leaves unnamed
// (13 and 14 crossings).
//   build_knot_index --census knot-census.rga --rolfsen rolfsen_braids.txt --out knot_index.tsv
//   build_knot_index ... --dt-names FILE   (lines "13n_5018  <numerical DT code>"; '#' comments)
//   build_knot_index ... --check   (exit 1 if the existing --out file differs)
#include <link/link.h>
#include <packet/packet.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "knots/braid_closure.hpp"
#include "knots/knot_index.hpp"
#include "knots/knot_invariants.hpp"
#include "knots/polynomial.hpp"
#include "knots/regina_link.hpp"

using namespace s4d;

namespace {

// Regina's Laurent2 hides its terms; the exponents of an n-crossing knot's HOMFLY-PT polynomial
// lie in [-(n + 2), n + 2].
Laurent2 homfly_of(const regina::Link& link) {
  const auto& p = link.homflyAZ();
  const long bound = static_cast<long>(link.size()) + 2;
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

  // [2b] DT names from a table of DT codes, for census knots that have none (13 and 14 crossings):
  // the same HOMFLY-PT matching as for Rolfsen names, Reidemeister rewriting to break ties.
  int dt_named = 0, dt_unresolved = 0;
  if (!args.dt_names.empty()) {
    std::ifstream in(args.dt_names);
    if (!in) throw std::runtime_error("cannot read " + args.dt_names);
    std::string line;
    int line_no = 0;
    while (std::getline(in, line)) {
      ++line_no;
      if (line.empty() || line[0] == '#') continue;
      for (char& ch : line)
        if (ch == ',' || ch == '[' || ch == ']' || ch == '(' || ch == ')') ch = ' ';
      std::istringstream fields(line);
      std::string name, code, v;
      fields >> name;
      while (fields >> v) code += (code.empty() ? "" : " ") + v;
      name = canonical_knot_name(name);
      regina::Link link;
      try {
        link = regina::Link::fromDT(code);
      } catch (const std::exception& ex) {
        throw std::runtime_error(args.dt_names + ":" + std::to_string(line_no) + ": bad DT code (" +
                                 ex.what() + ")");
      }
      const int n = static_cast<int>(link.size());
      const std::uint64_t fp = homfly_fingerprint(homfly_of(link));
      std::vector<KnotTableEntry*> free_hits;
      for (auto& e : entries)
        if (e.crossings == n && e.dt_name.empty() && (e.key == fp || e.mirror_key == fp))
          free_hits.push_back(&e);
      if (free_hits.size() > 1) {
        std::vector<std::string> sigs;
        for (auto* e : free_hits) sigs.push_back(census_links[e - entries.data()].knotSig());
        const int i = find_by_rewriting(link, sigs, 2);
        if (i >= 0) free_hits = {free_hits[i]};
      }
      if (free_hits.size() != 1) {
        ++dt_unresolved;
        std::cerr << "build_knot_index: " << name << " matches " << free_hits.size()
                  << " unnamed census knots\n";
        continue;
      }
      free_hits.front()->dt_name = name;
      ++dt_named;
    }
    std::cerr << "build_knot_index: " << dt_named << " DT names from " << args.dt_names << ", "
              << dt_unresolved << " unresolved\n";
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
  return ambiguous ? 1 : 0;
} catch (const std::exception& e) {
  std::cerr << "build_knot_index: " << e.what() << "\n";
  return 1;
}
