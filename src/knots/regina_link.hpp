// The one place where our KnotDiagram meets Regina's Link type (kept out of the other headers so
// that only code needing Regina pays for its headers).
#pragma once
#include <link/link.h>

#include "knots/knot_diagram.hpp"

namespace s4d {

// Regina's diagram of the same crossings, signs and components (throws Error if inconsistent).
regina::Link to_regina_link(const KnotDiagram& diagram);

// The inverse: our abstract diagram (no geometry) of a Regina link, crossings labelled in order of
// first visit. Crossing-free components become empty components.
KnotDiagram diagram_from_regina(const regina::Link& link);

}  // namespace s4d
