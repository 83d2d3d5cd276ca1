// Ribbon sweeps (see ribbons.hpp).
#include "shape/ribbons.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "shape/grid_mesh.hpp"
#include "shape/knotted_arc.hpp"
#include "shape/polyline_ops.hpp"

namespace s4d {

namespace {
void check_strip(double width, int m) {
  if (!(width > 0) || !std::isfinite(width)) throw Error("a ribbon's width must be positive");
  if (m < 2) throw Error("a ribbon needs at least 2 samples across");
}
// Offset of column j across a strip of the given width, from -width/2 to +width/2.
double across(int j, int m, double width) { return width * (static_cast<double>(j) / (m - 1) - 0.5); }
}  // namespace

Surface<3> ribbon_along(const std::vector<Vec3>& core, bool closed,
                        const std::vector<Vec3>& normals, double width, int m) {
  check_strip(width, m);
  if (normals.size() != core.size()) throw Error("a ribbon needs one normal per core point");
  Surface<3> s;
  s.grid = Grid{static_cast<int>(core.size()), m, closed, false};
  s.vertices.reserve(core.size() * m);
  for (std::size_t i = 0; i < core.size(); ++i)
    for (int j = 0; j < m; ++j) s.vertices.push_back(core[i] + across(j, m, width) * normals[i]);
  s.triangles = grid_triangles(*s.grid);
  return s;
}

Surface<3> trefoil_ribbon(int n, int m, double width) {
  if (width > kMaxTrefoilRibbonWidth)
    throw Error("trefoil-ribbon: width " + std::to_string(width) + " is wider than " +
                std::to_string(kMaxTrefoilRibbonWidth) + ", where the strands would touch");
  const std::vector<Vec3> core = trefoil_arc(n, true);
  const std::vector<Vec3> normals = rotation_minimising_normals(core, false, Vec3(0, 1, 0));
  return ribbon_along(core, false, normals, width, m);
}

Surface<4> ribbon_loop(const Vec4& centre, const Vec4& e1, const Vec4& e2, const Vec4& across_dir,
                       double radius, double width, int n, int m) {
  check_strip(width, m);
  if (n < 3) throw Error("a ribbon loop needs at least 3 samples around");
  if (!(radius > width / 2)) throw Error("a ribbon loop's radius must exceed half its width");
  Surface<4> s;
  s.grid = Grid{n, m, true, false};
  s.vertices.reserve(static_cast<std::size_t>(n) * m);
  for (int i = 0; i < n; ++i) {
    const double u = 2.0 * std::numbers::pi * i / n;
    const Vec4 c = centre + radius * (std::cos(u) * e1 + std::sin(u) * e2);
    for (int j = 0; j < m; ++j) s.vertices.push_back(c + across(j, m, width) * across_dir);
  }
  s.triangles = grid_triangles(*s.grid);
  return s;
}

Surface<4> ribbon_loop(int n, int m, double radius, double width) {
  return ribbon_loop(Vec4::Zero(), Vec4::UnitX(), Vec4::UnitY(), Vec4::UnitZ(), radius, width, n,
                     m);
}

}  // namespace s4d
