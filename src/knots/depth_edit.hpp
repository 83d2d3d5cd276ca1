// Edits of a curve along the view's depth axis only, so its shadow (and the crossings' places)
// stay put: changing one crossing from over to under, and smoothing the depth after such
// choices (the paper's section 4.2) without ever changing an over/under decision.
#pragma once
#include <array>
#include <span>
#include <vector>

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

// The constrained smoothing itself, on plain depth values, for anything that keeps a depth per
// vertex along chains (a knot's components; a ribbon's rows, whose w is one per row).
struct DepthChain {
  std::vector<double> z;  // depth of each vertex along the chain
  bool closed = true;     // closed: the last vertex neighbours the first; open: ends are free
};
struct DepthTerm {
  int chain = 0, index = 0;
  double weight = 0;
};
// sum(weight × z) >= floor + gap; its order (over/under, above/below) holds while the sum > floor.
struct DepthConstraint {
  std::array<DepthTerm, 4> terms{};
  int count = 0;  // terms used
  double floor = 0;
  double gap = 0;
  double value(const std::vector<DepthChain>& chains) const {
    double v = 0;
    for (int k = 0; k < count; ++k) v += terms[k].weight * chains[terms[k].chain].z[terms[k].index];
    return v;
  }
};
// Projects the depths onto the constraints, one minimum-norm correction each, for at most `sweeps`
// sweeps; true once none is short of its gap by more than `tolerance`.
bool project_depth(std::vector<DepthChain>& chains, std::span<const DepthConstraint> constraints,
                   int sweeps, double tolerance = 0);
// Laplacian smoothing (`iterations` steps at `rate`), each step followed by up to `sweeps`
// projections. Returns the index of the first constraint whose order was lost, or -1.
int smooth_depth_values(std::vector<DepthChain>& chains, std::span<const DepthConstraint> constraints,
                        int iterations, double rate, int sweeps = 8);

// Smooths the depth coordinate (along frame.axis(2)) of every vertex while keeping, at every
// crossing of the view, the over strand at least `clearance` above the under one. Shadows, and
// so the diagram and the knot type, are unchanged.
Curve<3> smooth_depth(const Curve<3>& curve, const Frame<3>& frame, const DepthSmoothing& s = {});

}  // namespace s4d
