// A scripted hand for exploring: a polyline of shadow-space points ("x,y,z;x,y,z;...") walked at a
// steady speed, as `shadow4d explore --through` and the tests drive the simulated arm.
#pragma once
#include <string_view>
#include <vector>

#include "core/vec.hpp"

namespace s4d {

// Parses "x,y,z;x,y,z;..." (at least two points, all finite). Throws Error naming the bad point.
std::vector<Vec3> parse_point_list(std::string_view text, std::string_view option = "--through");

class PolylinePath {
 public:
  // Throws Error for fewer than two points or non-finite ones.
  explicit PolylinePath(std::vector<Vec3> points);
  double length() const { return cumulative_.back(); }
  // The point at arc length s (clamped to [0, length]).
  Vec3 at_length(double s) const;
  // The point at time t of a walk lasting `seconds` at constant speed, holding the ends outside.
  Vec3 at_time(double t, double seconds) const;
  const std::vector<Vec3>& points() const { return points_; }

 private:
  std::vector<Vec3> points_;
  std::vector<double> cumulative_;  // arc length at each point
};

}  // namespace s4d
