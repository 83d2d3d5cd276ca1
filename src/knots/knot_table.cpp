// Resolving table names to diagrams and curves: Rolfsen knots from their braid words, the other
// census knots from the minimal diagram whose signature the index keeps, torus knots on a torus,
// links from the link table's PD codes.
// Sections: [SECTION] names, [SECTION] resolving
#include "knots/knot_table.hpp"

#include <algorithm>
#include <cctype>
#include <numbers>
#include <numeric>

#include "core/data_paths.hpp"
#include "core/error.hpp"
#include "knots/braid_closure.hpp"
#include "knots/diagram_codes.hpp"
#include "knots/own_codes.hpp"
#include "knots/relax.hpp"
#include "knots/resample.hpp"
#include "shape/knot_curves.hpp"

namespace s4d {

namespace {

const std::vector<BraidWord>& rolfsen_braids() {
  static const std::vector<BraidWord> table =
      load_braid_table((data_dirs().knots / "rolfsen_braids.txt").string());
  return table;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// "T(2,5)", "T(3, -4)", "t(2,5)" -> (p, q); false if not of that form.
bool parse_torus(const std::string& s, int& p, int& q) {
  std::string t;
  for (char c : s)
    if (c != ' ') t += c;
  if (t.size() < 6 || (t[0] != 'T' && t[0] != 't') || t[1] != '(' || t.back() != ')') return false;
  const auto comma = t.find(',');
  if (comma == std::string::npos) return false;
  try {
    std::size_t u1 = 0, u2 = 0;
    const std::string a = t.substr(2, comma - 2), b = t.substr(comma + 1, t.size() - comma - 2);
    p = std::stoi(a, &u1);
    q = std::stoi(b, &u2);
    return u1 == a.size() && u2 == b.size();
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<int> torus_word(int p, int q) {
  std::vector<int> w;
  for (int k = 0; k < std::abs(q); ++k)
    for (int i = 1; i < p; ++i) w.push_back(q > 0 ? i : -i);
  return w;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

// The crossing number a name starts with: "8_2" -> 8, "L6a4" -> 6; -1 if none.
int leading_number(const std::string& s) {
  int n = 0;
  std::size_t i = s.size() > 1 && (s[0] == 'L' || s[0] == 'l') ? 1 : 0;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) n = 10 * n + (s[i++] - '0');
  return i > 0 && std::isdigit(static_cast<unsigned char>(s[i - 1])) ? n : -1;
}


}  // namespace

KnotDiagram link_diagram(const LinkTableEntry& e) {
  try {
    return diagram_from_pd(e.pd);
  } catch (const Error& ex) {
    throw Error("the link table's PD code of " + e.name + " is unreadable: " + ex.what());
  }
}

// [SECTION] names

std::vector<TableName> knot_table_names(const KnotIndex* index_in, const LinkTable* links_in) {
  const KnotIndex& index = index_in ? *index_in : KnotIndex::shipped();
  const LinkTable& links = links_in ? *links_in : LinkTable::shipped();
  std::vector<TableName> out{{"unknot", 0, "unknot", ""}};
  for (const auto& e : index.entries()) {
    const char* source = !e.rolfsen_name.empty() ? "Rolfsen" : !e.dt_name.empty() ? "DT" : "census";
    out.push_back({e.display_name(), e.crossings, source, ""});
  }
  for (int p = 2; p <= index.max_crossings(); ++p)
    for (int q = p + 1; q * (p - 1) <= index.max_crossings(); ++q)
      if (std::gcd(p, q) == 1)
        out.push_back({"T(" + std::to_string(p) + "," + std::to_string(q) + ")", q * (p - 1), "torus", ""});
  for (const auto& l : links.entries()) out.push_back({l.name, l.crossings, "link", l.alias});
  // Rolfsen and DT names sort by crossings, then by their number ("8_2" before "8_10").
  auto number = [](const std::string& s) {
    const auto u = s.rfind('_');
    return u == std::string::npos ? 0 : std::atoi(s.c_str() + u + 1);
  };
  std::stable_sort(out.begin(), out.end(), [&](const TableName& a, const TableName& b) {
    auto rank = [](const TableName& t) {
      return t.source == "unknot" ? 0 : t.source == "torus" ? 2 : t.source == "link" ? 3 : 1;
    };
    if (rank(a) != rank(b)) return rank(a) < rank(b);
    if (a.crossings != b.crossings) return a.crossings < b.crossings;
    if (rank(a) != 1) return false;  // torus knots and links keep their order
    const std::string ka = a.name.substr(0, a.name.rfind('_')), kb = b.name.substr(0, b.name.rfind('_'));
    if (ka != kb) return ka < kb;  // "11a" before "11n"
    return number(a.name) < number(b.name);
  });
  return out;
}

std::vector<std::string> close_table_names(const std::string& name, std::size_t count,
                                           const KnotIndex* index, const LinkTable* links) {
  const std::string as_link = canonical_link_name(name);
  const std::string want = lower(as_link.empty() ? canonical_knot_name(name) : as_link);
  const int n = leading_number(want);
  const bool link = !as_link.empty() || want.find("link") != std::string::npos;
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const auto& t : knot_table_names(index, links)) {
    std::size_t d = edit_distance(want, lower(t.name));
    if (!t.alias.empty()) d = std::min(d, edit_distance(want, lower(t.alias)));
    if (n >= 0 && t.crossings != n) d += 2;  // same crossing number first
    if (link != (t.source == "link")) d += 1;  // then links for a link's name, knots for a knot's
    scored.emplace_back(d, t.name);
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (std::size_t i = 0; i < scored.size() && out.size() < count; ++i) out.push_back(scored[i].second);
  return out;
}

// [SECTION] resolving

TableKnot table_knot(const std::string& name_in, const KnotIndex* index_in, const LinkTable* links_in) {
  const KnotIndex& index = index_in ? *index_in : KnotIndex::shipped();
  const LinkTable& links = links_in ? *links_in : LinkTable::shipped();
  std::string name = trim(name_in);
  if (name.empty()) throw Error("no knot name given (try 3_1, 11n_34, T(2,5), L6a4 or Hopf link)");
  bool mirror = false;
  for (const std::string suffix : {" mirror", "*"})
    if (name.size() > suffix.size() && lower(name).ends_with(suffix)) {
      mirror = true;
      name = trim(name.substr(0, name.size() - suffix.size()));
      break;
    }
  TableKnot t;
  auto finish = [&](TableKnot k, bool mirrored) {
    k.mirror = mirrored;
    if (mirrored) {
      k.diagram = k.diagram.mirrored();
      k.name += " mirror";
    }
    return k;
  };
  int p = 0, q = 0;
  if (parse_torus(name, p, q)) {
    if (p < 2 || q == 0 || std::abs(q) < 2)
      throw Error("T(" + std::to_string(p) + "," + std::to_string(q) +
                  ") is not a torus knot or link (it needs p >= 2 and |q| >= 2)");
    if (q < 0) mirror = !mirror;
    t.name = "T(" + std::to_string(p) + "," + std::to_string(std::abs(q)) + ")";
    t.source = "torus";
    t.diagram = braid_diagram(p, torus_word(p, std::abs(q)));
    return finish(std::move(t), mirror);
  }
  if (lower(name) == "unknot" || name == "0_1") {
    t.name = "unknot";
    t.source = "unknot";
    t.diagram.components.resize(1);
    return t;
  }
  const LinkTableEntry* l = links.find_name(name);
  if (!l && !mirror && name.size() > 2 && name[0] == 'm' && (name[1] == 'L' || name[1] == 'l')) {
    l = links.find_name(name.substr(1));
    mirror = l != nullptr;
  }
  if (l) {
    t.name = l->name;
    t.source = "link";
    t.link = l;
    t.diagram = link_diagram(*l);
    return finish(std::move(t), mirror);
  }
  const KnotTableEntry* e = index.find_name(name);
  if (!e && !mirror && name.size() > 1 && name[0] == 'm' &&
      std::isdigit(static_cast<unsigned char>(name[1]))) {
    e = index.find_name(name.substr(1));
    mirror = e != nullptr;
  }
  if (!e) {
    std::string msg = "no knot or link called '" + trim(name_in) + "' in the table; close matches:";
    const auto close = close_table_names(name, 5, &index, &links);
    for (std::size_t i = 0; i < close.size(); ++i) msg += (i ? ", " : " ") + close[i];
    throw Error(msg);
  }
  t.entry = e;
  t.name = e->display_name();
  t.source = !e->rolfsen_name.empty() ? "Rolfsen" : !e->dt_name.empty() ? "DT" : "census";
  if (!e->rolfsen_name.empty()) {
    const auto& table = rolfsen_braids();
    const auto it = std::find_if(table.begin(), table.end(),
                                 [&](const BraidWord& b) { return b.name == e->rolfsen_name; });
    if (it == table.end()) throw Error("the braid table has no word for " + e->rolfsen_name);
    t.diagram = braid_diagram(it->strands, it->word);
  } else {
    if (e->sig.empty())
      throw Error("the knot index has no diagram for " + t.name + " (an old index file: rebuild it)");
    try {
      t.diagram = diagram_from_knot_sig(e->sig);
    } catch (const Error& ex) {
      throw Error("the knot index's diagram of " + t.name + " is unreadable: " + ex.what());
    }
  }
  return finish(std::move(t), mirror);
}

Curve<3> make_table_knot(const std::string& name, const DiagramEmbedding& options, const KnotIndex* index,
                         const LinkTable* links) {
  const TableKnot t = table_knot(name, index, links);
  Curve<3> curve;
  const int crossings = t.diagram.crossing_count();
  const int points = std::max(60, options.points_per_crossing * crossings);
  int p = 0, q = 0;
  if (t.source == "unknot") {
    return curve_from_diagram(t.diagram, options);
  } else if (t.source == "torus" && parse_torus(t.name.substr(0, t.name.find(' ')), p, q)) {
    // The standard picture on a torus is already a good embedding; the mirror flips depth below.
    // shape/torus_knot(p, q) winds the other way round from the positive braid (sigma_1 ...
    // sigma_{p-1})^q that T(p,q) means here (and in KnotInfo): positive crossings.
    curve = torus_knot(p, -q, std::max(points / std::gcd(p, q), 24));
  } else if (t.source == "Rolfsen") {
    // Braid closures are clean pictures of their braid words; relaxation rounds them.
    int strands = 0;
    std::vector<int> word;
    for (const auto& b : rolfsen_braids())
      if (b.name == t.entry->rolfsen_name) strands = b.strands, word = b.word;
    curve = resample_curve_to_count(braid_closure(strands, word, 9), points);
    if (options.relax_iterations > 0) curve = relax(curve, options.relax_iterations);
  } else {
    // Draw the table's own diagram (census knots, links); a mirror image is mirrored below.
    curve = curve_from_diagram(t.mirror ? t.diagram.mirrored() : t.diagram, options);
  }
  if (t.mirror)
    for (auto& pl : curve.components)
      for (auto& pt : pl.points) pt.z() = -pt.z();
  return curve;
}

}  // namespace s4d
