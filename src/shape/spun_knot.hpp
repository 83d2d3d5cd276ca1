// Artin spinning: an arc in the half-space z >= 0 with its ends on z = 0, spun about the plane
// z = w = 0 of R^4, sweeps a 2-sphere; spinning a knotted arc gives a knotted sphere.
#pragma once
#include <vector>

#include "shape/surface.hpp"

namespace s4d {

// (x, y, z) -> (x, y, z cos θ, z sin θ) for m angles θ. arc (#P × 3) must have z = 0 at both
// ends and z > 0 everywhere else; its ends become the two poles. Vertices: 2 poles and
// (#P - 2) × m ring vertices; closed, χ = 2. Throws s4d::Error for an arc that breaks the rules.
Surface<4> spin_arc(const std::vector<Vec3>& arc, int m);

// The spun trefoil: the knotted trefoil arc (knotted_arc.hpp) with n samples, spun with m.
Surface<4> spun_trefoil(int n, int m);

}  // namespace s4d
