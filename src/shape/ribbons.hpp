// Ribbons: strips swept along a core curve. The open trefoil ribbon of the paper's Fig. 10 and
// closed ribbon loops (annuli) such as the links of a 4D chain.
#pragma once
#include <vector>

#include "shape/surface.hpp"

namespace s4d {

// A strip of width `width` centred on `core` (#P × 3), spreading along `normals` (#P × 3, unit,
// perpendicular to the core): grid rows = core points, cols = m samples across; a closed core
// wraps the rows. Needs m >= 2 and width > 0.
Surface<3> ribbon_along(const std::vector<Vec3>& core, bool closed,
                        const std::vector<Vec3>& normals, double width, int m);

// The trefoil ribbon: n samples along the open trefoil arc with tails (knotted_arc.hpp), m
// across, the width direction from a rotation-minimising frame that starts flat (along y) on
// the first tail. Embedded for width <= kMaxTrefoilRibbonWidth.
Surface<3> trefoil_ribbon(int n, int m, double width);
inline constexpr double kMaxTrefoilRibbonWidth = 0.4;

// A closed ribbon (annulus) around the circle centre + radius (cos u e1 + sin u e2), spreading
// along `across` (e1, e2, across orthonormal): n samples around, m across, rows wrapped.
Surface<4> ribbon_loop(const Vec4& centre, const Vec4& e1, const Vec4& e2, const Vec4& across,
                       double radius, double width, int n, int m);
// The default loop: around the origin in the xy-plane, spreading along z (w = 0).
Surface<4> ribbon_loop(int n, int m, double radius, double width);

}  // namespace s4d
