#include "core/colour_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace s4d {

namespace {

Vec3f lerp_table(const Vec3f* table, int n, double t) {
  const double x = t * (n - 1);
  const int i = std::min(static_cast<int>(x), n - 2);
  const float f = static_cast<float>(x - i);
  return table[i] * (1.0f - f) + table[i + 1] * f;
}

}  // namespace

Vec3f map_colour(ColourMap map, double t) {
  if (std::isnan(t)) return {0.6f, 0.6f, 0.6f};
  t = std::clamp(t, 0.0, 1.0);
  switch (map) {
    case ColourMap::kCoolWarm: {
      static const std::array<Vec3f, 5> table{
          Vec3f{0.230f, 0.299f, 0.754f}, Vec3f{0.552f, 0.690f, 0.996f}, Vec3f{0.866f, 0.866f, 0.866f},
          Vec3f{0.956f, 0.604f, 0.486f}, Vec3f{0.706f, 0.016f, 0.150f}};
      return lerp_table(table.data(), static_cast<int>(table.size()), t);
    }
    case ColourMap::kRainbow: {
      static const std::array<Vec3f, 5> table{
          Vec3f{0.10f, 0.20f, 0.95f}, Vec3f{0.05f, 0.80f, 0.90f}, Vec3f{0.20f, 0.85f, 0.25f},
          Vec3f{0.98f, 0.85f, 0.10f}, Vec3f{0.92f, 0.12f, 0.10f}};
      return lerp_table(table.data(), static_cast<int>(table.size()), t);
    }
    case ColourMap::kGrey:
      return {0.78f, 0.76f, 0.72f};
  }
  return {0.6f, 0.6f, 0.6f};
}

std::optional<ColourMap> parse_colour_map(std::string_view name) {
  if (name == "coolwarm") return ColourMap::kCoolWarm;
  if (name == "rainbow") return ColourMap::kRainbow;
  if (name == "grey" || name == "gray" || name == "none") return ColourMap::kGrey;
  return std::nullopt;
}

std::string_view colour_map_name(ColourMap map) {
  switch (map) {
    case ColourMap::kCoolWarm: return "coolwarm";
    case ColourMap::kRainbow: return "rainbow";
    case ColourMap::kGrey: return "grey";
  }
  return "grey";
}

}  // namespace s4d
