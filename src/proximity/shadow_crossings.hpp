// Crossings of a curve's shadow: pairs of segments whose projections onto the first D-1 view axes
// of a Frame<D> meet, with the depth of both strands there (the knot engine's over/under input).
#pragma once
#include <vector>

#include "core/frame.hpp"
#include "shape/curve.hpp"

namespace s4d {

// A segment of a Curve: segment k of component c joins points[k] and points[(k+1) % n].
struct SegmentRef {
  int component = 0;
  int segment = 0;
  friend bool operator==(const SegmentRef&, const SegmentRef&) = default;
  friend auto operator<=>(const SegmentRef&, const SegmentRef&) = default;
};

template <int D>
struct ShadowCrossing {
  SegmentRef a, b;        // a < b in (component, segment) order
  double ta = 0, tb = 0;  // parameter along each segment, in [0, 1): 0 = its first point
  Vec<D - 1> point;       // the crossing in shadow coordinates (first D-1 view coordinates)
  double depth_a = 0;     // view depth of strand a there (Frame::depth, larger = nearer the viewer)
  double depth_b = 0;     // view depth of strand b there
  bool a_over() const { return depth_a > depth_b; }  // strand a passes over (nearer the viewer)
};

struct ShadowCrossingOptions {
  // D = 3: ignored, 2D crossings are found exactly. D >= 4: shadows of curves in a (D-1)-space
  // meet only non-generically, so strands whose shadows come within `tolerance` count as crossing.
  double tolerance = 0;
};

template <int D>
struct ShadowCrossingResult {
  std::vector<ShadowCrossing<D>> crossings;  // sorted by (a, ta)
  // Non-generic spots of this projection: a shadow crossing exactly at a vertex, two shadow
  // segments overlapping along a line, or a segment whose shadow is a point. A caller that needs a
  // regular diagram (Gauss codes) should turn the frame slightly when this is non-zero.
  int non_generic = 0;
};

// Every crossing of the shadow of `curve` seen through `frame`. Segments sharing a vertex are not
// paired (they meet at that vertex by construction). Each segment is half-open [0, 1) (the last
// segment of an open polyline is closed [0, 1]), so a crossing at a vertex is reported once.
// Non-finite points are skipped and counted as non-generic. Uses a BVH on the shadow boxes.
template <int D>
ShadowCrossingResult<D> shadow_crossings(const Curve<D>& curve, const Frame<D>& frame,
                                         const ShadowCrossingOptions& options = {});

extern template ShadowCrossingResult<3> shadow_crossings<3>(const Curve<3>&, const Frame<3>&,
                                                            const ShadowCrossingOptions&);
extern template ShadowCrossingResult<4> shadow_crossings<4>(const Curve<4>&, const Frame<4>&,
                                                            const ShadowCrossingOptions&);

}  // namespace s4d
