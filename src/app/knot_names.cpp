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

std::string identification_line(const SceneObject& obj) {
  try {
    return "knot: " + identify_knot(knot_curve_of(obj.shape, "'" + obj.name + "'")).headline();
  } catch (const Error& e) {
    return e.what();
  }
}
}  // namespace

bool KnotNames::nameable(const SceneObject& obj) {
  return std::holds_alternative<Curve<3>>(obj.shape) || std::holds_alternative<Curve<4>>(obj.shape);
}

KnotNames::Named& KnotNames::entry(const SceneObject& obj, std::size_t hash) {
  auto it = std::find_if(named_.begin(), named_.end(),
                         [&](const Named& n) { return n.object == obj.name; });
  if (it == named_.end()) it = named_.insert(named_.end(), Named{obj.name, hash, false, {}});
  if (it->points_hash != hash) *it = Named{obj.name, hash, false, {}};
  return *it;
}

const std::string* KnotNames::live(const SceneObject& obj) {
  const std::size_t hash = points_hash(obj.shape);
  const bool known = std::any_of(named_.begin(), named_.end(), [&](const Named& n) {
    return n.object == obj.name && n.points_hash == hash;
  });
  Named& e = entry(obj, hash);
  if (!known) {
    // Named now unless its diagram is large; a bad curve is named now too (its line says why).
    bool small = true;
    try {
      const Curve<3> c = knot_curve_of(obj.shape, obj.name);
      small = diagram_from_curve(c, Frame<3>()).crossing_count() <= kLiveCrossings;
    } catch (const Error&) {
    }
    if (small) {
      e.line = identification_line(obj);
      e.named = true;
    }
  }
  return e.named ? &e.line : nullptr;
}

const std::string& KnotNames::name(const SceneObject& obj) {
  Named& e = entry(obj, points_hash(obj.shape));
  e.line = identification_line(obj);
  e.named = true;
  return e.line;
}

}  // namespace s4d
