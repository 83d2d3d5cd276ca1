// Rotation planes of R^D named by their axes ("xy", "xw", ...), as the UI and CLI spell them.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace s4d {

// A coordinate plane spanned by axes a < b (0 = x, 1 = y, 2 = z, 3 = w).
struct Plane {
  int a = 0;
  int b = 1;
  friend bool operator==(const Plane&, const Plane&) = default;
};

inline constexpr std::array<char, 4> kAxisNames{'x', 'y', 'z', 'w'};

// "xw" -> {0,3}; order-insensitive ("wx" is the same plane, with the angle's sign flipped
// by the caller if it cares). Returns nullopt for unknown names or axes >= dim.
std::optional<Plane> parse_plane(std::string_view name, int dim);
std::string plane_name(Plane p);
// A rotation by `degrees` in `plane`, as written on the command line ("xw=30").
struct PlaneAngle {
  Plane plane;
  double degrees = 0;
};
// Parses "xw=30,yz=-10" (also space- or semicolon-separated). Throws s4d::Error naming the bad
// item for unknown planes, missing '=', or non-finite angles.
std::vector<PlaneAngle> parse_rotation_list(std::string_view text, int dim);

// All D(D-1)/2 planes in the order xy, xz, xw, yz, yw, zw (for D = 4).
std::vector<Plane> all_planes(int dim);

}  // namespace s4d
