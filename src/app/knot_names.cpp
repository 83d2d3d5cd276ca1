#include "app/knot_names.hpp"

#include <algorithm>
#include <functional>
#include <variant>

#include "core/error.hpp"
#include "knots/knot_curve.hpp"
#include "knots/knot_naming.hpp"

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
    // Live on the UI thread: the fast naming, which says what it skipped (the Knot panel goes on).
    NamingOptions fast;
    fast.fast = true;
    return "knot: " + name_knot(knot_curve_of(obj.shape, "'" + obj.name + "'"), fast).headline();
  } catch (const Error& e) {
    return e.what();
  }
}
}  // namespace

bool KnotNames::nameable(const SceneObject& obj) { return !is_surface(obj.shape); }

KnotNames::Named& KnotNames::entry(const SceneObject& obj, bool& fresh) {
  const std::size_t hash = points_hash(obj.shape);
  auto it = std::find_if(named_.begin(), named_.end(),
                         [&](const Named& n) { return n.object == obj.name; });
  fresh = it == named_.end() || it->points_hash != hash;
  if (it == named_.end()) return named_.emplace_back(Named{obj.name, hash, false, {}});
  if (fresh) *it = Named{obj.name, hash, false, {}};
  return *it;
}

const std::string* KnotNames::live(const SceneObject& obj) {
  bool fresh = false;
  Named& e = entry(obj, fresh);
  if (fresh) {
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
  bool fresh = false;
  Named& e = entry(obj, fresh);
  e.line = identification_line(obj);
  e.named = true;
  return e.line;
}

}  // namespace s4d
