// Drawing a combinatorial knot or link diagram (a PD code, a census diagram) as a 3D curve: a
// planar straight-line drawing of the diagram (Tutte's barycentric embedding of its barycentric
// subdivision), lifted over and under at the crossings, then resampled and relaxed.
#pragma once
#include "knots/knot_diagram.hpp"
#include "shape/curve.hpp"

namespace s4d {

struct DiagramEmbedding {
  int points_per_crossing = 24;  // of the finished curve (at least 60 points in all)
  int relax_iterations = 600;    // knots/relax steps after the drawing (0: the raw drawing)
};

// A curve whose diagram seen from +z (the identity Frame<3>) is `diagram` before relaxation:
// same crossings, over/under and signs, so the knot or link and its chirality are those of the
// diagram (relaxation never passes a strand through another). The diagram must be planar and
// connected, every component with at least one crossing, or a single crossing-free circle.
// Throws s4d::Error otherwise.
Curve<3> curve_from_diagram(const KnotDiagram& diagram, const DiagramEmbedding& options = {});

}  // namespace s4d
