// An open, knotted trefoil arc above the plane z = 0: the core of the trefoil ribbon (with long
// tails along ±x, as a knot tied loosely in the middle of a rope) and of the spun trefoil.
#pragma once
#include <vector>

#include "core/vec.hpp"

namespace s4d {

// n points equally spaced in arc length along the arc. The trefoil body is cut open at its
// lowest point and both cut ends are led straight down, away from the body:
//  - tails = false: the arc starts and ends on z = 0, with every other point at z > 0 and the
//    ends meeting z = 0 at right angles (what the Artin spin needs);
//  - tails = true: at z = 0 the ends turn outwards into straight tails lying along ±x.
// Joining the two ends through the half-space z <= 0 closes the arc into a trefoil, so it is
// knotted in any sense that matters here. The body spans about [-1.5, 1.5] in x and y and
// z in [0.75, 1.75]; the tails reach x = ±2.5. Needs n >= 16.
std::vector<Vec3> trefoil_arc(int n, bool tails);

}  // namespace s4d
