// Edits of a curve along the view's depth axis only, so its shadow (and the crossings' places)
// stay put: changing one crossing from over to under, and smoothing the depth after such
// choices (the paper's section 4.2) without ever changing an over/under decision.
#pragma once
#include "core/frame.hpp"
#include "shape/curve.hpp"

namespace s4d {

// The curve with crossing `label` (1-based, as numbered in the diagram's codes) changed: the
// under strand is lifted over the other one right at the crossing (three points are inserted on
// it so nothing else moves). The crossing is found in the view diagram_from_curve uses for
// `frame`; the result's diagram in that view equals the old one with that crossing changed.
// Throws Error for bad curves or a label out of range.
Curve<3> flip_crossing(const Curve<3>& curve, const Frame<3>& frame, int label);

struct DepthSmoothing {
  int iterations = 200;
  double rate = 0.5;          // Laplacian smoothing rate per iteration, in (0, 1]
  double clearance = 0.05;    // minimum depth gap kept at every crossing, × the curve's size
};

// Smooths the depth coordinate (along frame.axis(2)) of every vertex while keeping, at every
// crossing of the view, the over strand at least `clearance` above the under one. Shadows, and
// so the diagram and the knot type, are unchanged.
Curve<3> smooth_depth(const Curve<3>& curve, const Frame<3>& frame, const DepthSmoothing& s = {});

}  // namespace s4d
