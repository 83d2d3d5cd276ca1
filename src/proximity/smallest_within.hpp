// The smallest distance a pairs-within query finds up to a radius, without listing every pair
// within that radius: on a fine mesh one query at the radius can list millions of pairs.
#pragma once
#include <algorithm>
#include <limits>

namespace s4d {

// within(r): the smallest distance among the pairs within r (infinity when none). It is asked at
// radii doubling from up_to / 64, so the query that finds a pair lists only those within twice
// the answer. Returns that distance, or infinity when nothing lies within up_to.
template <class Within>
double smallest_within(double up_to, Within&& within) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (!(up_to >= 0)) return inf;
  for (double r = up_to / 64;; r = std::min(2 * r, up_to)) {
    const double d = within(r);
    if (d <= r) return d;
    if (r >= up_to) return inf;
  }
}

}  // namespace s4d
