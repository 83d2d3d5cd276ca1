// Cloth, Clifford torus and spheres (see surfaces_4d.hpp).
#include "shape/surfaces_4d.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "shape/grid_mesh.hpp"

namespace s4d {

Surface<4> cloth(int n, double size) {
  if (n < 2) throw Error("cloth: needs at least 2 vertices per side");
  if (!(size > 0) || !std::isfinite(size)) throw Error("cloth: size must be positive");
  Surface<4> s;
  s.grid = Grid{n, n, false, false};
  s.vertices.reserve(static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      s.vertices.emplace_back(size * (static_cast<double>(i) / (n - 1) - 0.5),
                              size * (static_cast<double>(j) / (n - 1) - 0.5), 0.0, 0.0);
  s.triangles = grid_triangles(*s.grid);
  return s;
}

Surface<4> clifford_torus(int n, int m) {
  if (n < 3 || m < 3) throw Error("clifford-torus: needs at least 3 samples in each direction");
  Surface<4> s;
  s.grid = Grid{n, m, true, true};
  s.vertices.reserve(static_cast<std::size_t>(n) * m);
  for (int i = 0; i < n; ++i) {
    const double u = 2.0 * std::numbers::pi * i / n;
    for (int j = 0; j < m; ++j) {
      const double v = 2.0 * std::numbers::pi * j / m;
      s.vertices.emplace_back(std::cos(u), std::sin(u), std::cos(v), std::sin(v));
    }
  }
  s.triangles = grid_triangles(*s.grid);
  return s;
}

template <int D>
Surface<D> uv_sphere(int n, double radius, const Vec<D>& centre) {
  static_assert(D >= 3, "a round 2-sphere needs three coordinates");
  if (n < 3) throw Error("sphere: needs at least 3 samples around");
  if (!(radius > 0) || !std::isfinite(radius)) throw Error("sphere: radius must be positive");
  const int bands = std::max(2, n / 2);
  Surface<D> s;
  auto at = [&](double theta, double phi) {  // theta from the north pole, phi around z
    Vec<D> p = centre;
    p[0] += radius * std::sin(theta) * std::cos(phi);
    p[1] += radius * std::sin(theta) * std::sin(phi);
    p[2] += radius * std::cos(theta);
    return p;
  };
  const int north = 0;
  s.vertices.push_back(at(0, 0));
  for (int b = 1; b < bands; ++b)
    for (int j = 0; j < n; ++j)
      s.vertices.push_back(at(std::numbers::pi * b / bands, 2.0 * std::numbers::pi * j / n));
  const int south = static_cast<int>(s.vertices.size());
  s.vertices.push_back(at(std::numbers::pi, 0));
  auto ring = [&](int b, int j) { return 1 + (b - 1) * n + (j % n); };  // b in [1, bands)
  // Outward orientation: seen from outside, (down the meridian, along increasing phi) is
  // counter-clockwise.
  for (int j = 0; j < n; ++j) s.triangles.push_back({north, ring(1, j), ring(1, j + 1)});
  for (int b = 1; b + 1 < bands; ++b)
    for (int j = 0; j < n; ++j) {
      s.triangles.push_back({ring(b, j), ring(b + 1, j), ring(b + 1, j + 1)});
      s.triangles.push_back({ring(b, j), ring(b + 1, j + 1), ring(b, j + 1)});
    }
  for (int j = 0; j < n; ++j) s.triangles.push_back({ring(bands - 1, j), south, ring(bands - 1, j + 1)});
  return s;
}

template Surface<3> uv_sphere<3>(int, double, const Vec<3>&);
template Surface<4> uv_sphere<4>(int, double, const Vec<4>&);

}  // namespace s4d
