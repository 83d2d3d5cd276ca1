// Names one slice of a surface of R^4 (a link of R^3, see shape/level_set.hpp) with the one naming
// decision (name_knot): the name, whether it is proven, the candidates, the components and their
// linking numbers, in the few fields the slice panel, `shadow4d slice` and the tests read.
#pragma once
#include <string>
#include <vector>

#include "knots/knot_naming.hpp"
#include "shape/curve.hpp"

namespace s4d {

struct SliceNaming {
  double level = 0;
  int components = 0;       // closed curves of the slice
  int open_components = 0;  // arcs ending on the surface's boundary (not named)
  std::string name;         // name_knot's name: "3_1 # 3_1 mirror", "unlink of 2 components: ...", "empty"
  std::string label;        // the short form for a picture: "3_1 # 3_1 mirror", "unlink of 2 components"
  bool proven = false;
  std::vector<std::string> candidates;        // every answer still possible
  std::vector<std::vector<int>> linking;      // components × components
  std::vector<std::string> decided_by;        // what decided the name
  std::string error;                          // why the slice could not be named ("" when it was)
  // One line: the label, "[not proven]" when other answers remain, a link's linking numbers
  // ("unlink of 2 components  linking numbers lk(0,1)=0") and the open arcs.
  std::string headline() const;
};

// A name's short form for a picture or a panel's line: a link's well-known name ("unlink of 2
// components"), else the one answer left, else "one of: a, b"; the full name when none applies.
std::string short_knot_name(const KnotIdentification& id, const std::vector<std::string>& candidates);

// Names the closed components of `slice` (shadow coordinates, drawn as the identity view sees
// them); open arcs are counted, not named. Never throws for a slice the naming refuses (a curve
// too small or too tangled for a diagram): `error` says why and `name` is "not named".
SliceNaming name_slice(const Curve<3>& slice, double level, const NamingOptions& options = {});

}  // namespace s4d
