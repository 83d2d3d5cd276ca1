// Polyline helpers used by the generators: arc-length resampling and rotation-minimising frames.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/error.hpp"
#include "core/vec.hpp"

namespace s4d {

// Resamples a polyline (points  #P × D) to n points equally spaced in arc length. An open
// polyline keeps both end points; a closed one keeps points[0] and spaces n points around the
// loop (the last one does not repeat the first). Generators build curves densely and then
// resample, so that mesh rows are evenly spaced however the curve was parametrised.
template <int D>
std::vector<Vec<D>> resample_by_arc_length(const std::vector<Vec<D>>& points, int n, bool closed) {
  if (points.size() < 2) throw Error("cannot resample a polyline with fewer than two points");
  if (n < 2) throw Error("cannot resample a polyline to fewer than two points");
  const std::size_t np = points.size();
  const std::size_t segs = closed ? np : np - 1;
  std::vector<double> cum(segs + 1, 0.0);  // arc length at the start of each segment
  for (std::size_t k = 0; k < segs; ++k)
    cum[k + 1] = cum[k] + (points[(k + 1) % np] - points[k]).norm();
  const double total = cum.back();
  if (!(total > 0)) throw Error("cannot resample a polyline of zero length");

  std::vector<Vec<D>> out;
  out.reserve(static_cast<std::size_t>(n));
  const double step = closed ? total / n : total / (n - 1);
  std::size_t k = 0;
  for (int i = 0; i < n; ++i) {
    const double s = (!closed && i == n - 1) ? total : i * step;
    while (k + 1 < segs && cum[k + 1] < s) ++k;
    const double len = cum[k + 1] - cum[k];
    const double f = len > 0 ? std::clamp((s - cum[k]) / len, 0.0, 1.0) : 0.0;
    out.push_back(points[k] + f * (points[(k + 1) % np] - points[k]));
  }
  return out;
}

// Unit tangents of a polyline by central differences (one-sided at the ends of an open one).
std::vector<Vec3> polyline_tangents(const std::vector<Vec3>& points, bool closed);

// A rotation-minimising unit normal at every point (double reflection method of Wang, Jüttler,
// Zheng & Liu, 2008): the normal turns only as much as the tangent forces it to, so a ribbon
// built from it does not twist around its core. `initial` fixes the first normal (projected
// off the first tangent); it must not be parallel to that tangent.
std::vector<Vec3> rotation_minimising_normals(const std::vector<Vec3>& points, bool closed,
                                              const Vec3& initial);

}  // namespace s4d
