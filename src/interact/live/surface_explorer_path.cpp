// Parsing and arc-length walking of the scripted hand's polyline.
#include "interact/live/surface_explorer_path.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace s4d {

std::vector<Vec3> parse_point_list(std::string_view text, std::string_view option) {
  std::vector<Vec3> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    std::string item(text.substr(start, end - start));
    start = end + 1;
    if (item.find_first_not_of(" \t") == std::string::npos) {
      if (end == text.size()) break;
      continue;
    }
    double x = 0, y = 0, z = 0;
    char extra = 0;
    if (std::sscanf(item.c_str(), " %lf , %lf , %lf %c", &x, &y, &z, &extra) != 3 || !std::isfinite(x) ||
        !std::isfinite(y) || !std::isfinite(z))
      throw Error(std::string(option) + ": point " + std::to_string(out.size() + 1) + " '" + item +
                  "' should be three finite numbers x,y,z");
    out.emplace_back(x, y, z);
  }
  if (out.size() < 2)
    throw Error(std::string(option) + " needs at least two points, e.g. \"0,-1,0;0,1,0\"");
  return out;
}

PolylinePath::PolylinePath(std::vector<Vec3> points) : points_(std::move(points)) {
  if (points_.size() < 2) throw Error("a path needs at least two points");
  cumulative_.assign(1, 0.0);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (!points_[i].allFinite()) throw Error("path point " + std::to_string(i + 1) + " is not finite");
    if (i > 0) cumulative_.push_back(cumulative_.back() + (points_[i] - points_[i - 1]).norm());
  }
}

Vec3 PolylinePath::at_length(double s) const {
  if (!(s > 0)) return points_.front();
  if (s >= length()) return points_.back();
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  const std::size_t i = static_cast<std::size_t>(it - cumulative_.begin()) - 1;
  const double seg = cumulative_[i + 1] - cumulative_[i];
  const double u = seg > 0 ? (s - cumulative_[i]) / seg : 0.0;
  return points_[i] + u * (points_[i + 1] - points_[i]);
}

Vec3 PolylinePath::at_time(double t, double seconds) const {
  if (!(seconds > 0)) return points_.back();
  return at_length(length() * std::clamp(t / seconds, 0.0, 1.0));
}

}  // namespace s4d
