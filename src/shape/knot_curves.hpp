// Closed knots in R^3 as polylines: torus knots and links T(p, q), and the figure-eight knot.
#pragma once
#include "shape/curve.hpp"

namespace s4d {

// T(p, q) on the torus of radii R > r > 0 around the z axis: p turns around the axis, q turns
// around the tube (q < 0 gives the mirror image). With g = gcd(p, |q|) > 1 the result is the
// torus link with g components, each a T(p/g, q/g) shifted around the tube. Every component has
// n points and lies on the torus. Needs p >= 1, n >= 3 and r < R; throws s4d::Error otherwise.
Curve<3> torus_knot(int p, int q, int n, double R = 2.0, double r = 1.0);

// The figure-eight knot (4_1) in the Lissajous-like form
// ((2 + cos 2t) cos 3t, (2 + cos 2t) sin 3t, sin 4t), with n points (n >= 8).
Curve<3> figure_eight_knot(int n);

// The trefoil (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t) and its derivative; the knotted arc
// of the ribbons and of the spun trefoil is cut from it.
Vec3 trefoil_point(double t);
Vec3 trefoil_derivative(double t);

}  // namespace s4d
