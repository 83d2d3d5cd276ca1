// The HOMFLY-PT and Jones polynomials without Regina, in Regina's normalisation: HOMFLY-PT in
// (alpha, z) with alpha P+ - alpha^-1 P- = z P0 and P(unknot) = 1, Jones in s = t^(1/2) with
// V(unknot) = 1. The HOMFLY-PT polynomial comes from the skein relation, recursing to descending
// diagrams (unlinks) with R1/R2 removal and memoisation at every step; the Kauffman bracket's
// state sum gives Jones independently (the tests' brute-force reference; 2^n states).
#pragma once
#include "knots/diagram_moves.hpp"
#include "knots/polynomial.hpp"

namespace s4d {

Laurent2 homfly_polynomial(const KnotDiagram& diagram);
Laurent2 homfly_polynomial(const GaussDiagram& diagram);

// Jones from HOMFLY-PT: alpha = t^-1, z = t^(1/2) - t^(-1/2), for a link of `components`
// components (the division by z^(components - 1) is exact).
Laurent1 jones_from_homfly(const Laurent2& homfly_az, int components);

// Jones from the Kauffman bracket state sum, (-A^3)^-writhe <D> with A = t^(-1/4), in s = t^(1/2).
// Throws Error above 24 crossings (2^n states).
Laurent1 jones_by_state_sum(const KnotDiagram& diagram);

}  // namespace s4d
