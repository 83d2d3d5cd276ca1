// KnotDiagram: the combinatorial knot or link diagram of a closed Curve<3> seen through a Frame<3>
// (crossings with over/under and sign, in order along each component) and every code derived from
// it: Gauss (classical, extended, signed "1+a"), planar diagram (PD), writhe, linking numbers.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "core/frame.hpp"
#include "shape/curve.hpp"

namespace s4d {

// One visit of a component to a crossing.
struct Passage {
  int crossing = 0;      // index into KnotDiagram::crossings
  bool over = false;     // this strand passes over (nearer the viewer)
  int component = 0;     // which component of the curve
  double position = 0;   // segment index + parameter in [0, 1) along that component (curve input)
};

struct DiagramCrossing {
  int sign = 1;          // +1 right-handed (positive), -1 left-handed
  int over = 0;          // passage index of the over strand
  int under = 0;         // passage index of the under strand
  Vec2 point = Vec2::Zero();  // where it is in shadow coordinates (zero for abstract diagrams)
  double depth_over = 0, depth_under = 0;  // view depths of both strands there (curve input)
};

struct KnotDiagram {
  std::vector<DiagramCrossing> crossings;   // labelled 1..n in order of first visit (codes use it)
  std::vector<Passage> passages;            // 2n visits
  std::vector<std::vector<int>> components; // per component, its passage indices in order

  int crossing_count() const { return static_cast<int>(crossings.size()); }
  int component_count() const { return static_cast<int>(components.size()); }
  int writhe() const;
  // Symmetric matrix (components × components) of linking numbers; the diagonal is 0.
  std::vector<std::vector<int>> linking_numbers() const;

  // Classical Gauss code, one list per component: +k over crossing k, -k under ("1, -2, 3, -1,
  // 2, -3"); components separated by " | ".
  std::string gauss_code() const;
  // KnotInfo's extended Gauss code: first visit signed over(+)/under(-), second visit signed by the
  // crossing's handedness (+ right-handed).
  std::string extended_gauss_code() const;
  // The live-display form: each visit as label, handedness sign, a(bove) or b(elow):
  // "1+a, 2+b, 3+a, 1+b, 2+a, 3+b" for the right-handed trefoil.
  std::string signed_gauss_code() const;
  // Planar diagram: X[i, j, k, l] per crossing, i the incoming under edge, then counter-clockwise
  // (Knot Atlas / KnotInfo convention). Edges are numbered from 1 along the components in order.
  // Components without crossings get no entry.
  std::vector<std::array<int, 4>> pd() const;
  std::string pd_code() const;  // "PD[X[1, 5, 2, 4], ...]"

  // The same diagram with crossing k (0-based) changed: over and under swapped, sign negated.
  KnotDiagram with_crossing_changed(int k) const;
  // The same diagram with component c's orientation reversed: its passages in reverse order, the
  // signs of its crossings with other components negated.
  KnotDiagram with_component_reversed(int c) const;
  // The mirror image: every crossing changed.
  KnotDiagram mirrored() const;
  // Relabels crossings in order of first visit (components in order, from their first passage).
  void normalise();
};

struct DiagramOptions {
  // Two strands nearer than this (relative to the curve's size) where their shadows cross make
  // the curve "self-intersecting" and are rejected.
  double touch_tolerance = 1e-9;
  // How many tiny frame perturbations to try when the projection is not generic.
  int max_perturbations = 12;
};

// The diagram of `curve` seen through `frame`. Every component must be closed, finite, with at
// least 3 points and no repeated consecutive point; the curve must not touch itself. A
// non-generic view (crossings at vertices, parallel overlapping shadows, triple points) is turned
// by a tiny deterministic rotation first; `used_frame` receives the frame actually used.
// Throws s4d::Error with a sentence saying what is wrong and where.
KnotDiagram diagram_from_curve(const Curve<3>& curve, const Frame<3>& frame,
                               const DiagramOptions& options = {}, Frame<3>* used_frame = nullptr);

// The checks that need no view: closed components of at least 3 finite points, no repeated
// consecutive point. (Touching strands are found by diagram_from_curve.) Throws s4d::Error.
void validate_knot_curve(const Curve<3>& curve);

// Size of the curve (bounding-box diagonal), the scale of every tolerance.
double curve_scale(const Curve<3>& curve);

}  // namespace s4d
