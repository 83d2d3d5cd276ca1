// The knot table a person picks from (the window's Create > Knot from the table, `shadow4d knot
// make`): every knot of the index by its Rolfsen, DT or census name, torus knots T(p,q), the links
// of Thistlethwaite's table (L2a1 ... L11n459), and their mirror images, each drawn as a relaxed
// 3D curve.
#pragma once
#include <string>
#include <vector>

#include "knots/diagram_embedding.hpp"
#include "knots/knot_diagram.hpp"
#include "knots/knot_index.hpp"
#include "knots/link_table.hpp"
#include "shape/curve.hpp"

namespace s4d {

// One name of the picker's list.
struct TableName {
  std::string name;    // as typed back into make_table_knot: "3_1", "11n_34", "T(2,5)", "L6a4"
  int crossings = 0;   // crossing number
  std::string source;  // "Rolfsen", "DT", "census" (Regina's label only), "torus", "link"
  std::string alias;   // links: a common name ("Borromean rings"), also accepted; else ""
};

// Every name, ordered by crossings and then as the tables order them (fast; the index is loaded
// once). Torus knots are listed as T(p,q) for 2 <= p < q, gcd 1, up to the index's crossings;
// then the links of the link table in its order (L2a1, L4a1, ..., L11n459).
std::vector<TableName> knot_table_names(const KnotIndex* index = nullptr, const LinkTable* links = nullptr);

// The names closest in spelling to `name` (edit distance, same crossing number first), for an
// error message or a picker's suggestions.
std::vector<std::string> close_table_names(const std::string& name, std::size_t count = 5,
                                           const KnotIndex* index = nullptr, const LinkTable* links = nullptr);

// A name resolved: what it is and a diagram of it (in the table's chirality, or its mirror).
struct TableKnot {
  std::string name;    // canonical spelling, " mirror" appended for a mirror image
  std::string source;  // as in TableName
  bool mirror = false;
  const KnotTableEntry* entry = nullptr;  // prime knots of the index; null for torus links, links
  const LinkTableEntry* link = nullptr;   // links of the link table
  KnotDiagram diagram;                    // combinatorial diagram (no geometry)
};

// The table's own diagram of a link (its PD code). Throws s4d::Error when the code is unreadable.
KnotDiagram link_diagram(const LinkTableEntry& entry);

// Accepts any spelling the index knows ("12a_803", "K12a803", "13nh_517"), "T(p,q)" (negative q
// is the mirror), "unknot", the table's links by Thistlethwaite's name in KnotInfo's spellings
// ("L6a4", "l6a4", "L6a_4", orientation suffixes "L6a4{1,0}" dropped) or a common name ("Hopf
// link", "Solomon link", "Whitehead link", "Borromean rings"), and a mirror image as "NAME mirror",
// "mNAME" or "NAME*". Throws Error for an unknown name, listing close matches.
TableKnot table_knot(const std::string& name, const KnotIndex* index = nullptr, const LinkTable* links = nullptr);

// The 3D curve of a table name, relaxed to a good-looking embedding; identify_knot names it as
// that knot with that chirality. Slow for large knots (relaxation: tens to hundreds of ms): run
// it off the UI thread. Throws Error as table_knot does.
Curve<3> make_table_knot(const std::string& name, const DiagramEmbedding& options = {},
                         const KnotIndex* index = nullptr, const LinkTable* links = nullptr);

}  // namespace s4d
