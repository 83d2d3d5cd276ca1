// Geomview OFF meshes: OFF (R^3), 4OFF (R^4 here — not Geomview's homogeneous 3D) and nOFF
// (dimension on the next token), with the optional ST/C/N prefixes. Polygons are fan-triangulated.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "shape/shape.hpp"
#include "shape/surface.hpp"

namespace s4d {

// Reads an OFF-family file into a Surface<3> or Surface<4> chosen by its header.
// Malformed input throws ParseError("file:line: message").
Shape read_off(const std::filesystem::path& path);
Shape parse_off(std::string_view text, const std::string& origin);
// Same, but the file must hold a surface of exactly that dimension.
Surface<3> read_off3(const std::filesystem::path& path);
Surface<4> read_off4(const std::filesystem::path& path);

// "OFF" for D = 3, "4OFF" for D = 4; coordinates are written so they read back bit-exact, and the
// grid layout (if any) is kept in a "#! grid" line that read_off understands.
template <int D>
std::string format_off(const Surface<D>& surface);
template <int D>
void write_off(const Surface<D>& surface, const std::filesystem::path& path);

}  // namespace s4d
