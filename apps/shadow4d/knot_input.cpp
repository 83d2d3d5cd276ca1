// The knot commands' input: curves gathered from a file or scene, and a view given as rotations.
#include "knot_input.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "core/plane.hpp"
#include "io/scene.hpp"
#include "knots/knot_curve.hpp"

namespace s4d::cli {

Curve<3> load_knot_curve(const std::string& spec) {
  const Scene scene = load_scene_or_object(spec);
  Curve<3> all;
  for (const SceneObject& obj : scene.objects) {
    if (is_surface(obj.shape)) continue;
    const std::string where = scene.objects.size() > 1 ? spec + ", object '" + obj.name + "'" : spec;
    for (auto& p : knot_curve_of(obj.shape, where).components) all.components.push_back(std::move(p));
  }
  if (all.components.empty()) {
    if (scene.objects.size() == 1) knot_curve_of(scene.objects[0].shape, spec);  // says what it is
    throw Error(spec + " has no curve; a knot is a closed curve");
  }
  return all;
}

Frame<3> parse_view(const std::string& text) {
  Frame<3> f;
  if (text.empty()) return f;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw Error("bad rotation '" + item + "', expected e.g. xz=30");
    const auto plane = parse_plane(item.substr(0, eq), 3);
    if (!plane) throw Error("unknown rotation plane '" + item.substr(0, eq) + "' (use xy, xz or yz)");
    double deg = 0;
    try {
      std::size_t used = 0;
      deg = std::stod(item.substr(eq + 1), &used);
      if (used != item.size() - eq - 1 || !std::isfinite(deg)) throw std::invalid_argument("angle");
    } catch (const std::exception&) {
      throw Error("bad angle in '" + item + "'");
    }
    f.rotate(*plane, deg * std::numbers::pi / 180);
  }
  return f;
}
}  // namespace s4d::cli
