// Adaptive resampling of a closed curve to nearly equal segment lengths that provably keeps its
// knot type: each new chord replaces a piece of the old polyline only if the triangles swept on
// the way (a Delta move) are pierced by no other strand; otherwise the old vertices stay.
#pragma once
#include "shape/curve.hpp"

namespace s4d {

struct ResampleStats {
  int moves = 0;     // chords accepted
  int refused = 0;   // chords refused because a strand pierced their Delta triangles
};

// `spacing` > 0 is the target segment length; each component gets max(3, round(L / spacing))
// points (at least 4 for safety when the curve is tiny). Validates like validate_knot_curve.
Curve<3> resample_curve(const Curve<3>& curve, double spacing, ResampleStats* stats = nullptr);
// Same with a total point budget spread over the components by length.
Curve<3> resample_curve_to_count(const Curve<3>& curve, int points, ResampleStats* stats = nullptr);

}  // namespace s4d
