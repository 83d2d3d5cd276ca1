// Finder (b): the intersection curves of a surface's 3D shadow (a Surface<4> seen through a
// Frame<4>), with the 4D depth of both sheets along them: the paper's projection-based depth test.
// Where the depths differ the crossing is only in the shadow; where they agree the surface truly
// meets itself in R^4.
#pragma once
#include <string>
#include <vector>

#include "core/frame.hpp"
#include "shape/surface.hpp"

namespace s4d {

struct ShadowSegment {
  int a = 0, b = 0;          // the two triangles (self: a < b, sharing no vertex)
  Vec3 p0, p1;               // ends of the segment in shadow space (view x, y, z)
  double depth_a0 = 0, depth_b0 = 0;  // 4D depth (view w) of sheet a and sheet b at p0
  double depth_a1 = 0, depth_b1 = 0;  // ... at p1
  // The depth difference vanishes on the segment: the two sheets meet in R^4 at `meet`.
  bool true_intersection = false;
  Vec3 meet = Vec3::Zero();  // shadow of that 4D intersection point (when true)
  double length() const { return (p1 - p0).norm(); }
};

struct ShadowCurve {
  std::vector<int> segments;  // indices into ShadowIntersections::segments, in no special order
  bool closed = false;        // every end point is shared by exactly two segments
  double length = 0;
  int true_points = 0;        // segments of this curve that carry a true 4D intersection
  bool true_intersection() const { return true_points > 0; }
};

// A curve's segments in walking order, from one end or branch point to the next (or once around
// a loop): what a drawing joins into one smooth polyline.
struct ShadowStroke {
  std::vector<int> segments;  // indices into ShadowIntersections::segments, in order
  std::vector<Vec3> points;   // segments.size() + 1 points (closed: the last equals the first)
  bool closed = false;
};

struct ShadowIntersections {
  std::vector<ShadowSegment> segments;
  std::vector<ShadowCurve> curves;  // segments chained by shared end points
  std::vector<ShadowStroke> strokes;  // every segment in exactly one stroke
  double total_length = 0;
  int shadow_only_curves = 0;       // curves whose sheets are apart in depth everywhere
  int true_curves = 0;              // curves that pass through a true 4D intersection
  int coplanar_pairs = 0;           // triangle pairs whose shadows are coplanar and overlap
                                    // (not a curve; the frame is non-generic there)
};

// What one or several ShadowIntersections add up to (a surface with itself, pairs of surfaces):
// the one line that `check`, the view panel and `render` give.
struct ShadowCurveCounts {
  int curves = 0;
  int shadow_only_curves = 0;
  int true_curves = 0;
  int true_points = 0;     // segments carrying a true 4D intersection
  int coplanar_pairs = 0;  // sheets overlapping in area: the view is not generic
  double length = 0;
  void add(const ShadowIntersections& r);
};

// "3 curve(s), total length 1.2: 2 shadow-only, 1 true (2 true point(s))", and "; the view is not
// generic (sheets overlap in area): turn it" when it is not.
std::string counts_text(const ShadowCurveCounts& c);

struct ShadowIntersectionOptions {
  // Segment end points closer than this are joined into one curve. < 0: 1e-9 × shadow diagonal.
  double join_distance = -1;
};

// Intersection curves of the shadow of `s` with itself (triangle pairs sharing no vertex).
ShadowIntersections shadow_intersections(const Surface<4>& s, const Frame<4>& frame,
                                         const ShadowIntersectionOptions& opt = {});
// Intersection curves of the shadows of two different surfaces.
ShadowIntersections shadow_intersections(const Surface<4>& a, const Surface<4>& b,
                                         const Frame<4>& frame,
                                         const ShadowIntersectionOptions& opt = {});

}  // namespace s4d
