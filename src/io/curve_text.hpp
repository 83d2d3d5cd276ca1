// Plain-text curves: one point per line ("x y z" or "x y z w"), '#' comments, a blank line between
// components. Components are closed (knots) unless a "#! open" line comes before them.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "shape/curve.hpp"
#include "shape/shape.hpp"

namespace s4d {

// Reads a Curve<3> or Curve<4>; the dimension comes from the first data line and every other line
// must match. Malformed input throws ParseError("file:line: message").
Shape read_curve_text(const std::filesystem::path& path);
Shape parse_curve_text(std::string_view text, const std::string& origin);

// Writes one point per line with bit-exact coordinates and "#! open" before open components.
template <int D>
std::string format_curve_text(const Curve<D>& curve);
template <int D>
void write_curve_text(const Curve<D>& curve, const std::filesystem::path& path);

}  // namespace s4d
