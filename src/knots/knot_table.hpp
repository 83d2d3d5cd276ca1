// The knot table a person picks from (the window's Create > Knot from the table, `shadow4d knot
// make`): every knot of the index by its Rolfsen, DT or census name, torus knots T(p,q), a few
// named links, and their mirror images, each drawn as a relaxed 3D curve.
#pragma once
#include <string>
#include <vector>

#include "knots/diagram_embedding.hpp"
#include "knots/knot_diagram.hpp"
#include "knots/knot_index.hpp"
#include "shape/curve.hpp"

namespace s4d {

// One name of the picker's list.
struct TableName {
  std::string name;    // as typed back into make_table_knot: "3_1", "11n_34", "T(2,5)", "Hopf link"
  int crossings = 0;   // crossing number (links: of the table's diagram)
  std::string source;  // "Rolfsen", "DT", "census" (Regina's label only), "torus", "link"
};

// Every name, ordered by crossings and then as the tables order them (fast; the index is loaded
// once). Torus knots are listed as T(p,q) for 2 <= p < q, gcd 1, up to the index's crossings.
std::vector<TableName> knot_table_names(const KnotIndex* index = nullptr);

// The names closest in spelling to `name` (edit distance, same crossing number first), for an
// error message or a picker's suggestions.
std::vector<std::string> close_table_names(const std::string& name, std::size_t count = 5,
                                           const KnotIndex* index = nullptr);

// A name resolved: what it is and a diagram of it (in the table's chirality, or its mirror).
struct TableKnot {
  std::string name;    // canonical spelling, " mirror" appended for a mirror image
  std::string source;  // as in TableName
  bool mirror = false;
  const KnotTableEntry* entry = nullptr;  // prime knots of the index; null for torus links, links
  KnotDiagram diagram;                    // combinatorial diagram (no geometry)
};

// Accepts any spelling the index knows ("12a_803", "K12a803", "13nh_517"), "T(p,q)" (negative q
// is the mirror), "unknot", the named links ("Hopf link", "L2a1", "Whitehead link", "L5a1",
// "Solomon link", "L4a1", "Borromean rings", "L6a4"), and a mirror image as "NAME mirror",
// "mNAME" or "NAME*". Throws Error for an unknown name, listing close matches.
TableKnot table_knot(const std::string& name, const KnotIndex* index = nullptr);

// The 3D curve of a table name, relaxed to a good-looking embedding; identify_knot names it as
// that knot with that chirality. Slow for large knots (relaxation: tens to hundreds of ms): run
// it off the UI thread. Throws Error as table_knot does.
Curve<3> make_table_knot(const std::string& name, const DiagramEmbedding& options = {},
                         const KnotIndex* index = nullptr);

}  // namespace s4d
