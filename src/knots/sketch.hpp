// Sketching a knot in a plane (the paper's section 4.2): the hand's stroke is smoothed with
// Dynadraw and closed; where it crosses what it has already drawn, the new strand passes over,
// or under while the user holds the "under" modifier (the paper's explicit over/under choice);
// the depth is then smoothed without changing any choice.
#pragma once
#include <span>
#include <vector>

#include "knots/dynadraw.hpp"
#include "knots/stroke.hpp"
#include "shape/curve.hpp"

namespace s4d {

// A cursor sample in the sketch plane; `under`: the modifier held, this part passes under.
using SketchSample = StrokeSample<2>;

struct SketchOptions {
  DynadrawParams pen;
  double spacing = 0;       // of the knot's points; 0: 1/120 of the stroke's size
  double clearance = 0.05;  // depth gap at every crossing, × the stroke's size
};

struct SketchedKnot {
  Curve<3> curve;     // one closed component: (x, y) over the smoothed stroke, z its depth
                      // (towards the viewer, as Frame<3>() sees it)
  int crossings = 0;  // of its diagram in that view
};

// A stroke as the curve file `shadow4d knot sketch FILE --knot` reads: one open polyline of points
// (x, y, u), u = 1 where the modifier was held. Times are not kept: the reader spaces samples by
// `dt`, so the pen's smoothing may differ a little but the crossings and their choices do not.
Curve<3> stroke_as_curve(std::span<const SketchSample> stroke);
// The inverse: the first component's points, `dt` seconds apart. Throws s4d::Error for no points.
std::vector<SketchSample> stroke_from_curve(const Curve<3>& curve, double dt);

// Throws s4d::Error for a stroke of fewer than 3 samples, with non-finite values or times that go
// back, with no extent, or whose smoothed path runs along itself (draw it again).
SketchedKnot knot_from_sketch(std::span<const SketchSample> stroke, const SketchOptions& options = {});

}  // namespace s4d
