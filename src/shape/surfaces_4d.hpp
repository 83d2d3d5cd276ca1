// Basic surfaces for the 4D scenes: flat cloth, the Clifford torus and round 2-spheres.
#pragma once
#include "shape/surface.hpp"

namespace s4d {

// A flat size × size square of n × n vertices in the xy-plane, centred on the origin (z = w = 0).
Surface<4> cloth(int n, double size);

// The Clifford torus (cos u, sin u, cos v, sin v): n samples of u (rows) × m of v (cols), both
// wrapped; every vertex lies on the 3-sphere of radius √2.
Surface<4> clifford_torus(int n, int m);

// A round 2-sphere in the first three coordinates (the rest equal to centre's): n samples around
// each latitude and max(2, n / 2) latitude bands, with one vertex at each pole. Closed, χ = 2.
// No grid (the poles are not grid vertices). Instantiated for D = 3 and D = 4; needs n >= 3.
template <int D>
Surface<D> uv_sphere(int n, double radius, const Vec<D>& centre);

}  // namespace s4d
