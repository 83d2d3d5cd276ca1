// PD and DT codes as papers, KnotInfo, KnotTheory` and SnapPy write them, read into a diagram and
// written back: what a user types into `knot make --pd|--dt` and gets from `knot code --pd|--dt`.
#pragma once
#include <string>

#include "knots/knot_diagram.hpp"

namespace s4d {

// A planar diagram code of a knot or link: X[i,j,k,l] per crossing, i the incoming under edge,
// then counter-clockwise (KnotTheory`, KnotInfo); written "[[1,5,2,4],[3,1,4,6],[5,3,6,2]]",
// "PD[X[1,5,2,4], ...]" or SnapPy's "[(1,5,2,4), ...]". Components take the direction of their
// edge numbers. Throws s4d::Error saying what is wrong (Regina reads it; planarity is checked when
// the diagram is drawn).
KnotDiagram diagram_from_pd(const std::string& code);

// A Dowker-Thistlethwaite code of a knot: numerical ("4 6 2", "[4, 6, -2]", "DT[4, 6, 2]") or
// alphabetical ("bca"). A DT code does not say which of a knot and its mirror image it is (nor,
// for composite knots, always which knot): Regina's reading (as SnapPea's) picks one. Throws
// s4d::Error.
KnotDiagram diagram_from_dt(const std::string& code);

// The codes out, in the forms the readers above take: "[[1,5,2,4],[3,1,4,6],[5,3,6,2]]" (edges
// numbered along the components in order), and the numerical DT code "4 6 2" (knots only; throws
// s4d::Error for a link).
std::string pd_list(const KnotDiagram& diagram);
std::string dt_code(const KnotDiagram& diagram);

}  // namespace s4d
