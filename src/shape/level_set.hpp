// The slice of a triangle mesh in R^D by the hyperplane "depth = c" of a view frame: the level set
// of the frame's last coordinate on the mesh, as polylines in the shadow's coordinates (R^(D-1)).
// For a surface of R^4 that hyperplane is parallel to the shadow space, so the slice is a link
// drawn on the shadow: one frame of the surface's motion picture.
#pragma once
#include <vector>

#include "core/frame.hpp"
#include "shape/curve.hpp"
#include "shape/surface.hpp"

namespace s4d {

template <int D>
struct LevelSet {
  double level = 0;
  // Closed curves where the mesh is closed around them; an open polyline ends on the mesh's
  // boundary (or at a non-manifold edge). Closed ones are oriented as the boundary of the part
  // below the level when the mesh is consistently oriented.
  Curve<D - 1> curve;
  int open_components = 0;
  // Corners the level passed exactly through (vertices at the level, taken as just above it).
  int vertices_at_level = 0;
};

// The level set of depth = `level` on `mesh` seen through `frame`. Vertices exactly at the level
// count as just above it (a symbolic perturbation of the level downwards), so the result is the
// limit of the slices just below `level`: a vertex on the level is a corner of the curve, never
// two curves meeting; points closer than 1e-12 of the mesh's size along a curve are merged, and a
// curve that shrinks to a point (a maximum at the level) is left out.
template <int D>
LevelSet<D> level_set(const Surface<D>& mesh, const Frame<D>& frame, double level);

// The smallest and largest depth of the mesh's vertices in `frame` ({0, 0} for no vertices).
template <int D>
std::pair<double, double> depth_range(const Surface<D>& mesh, const Frame<D>& frame);

// `count` levels strictly inside [lo, hi], evenly spaced: lo + (i + 1)(hi - lo)/(count + 1). An
// odd count puts the middle one at (lo + hi)/2. None for count < 1.
std::vector<double> movie_levels(double lo, double hi, int count);

// The slice's points back in R^D: each shadow point with depth `level`.
template <int D>
Curve<D> lift_slice(const Curve<D - 1>& slice, const Frame<D>& frame, double level);

}  // namespace s4d
