// The one place where our KnotDiagram meets Regina's Link type (kept out of the other headers so
// that only code needing Regina pays for its headers).
#pragma once
#include <link/link.h>

#include "knots/knot_diagram.hpp"

namespace s4d {

// Regina's diagram of the same crossings, signs and components (throws Error if inconsistent).
regina::Link to_regina_link(const KnotDiagram& diagram);

}  // namespace s4d
