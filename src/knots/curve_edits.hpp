// The diagram toolbar's edits of a knot or link as a curve (KnotFolio's mirror, reverse and delete):
// each returns the changed curve and leaves the input as it was.
#pragma once
#include "shape/curve.hpp"

namespace s4d {

// The mirror image: reflected through the plane z = (its centre's z), so it stays where it was.
// Every crossing seen from +z changes; the knot becomes its mirror image.
Curve<3> mirrored_curve(const Curve<3>& curve);

// Component `c` (0-based) run the other way round. Throws s4d::Error for a missing component.
Curve<3> with_component_reversed(const Curve<3>& curve, int c);

// Component `c` (0-based) left out. Throws s4d::Error for a missing component, or when it is the
// only one (a knot needs a curve).
Curve<3> with_component_deleted(const Curve<3>& curve, int c);

}  // namespace s4d
