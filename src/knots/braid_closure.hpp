// The closure of a braid as a 3D curve: how knot-table entries (given as braid words) and torus
// knots become curves whose shadows are exactly their braid diagrams.
#pragma once
#include <vector>

#include <string>

#include "knots/knot_diagram.hpp"
#include "shape/curve.hpp"

namespace s4d {

// The closed braid on `strands` strands for `word` (entry +i is the generator sigma_i, a positive
// crossing of the strands at positions i and i+1, -i its inverse; 1 <= i < strands), drawn around
// the z axis: seen from +z (the identity Frame<3>) its shadow has exactly one crossing per letter,
// with the letter's sign. `samples` points per strand per letter (odd, >= 3). Components are
// returned in the order of the strand positions they start from. Throws Error on a bad word.
Curve<3> braid_closure(int strands, const std::vector<int>& word, int samples = 7);

// The diagram of the same closed braid built combinatorially (no geometry): crossing k is letter
// k, components and passages in the same order as braid_closure's curve gives them.
KnotDiagram braid_diagram(int strands, const std::vector<int>& word);

// A knot table line "name strands word..." (data/knots/rolfsen_braids.txt).
struct BraidWord {
  std::string name;
  int strands = 0;
  std::vector<int> word;
};
// Reads such a file ('#' comments); throws ParseError with file and line.
std::vector<BraidWord> load_braid_table(const std::string& path);

// The torus knot or link T(p, q) as the closure of (sigma_1 ... sigma_{p-1})^q on p strands;
// negative q gives the mirror image. |p| >= 2 and q != 0.
Curve<3> torus_braid_closure(int p, int q, int samples = 7);

}  // namespace s4d
