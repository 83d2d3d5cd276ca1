// Small shapes built inside the render tests, so they depend on no generator: a Clifford torus,
// a trefoil, a UV sphere, a square tilted into w, crossing squares, and image comparison helpers.
#pragma once
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <utility>

#include "io/image.hpp"
#include "io/scene.hpp"

namespace s4d::test {

inline constexpr double kPi = std::numbers::pi;

// Triangles of a rows × cols grid, wrapped as asked, counter-clockwise in (i, j).
inline std::vector<Triangle> grid_tris(int rows, int cols, bool wrap_i, bool wrap_j) {
  std::vector<Triangle> t;
  const int ri = wrap_i ? rows : rows - 1, cj = wrap_j ? cols : cols - 1;
  for (int i = 0; i < ri; ++i)
    for (int j = 0; j < cj; ++j) {
      const int a = i * cols + j, b = ((i + 1) % rows) * cols + j;
      const int c = ((i + 1) % rows) * cols + (j + 1) % cols, d = i * cols + (j + 1) % cols;
      t.push_back({a, b, c});
      t.push_back({a, c, d});
    }
  return t;
}

// (cos u, sin u, cos v, sin v) / sqrt 2: the flat torus on the unit 3-sphere.
inline Surface<4> clifford_torus(int n = 48) {
  Surface<4> s;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / n;
      s.vertices.push_back(Vec4(std::cos(u), std::sin(u), std::cos(v), std::sin(v)) / std::sqrt(2.0));
    }
  s.triangles = grid_tris(n, n, true, true);
  s.grid = Grid{n, n, true, true};
  return s;
}

// The standard trefoil (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t), scaled by `scale`.
inline Curve<3> trefoil(int n = 200, double scale = 0.3) {
  Polyline<3> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    p.points.push_back(scale * Vec3(std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t),
                                    -std::sin(3 * t)));
  }
  Curve<3> c;
  c.components.push_back(p);
  return c;
}

// Unit sphere, latitude rows × longitude cols, poles included as rows of coincident points.
inline Surface<3> uv_sphere(int rows = 24, int cols = 32) {
  Surface<3> s;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const double th = kPi * i / (rows - 1), ph = 2 * kPi * j / cols;
      s.vertices.emplace_back(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
    }
  // Grid (i, j) counter-clockwise in (theta, phi) faces outward since theta runs from +z down.
  s.triangles = grid_tris(rows, cols, false, true);
  return s;
}

// The square [-1,1]^2 in the xy plane, tilted so that w = slope · x: its right side is nearer in 4D.
// `bend` lifts it into a parabolic trough z = bend (1 - y^2), curved along y only.
inline Surface<4> tilted_square(double slope = 0.5, int n = 16, double bend = 0) {
  Surface<4> s;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -1 + 2.0 * j / (n - 1), y = -1 + 2.0 * i / (n - 1);
      s.vertices.emplace_back(x, y, bend * (1 - y * y), slope * x);
    }
  s.triangles = grid_tris(n, n, false, false);
  return s;
}

// Two unit squares in the complementary planes xy and zw, crossing at one interior point (the
// origin): a surface with one true 4D self-intersection. Turned so that no edge is axis-aligned.
inline Surface<4> crossing_planes() {
  Surface<4> s;
  const double a = 0.013, b = 0.021;
  for (const auto& [u, v] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
    s.vertices.push_back(Vec4(u - a, v + b, 0, 0));
  for (const auto& [u, v] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
    s.vertices.push_back(Vec4(0, 0, u + b, v - a));
  s.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  return s;
}

// Two unit squares whose shadows cross along the x axis without meeting in R^4: sheet A in the
// plane z = 0 at w = w_a, sheet B in the plane y = 0 at w = w_b, shifted along x so that the
// crossing ends on A's border at one end and on B's at the other. Triangles 0-1 are A's, 2-3 B's.
inline Surface<4> sheets_apart_in_w(double w_a = 0.5, double w_b = -0.5) {
  Surface<4> s;
  for (const auto& [u, v] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
    s.vertices.push_back(Vec4(u, v, 0, w_a));
  for (const auto& [u, v] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
    s.vertices.push_back(Vec4(u + 0.2, 0, v, w_b));
  s.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  return s;
}

// The two sheets of `s` (vertices 0-3 and 4-7 of a two-square surface) as surfaces of their own.
inline std::pair<Surface<4>, Surface<4>> split_squares(const Surface<4>& s) {
  Surface<4> a, b;
  a.vertices.assign(s.vertices.begin(), s.vertices.begin() + 4);
  b.vertices.assign(s.vertices.begin() + 4, s.vertices.begin() + 8);
  a.triangles = b.triangles = {{0, 1, 2}, {0, 2, 3}};
  return {a, b};
}

// A square of R^3 facing +z at height z, centred at (cx, 0), half-width h, in one plain colour.
inline SceneObject flat_square(double cx, double z, double h, const Vec3f& colour, const std::string& name) {
  Surface<3> s;
  for (const auto& [u, v] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
    s.vertices.emplace_back(cx + h * u, h * v, z);
  s.triangles = {{0, 1, 2}, {0, 2, 3}};
  SceneObject o;
  o.name = name;
  o.shape = s;
  o.colour = colour;
  return o;
}

inline Scene scene_of(Shape shape) {
  Scene sc;
  SceneObject o;
  o.name = "object";
  o.shape = std::move(shape);
  sc.objects.push_back(std::move(o));
  return sc;
}

// Fraction of pixels that differ from the scene background by more than a few counts.
inline double coverage(const Image& img, const Vec3f& background) {
  std::size_t hit = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const auto* p = img.pixel(x, y);
      for (int k = 0; k < 3; ++k)
        if (std::abs(p[k] - std::lround(background[k] * 255)) > 6) {
          ++hit;
          break;
        }
    }
  return static_cast<double>(hit) / (static_cast<double>(img.width) * img.height);
}

// Fraction of pixels whose largest channel difference exceeds `tolerance` counts.
inline double differing_fraction(const Image& a, const Image& b, int tolerance) {
  if (a.width != b.width || a.height != b.height) return 1.0;
  std::size_t diff = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4)
    for (int k = 0; k < 4; ++k)
      if (std::abs(int(a.rgba[i + k]) - int(b.rgba[i + k])) > tolerance) {
        ++diff;
        break;
      }
  return static_cast<double>(diff) / (static_cast<double>(a.width) * a.height);
}

}  // namespace s4d::test
