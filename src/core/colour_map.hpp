// Colour maps for depth coding. The paper's convention: blue = far (in w, or z for knots), red = near.
#pragma once
#include <string_view>
#include <optional>

#include "core/vec.hpp"

namespace s4d {

enum class ColourMap {
  kCoolWarm,  // diverging blue -> light grey -> red (Moreland); reads well under lighting
  kRainbow,   // blue -> cyan -> green -> yellow -> red, as in many 4D figures
  kGrey,      // no depth coding: a single neutral colour
};

// t in [0,1]: 0 = far (blue), 1 = near (red). Values outside are clamped; NaN gives grey.
Vec3f map_colour(ColourMap map, double t);

std::optional<ColourMap> parse_colour_map(std::string_view name);
std::string_view colour_map_name(ColourMap map);

// Maps depth d to [0,1] over [lo, hi] (hi > lo); a degenerate range maps to 0.5.
inline double normalise_depth(double d, double lo, double hi) {
  return hi > lo ? (d - lo) / (hi - lo) : 0.5;
}

}  // namespace s4d
