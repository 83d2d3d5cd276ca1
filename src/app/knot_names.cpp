#include "app/knot_names.hpp"

#include <algorithm>
#include <functional>
#include <variant>

#include "core/error.hpp"
#include "knots/knot_curve.hpp"
#include "knots/knot_identify.hpp"

namespace s4d {

namespace {
// Changes whenever a point of the curve does.
std::size_t points_hash(const Shape& shape) {
  std::size_t h = 0;
  auto mix = [&h](std::size_t v) { h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2); };
  std::visit(
      [&](const auto& s) {
        if constexpr (requires { s.components; })
          for (const auto& poly : s.components) {
            mix(poly.points.size() * 2 + poly.closed);
            for (const auto& p : poly.points)
              for (int k = 0; k < p.size(); ++k) mix(std::hash<double>{}(p[k]));
          }
      },
      shape);
  return h;
}
}  // namespace

bool KnotNames::nameable(const SceneObject& obj) {
  return std::holds_alternative<Curve<3>>(obj.shape) || std::holds_alternative<Curve<4>>(obj.shape);
}

const std::string* KnotNames::find(const SceneObject& obj) {
  const auto it = std::find_if(named_.begin(), named_.end(),
                               [&](const Named& n) { return n.object == obj.name; });
  if (it == named_.end()) return nullptr;
  if (it->points_hash != points_hash(obj.shape)) {
    named_.erase(it);
    return nullptr;
  }
  return &it->line;
}

const std::string& KnotNames::name(const SceneObject& obj) {
  std::string line;
  try {
    line = "knot: " + identify_knot(knot_curve_of(obj.shape, "'" + obj.name + "'")).headline();
  } catch (const Error& e) {
    line = e.what();
  }
  std::erase_if(named_, [&](const Named& n) { return n.object == obj.name; });
  named_.push_back({obj.name, points_hash(obj.shape), std::move(line)});
  return named_.back().line;
}

}  // namespace s4d
