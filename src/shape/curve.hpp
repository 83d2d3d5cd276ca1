// Curve<D>: polylines in R^D, open or closed, one per component (a link has several).
#pragma once
#include <cstddef>
#include <vector>

#include "core/vec.hpp"

namespace s4d {

template <int D>
struct Polyline {
  std::vector<Vec<D>> points;  // n × D
  bool closed = true;          // closed: the last point joins the first

  std::size_t segment_count() const {
    const std::size_t n = points.size();
    if (n < 2) return 0;
    return closed ? n : n - 1;
  }
  // Segment k joins points[k] and points[(k+1) % n].
  const Vec<D>& seg_a(std::size_t k) const { return points[k]; }
  const Vec<D>& seg_b(std::size_t k) const { return points[(k + 1) % points.size()]; }
  double length() const {
    double l = 0;
    for (std::size_t k = 0; k < segment_count(); ++k) l += (seg_b(k) - seg_a(k)).norm();
    return l;
  }
};

template <int D>
struct Curve {
  static constexpr int kDim = D;
  std::vector<Polyline<D>> components;

  std::size_t point_count() const {
    std::size_t n = 0;
    for (const auto& c : components) n += c.points.size();
    return n;
  }
  std::size_t segment_count() const {
    std::size_t n = 0;
    for (const auto& c : components) n += c.segment_count();
    return n;
  }
  double length() const {
    double l = 0;
    for (const auto& c : components) l += c.length();
    return l;
  }
  bool all_closed() const {
    for (const auto& c : components)
      if (!c.closed) return false;
    return !components.empty();
  }
};

}  // namespace s4d
