#include "core/plane.hpp"

#include <cmath>
#include <cstdlib>

#include "core/error.hpp"

namespace s4d {

namespace {
int axis_index(char c) {
  for (int i = 0; i < 4; ++i)
    if (kAxisNames[i] == c) return i;
  return -1;
}
}  // namespace

std::optional<Plane> parse_plane(std::string_view name, int dim) {
  if (name.size() != 2) return std::nullopt;
  int a = axis_index(name[0]);
  int b = axis_index(name[1]);
  if (a < 0 || b < 0 || a == b || a >= dim || b >= dim) return std::nullopt;
  if (a > b) std::swap(a, b);
  return Plane{a, b};
}

std::string plane_name(Plane p) { return {kAxisNames[p.a], kAxisNames[p.b]}; }

std::vector<PlaneAngle> parse_rotation_list(std::string_view text, int dim) {
  std::vector<PlaneAngle> out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find_first_of(", ;", pos);
    const std::string item(text.substr(pos, end == std::string_view::npos ? text.npos : end - pos));
    pos = end == std::string_view::npos ? text.size() : end + 1;
    if (item.empty()) continue;
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos)
      throw Error("rotation '" + item + "' should look like xw=30 (plane=degrees)");
    const auto plane = parse_plane(std::string_view(item).substr(0, eq), dim);
    if (!plane)
      throw Error("unknown rotation plane '" + item.substr(0, eq) + "' in R^" + std::to_string(dim) +
                  " (use two distinct axes of " + std::string(kAxisNames.data(), dim) + ", e.g. xw)");
    const std::string value = item.substr(eq + 1);
    char* stop = nullptr;
    const double deg = std::strtod(value.c_str(), &stop);
    if (value.empty() || *stop != '\0' || !std::isfinite(deg))
      throw Error("rotation angle '" + value + "' for plane " + plane_name(*plane) +
                  " is not a finite number of degrees");
    // "wx=30" turns the other way round from "xw=30".
    const bool swapped = kAxisNames[plane->a] != item[0];
    out.push_back({*plane, swapped ? -deg : deg});
  }
  return out;
}

std::vector<Plane> all_planes(int dim) {
  std::vector<Plane> out;
  for (int a = 0; a < dim; ++a)
    for (int b = a + 1; b < dim; ++b) out.push_back({a, b});
  return out;
}

}  // namespace s4d
