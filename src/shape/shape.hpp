// Shape: any object the app shows. Curves live in R^3 (knots) or R^4; surfaces in R^3 or R^4.
#pragma once
#include <string>
#include <variant>

#include "shape/curve.hpp"
#include "shape/surface.hpp"

namespace s4d {

using Shape = std::variant<Curve<3>, Curve<4>, Surface<3>, Surface<4>>;

// Ambient dimension of a shape (3 or 4).
inline int ambient_dim(const Shape& s) {
  return std::visit([](const auto& x) { return std::decay_t<decltype(x)>::kDim; }, s);
}
inline bool is_surface(const Shape& s) {
  return std::holds_alternative<Surface<3>>(s) || std::holds_alternative<Surface<4>>(s);
}

// Calls f(p) with every point of a curve (its components' points in order) or a surface (its
// vertices), p a Vec<D> of the shape's own dimension, writable when the shape is: the order a
// World numbers a body's vertices in.
template <class S, class F>
  requires requires(S& s) { s.components; } || requires(S& s) { s.vertices; }
void for_each_point(S& s, F&& f) {
  if constexpr (requires { s.triangles; }) {
    for (auto& p : s.vertices) f(p);
  } else {
    for (auto& c : s.components)
      for (auto& p : c.points) f(p);
  }
}
template <class F>
void for_each_point(Shape& shape, F&& f) {
  std::visit([&](auto& s) { for_each_point(s, f); }, shape);
}
template <class F>
void for_each_point(const Shape& shape, F&& f) {
  std::visit([&](const auto& s) { for_each_point(s, f); }, shape);
}

// How many points for_each_point visits.
inline int point_count(const Shape& shape) {
  int n = 0;
  for_each_point(shape, [&n](const auto&) { ++n; });
  return n;
}

// Lifts any shape to R^4 (w = 0 for 3D input): the renderer and the 4D tools work in R^4.
Curve<4> lift_to_4d(const Curve<3>& c);
Surface<4> lift_to_4d(const Surface<3>& s);

}  // namespace s4d
