// Finder (a): where a surface in R^D meets itself (or another surface): touching or crossing
// triangle pairs and the distinct points where they meet. The "no pass-through" check.
#pragma once
#include <array>
#include <span>
#include <vector>

#include "proximity/mesh_proximity.hpp"
#include "shape/surface.hpp"

namespace s4d {

struct IntersectionOptions {
  // Pairs closer than this count as meeting (scene units). < 0: 1e-9 × bounding-box diagonal.
  double tolerance = -1;
  // Meeting points closer than this are the same point. < 0: 1e-6 × bounding-box diagonal.
  double merge_distance = -1;
};

template <int D>
struct IntersectionReport {
  std::vector<ProximityPair<D>> pairs;  // triangle pairs that meet (self: sharing no vertex)
  // Distinct meeting points: the closest-point midpoint of each pair, merged within
  // merge_distance. For transverse crossings in R^4 these are the isolated intersection points;
  // for a non-transverse contact (a whole curve of contact) one point per pair is listed.
  std::vector<Vec<D>> points;
  double tolerance = 0;       // the tolerances actually used
  double merge_distance = 0;
};

// Self-intersections of one surface: triangle pairs sharing no vertex.
template <int D>
IntersectionReport<D> self_intersections(const Surface<D>& s, const IntersectionOptions& opt = {});
// The same test over the given triangle pairs only, for a caller that knows where meetings can
// be (pairs sharing a vertex, or a triangle with itself, are skipped; the tolerances are those
// self_intersections would use for the whole surface): it reports exactly the pairs of
// self_intersections that are among `candidates`, without a broad phase over the whole surface.
// Throws s4d::Error for a pair naming no triangle of `s`.
template <int D>
IntersectionReport<D> self_intersections_among(const Surface<D>& s,
                                               std::span<const std::array<int, 2>> candidates,
                                               const IntersectionOptions& opt = {});
// Intersections of two different surfaces: every triangle pair.
template <int D>
IntersectionReport<D> surface_intersections(const Surface<D>& a, const Surface<D>& b,
                                            const IntersectionOptions& opt = {});

// Merges points closer than `distance` (single linkage through a hash grid); returns one
// representative (the first seen) per cluster, in first-seen order.
template <int D>
std::vector<Vec<D>> merge_points(const std::vector<Vec<D>>& points, double distance);

}  // namespace s4d
