// Geomview VECT polylines: VECT (R^3), 4VECT (R^4 here) and nVECT (dimension on the next token).
// A negative vertex count marks a closed polyline; per-polyline colours are read and ignored.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "shape/curve.hpp"
#include "shape/shape.hpp"

namespace s4d {

// Reads a VECT-family file into a Curve<3> or Curve<4> chosen by its header.
// Malformed input throws ParseError("file:line: message").
Shape read_vect(const std::filesystem::path& path);
Shape parse_vect(std::string_view text, const std::string& origin);

// "VECT" for D = 3, "4VECT" for D = 4, no colours; coordinates read back bit-exact.
template <int D>
std::string format_vect(const Curve<D>& curve);
template <int D>
void write_vect(const Curve<D>& curve, const std::filesystem::path& path);

}  // namespace s4d
