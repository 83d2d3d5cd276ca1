// Which objects are classical knots: the curve of R^3 that the knot engine works on, taken from a
// scene object's shape.
#pragma once
#include <string>

#include "shape/shape.hpp"

namespace s4d {

// A curve of R^3 as it is; a curve of R^4 only when it lies in w = 0, since a curve in R^4 off
// that space is not a classical knot (any knot comes undone in R^4). Throws Error naming `where`
// for a surface or such a curve.
Curve<3> knot_curve_of(const Shape& shape, const std::string& where);

}  // namespace s4d
