// Builds data/knots/link_table.tsv: Thistlethwaite's prime links of 2 to 11 crossings with a PD
// code each, the HOMFLY-PT fingerprints of all their orientations and mirror images, their
// components' knot types and linking numbers, and the common names (Hopf link, ...).
//   build_link_table --knotpy links_11.csv --out link_table.tsv   (convert knotpy's table once;
//       the CSV is `zcat knotpy/tables/data/links_11.csv.gz`, see data/knots/README.md)
//   build_link_table --out link_table.tsv            (recompute every column from the PD codes)
//   build_link_table --out link_table.tsv --check    (exit 1 if the file is not up to date)
// Sections: [SECTION] knotpy's native notation, [SECTION] invariants
#include <link/link.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "knots/braid_closure.hpp"
#include "knots/knot_identify.hpp"
#include "knots/knot_invariants.hpp"
#include "knots/link_table.hpp"
#include "knots/regina_link.hpp"

using namespace s4d;

namespace {

struct Args {
  std::string knotpy, out;
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
    if (s == "--knotpy") a.knotpy = value();
    else if (s == "--out") a.out = value();
    else if (s == "--check") a.check = true;
    else throw std::runtime_error("unknown argument " + s);
  }
  if (a.out.empty()) throw std::runtime_error("usage: build_link_table [--knotpy links.csv] --out FILE [--check]");
  return a;
}

// [SECTION] knotpy's native notation

// "a=X(b3o b2i b1i b0o) b=X(a3i a2o a1o a0i) ['name'=...]": crossing a's endpoints in
// counter-clockwise order, positions 0 and 2 the under strand, 1 and 3 the over strand (as in a
// PD code's X[i,j,k,l]); each names the endpoint (node, position) at the other end of its edge
// and whether the strand leaves that node there (o) or enters it (i).
struct NativeEnd {
  int node = 0, pos = 0;
  bool twin_outgoing = false;
};

std::vector<std::array<NativeEnd, 4>> parse_native(const std::string& text) {
  std::map<std::string, int> node_of;
  std::vector<std::pair<std::string, std::string>> raw;  // node name, its endpoint list
  std::size_t at = 0;
  for (;;) {
    const auto eq = text.find("=X(", at);
    if (eq == std::string::npos) break;
    std::size_t start = eq;
    while (start > at && std::isalpha(static_cast<unsigned char>(text[start - 1]))) --start;
    const std::string node = text.substr(start, eq - start);
    if (node.empty()) throw std::runtime_error("a crossing without a name in " + text);
    const auto close = text.find(')', eq);
    if (close == std::string::npos) throw std::runtime_error("unclosed X( in " + text);
    node_of.emplace(node, static_cast<int>(raw.size()));
    raw.emplace_back(node, text.substr(eq + 3, close - eq - 3));
    at = close + 1;
  }
  std::vector<std::array<NativeEnd, 4>> out(raw.size());
  for (std::size_t n = 0; n < raw.size(); ++n) {
    std::istringstream in(raw[n].second);
    std::string tok;
    int p = 0;
    while (in >> tok) {
      if (p >= 4 || tok.size() < 3) throw std::runtime_error("bad crossing " + raw[n].first + " in " + text);
      std::size_t d = 0;
      while (d < tok.size() && std::isalpha(static_cast<unsigned char>(tok[d]))) ++d;
      const auto it = node_of.find(tok.substr(0, d));
      if (it == node_of.end() || d + 2 != tok.size() || (tok.back() != 'i' && tok.back() != 'o'))
        throw std::runtime_error("bad endpoint " + tok + " in " + text);
      out[n][p++] = {it->second, tok[d] - '0', tok.back() == 'o'};
    }
    if (p != 4) throw std::runtime_error("crossing " + raw[n].first + " has not 4 endpoints in " + text);
  }
  return out;
}

// PD code with edges numbered 1, 2, ... along each component in its orientation (so Regina's
// fromPD reads the orientation back unambiguously), X[i,j,k,l] from the incoming under end.
std::string pd_from_native(const std::vector<std::array<NativeEnd, 4>>& x) {
  const int n = static_cast<int>(x.size());
  auto outgoing = [&](int node, int pos) { return !x[node][pos].twin_outgoing; };  // the twin enters
  for (int c = 0; c < n; ++c)
    for (int p = 0; p < 4; ++p) {
      const NativeEnd& e = x[c][p];
      if (x[e.node][e.pos].node != c || x[e.node][e.pos].pos != p)
        throw std::runtime_error("edge ends do not pair up");
      if (outgoing(c, p) == outgoing(e.node, e.pos)) throw std::runtime_error("an edge with two heads");
      if (outgoing(c, p) == outgoing(c, (p + 2) % 4)) throw std::runtime_error("a strand that does not pass");
    }
  std::vector<std::array<int, 4>> label(n, {0, 0, 0, 0});
  int next = 0;
  for (int c = 0; c < n; ++c)
    for (int p = 0; p < 4; ++p) {
      if (!outgoing(c, p) || label[c][p]) continue;
      // A new component: follow it from this outgoing end until it closes.
      int node = c, pos = p;
      while (!label[node][pos]) {
        const NativeEnd e = x[node][pos];
        label[node][pos] = label[e.node][e.pos] = ++next;
        node = e.node;
        pos = (e.pos + 2) % 4;
      }
    }
  std::string s = "[";
  for (int c = 0; c < n; ++c) {
    const int in = outgoing(c, 0) ? 2 : 0;  // the under strand's incoming end
    s += c ? ",[" : "[";
    for (int k = 0; k < 4; ++k) s += (k ? "," : "") + std::to_string(label[c][(in + k) % 4]);
    s += "]";
  }
  return s + "]";
}

// The all-"+" orientation of each link of knotpy's CSV ("L6a_4+++,a=X(...) ..."), in file order.
std::vector<LinkTableEntry> read_knotpy(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<LinkTableEntry> out;
  std::set<std::string> seen;
  std::string line;
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    if (comma == std::string::npos || line.rfind("name,", 0) == 0) continue;
    const std::string oriented = line.substr(0, comma);
    const auto sign = oriented.find_first_of("+-");
    if (sign == std::string::npos) throw std::runtime_error("no orientation in " + oriented);
    if (oriented.find('-', sign) != std::string::npos) continue;
    LinkTableEntry e;
    e.name = canonical_link_name(oriented);
    if (e.name.empty() || !seen.insert(e.name).second) throw std::runtime_error("bad or repeated " + oriented);
    e.components = static_cast<int>(oriented.size() - sign);
    e.pd = pd_from_native(parse_native(line.substr(comma + 1)));
    out.push_back(std::move(e));
  }
  // Table order: crossings, alternating before non-alternating, then the number.
  auto order = [](const std::string& n) {
    const auto k = n.find_first_of("an");
    return std::tuple(std::stoi(n.substr(1, k - 1)), n[k], std::stoi(n.substr(k + 1)));
  };
  std::sort(out.begin(), out.end(), [&](const auto& a, const auto& b) { return order(a.name) < order(b.name); });
  return out;
}

// [SECTION] invariants

std::map<std::uint64_t, Laurent2> g_polys;  // fingerprint -> polynomial, to prove no collision
int g_collisions = 0;

std::uint64_t key_of(const Laurent2& h) {
  const std::uint64_t k = homfly_fingerprint(h);
  const auto [it, fresh] = g_polys.emplace(k, h);
  if (!fresh && !(it->second == h)) ++g_collisions;
  return k;
}

void fill_invariants(LinkTableEntry& e) {
  const regina::Link link = regina::Link::fromPD(e.pd);
  const KnotDiagram d = diagram_from_regina(link);
  if (d.component_count() != e.components && e.components != 0)
    throw std::runtime_error(e.name + ": " + std::to_string(d.component_count()) + " components, not " +
                             std::to_string(e.components));
  e.components = d.component_count();
  e.crossings = d.crossing_count();
  const int expected = std::stoi(e.name.substr(1));
  if (e.crossings != expected) throw std::runtime_error(e.name + ": the PD code has " + std::to_string(e.crossings) + " crossings");
  std::set<std::uint64_t> keys, mirror_keys;
  for (unsigned mask = 0; mask < (1u << (e.components - 1)); ++mask) {
    KnotDiagram v = d;
    for (int c = 1; c < e.components; ++c)
      if (mask & (1u << (c - 1))) v = v.with_component_reversed(c);
    const KnotInvariants inv = compute_invariants(v);
    if (inv.simplified_crossings != e.crossings)
      std::cerr << "build_link_table: note: " << e.name << " simplifies to " << inv.simplified_crossings
                << " crossings\n";
    keys.insert(key_of(inv.homfly));
    mirror_keys.insert(key_of(inv.homfly.mirror_alpha()));
  }
  e.keys.assign(keys.begin(), keys.end());
  e.mirror_keys.assign(mirror_keys.begin(), mirror_keys.end());
  e.component_knots.clear();
  for (int c = 0; c < e.components; ++c)
    e.component_knots.push_back(knot_type_up_to_mirror(identify_diagram(component_diagram(d, c))));
  std::sort(e.component_knots.begin(), e.component_knots.end());
  e.abs_linking.clear();
  const auto lk = d.linking_numbers();
  for (int i = 0; i < e.components; ++i)
    for (int j = i + 1; j < e.components; ++j) e.abs_linking.push_back(std::abs(lk[i][j]));
  std::sort(e.abs_linking.begin(), e.abs_linking.end());
}

// The common names, found in the table by their braid words' HOMFLY-PT (up to orientation and
// mirror image): one table link each, or the tool stops.
void name_common_links(std::vector<LinkTableEntry>& table) {
  struct Common {
    const char* name;
    int strands;
    std::vector<int> word;
  };
  const std::vector<Common> common = {
      {"Hopf link", 2, {1, 1}},
      {"Solomon link", 2, {1, 1, 1, 1}},
      {"Whitehead link", 3, {1, 1, -2, 1, -2}},
      {"Borromean rings", 3, {1, -2, 1, -2, 1, -2}},
      {"T(2,6) torus link", 2, {1, 1, 1, 1, 1, 1}},
      {"T(2,8) torus link", 2, {1, 1, 1, 1, 1, 1, 1, 1}},
      {"T(2,10) torus link", 2, {1, 1, 1, 1, 1, 1, 1, 1, 1, 1}},
      {"T(3,3) torus link", 3, {1, 2, 1, 2, 1, 2}},
  };
  for (auto& e : table) e.alias.clear();
  for (const auto& c : common) {
    const std::uint64_t k = compute_invariants(braid_diagram(c.strands, c.word)).fingerprint;
    std::vector<LinkTableEntry*> hits;
    for (auto& e : table)
      if (std::count(e.keys.begin(), e.keys.end(), k) || std::count(e.mirror_keys.begin(), e.mirror_keys.end(), k))
        hits.push_back(&e);
    if (hits.size() != 1)
      throw std::runtime_error(std::string(c.name) + " matches " + std::to_string(hits.size()) + " table links");
    hits[0]->alias = c.name;
    std::cerr << "build_link_table: " << c.name << " is " << hits[0]->name << "\n";
  }
}

std::vector<LinkTableEntry> read_shipped(const std::string& path) {
  return LinkTable::load(path).entries();
}

}  // namespace

int main(int argc, char** argv) try {
  const Args args = parse_args(argc, argv);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<LinkTableEntry> table = args.knotpy.empty() ? read_shipped(args.out) : read_knotpy(args.knotpy);
  std::map<int, int> per_crossings, per_components;
  for (auto& e : table) {
    fill_invariants(e);
    ++per_crossings[e.crossings];
    ++per_components[e.components];
  }
  if (g_collisions) throw std::runtime_error(std::to_string(g_collisions) + " fingerprint collisions");
  name_common_links(table);

  std::ostringstream text;
  text << "# Thistlethwaite's link table, 2 to 11 crossings (KnotInfo/LinkInfo, C. Livingston and A. H. Moore,\n"
          "# as carried by knotpy; see README.md). Made by tools/build_link_table. Columns:\n"
          "# name  crossings  components  alias  keys  mirror_keys  component_knots  abs_linking  pd\n";
  for (const auto& e : table) text << format_link_line(e) << "\n";
  std::cerr << "build_link_table: " << table.size() << " links;";
  for (auto [n, k] : per_crossings) std::cerr << " " << n << ":" << k;
  std::cerr << "; by components:";
  for (auto [n, k] : per_components) std::cerr << " " << n << ":" << k;
  std::cerr << "; " << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";

  if (args.check) {
    std::ifstream in(args.out, std::ios::binary);
    std::ostringstream old;
    old << in.rdbuf();
    if (old.str() != text.str()) {
      std::cerr << "build_link_table: " << args.out << " is out of date\n";
      return 1;
    }
    std::cerr << "build_link_table: " << args.out << " is up to date\n";
    return 0;
  }
  std::ofstream out(args.out, std::ios::binary);
  out << text.str();
  if (!out) throw std::runtime_error("cannot write " + args.out);
  return 0;
} catch (const std::exception& e) {
  std::cerr << "build_link_table: " << e.what() << "\n";
  return 2;
}
