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

// Lifts any shape to R^4 (w = 0 for 3D input): the renderer and the 4D tools work in R^4.
Curve<4> lift_to_4d(const Curve<3>& c);
Surface<4> lift_to_4d(const Surface<3>& s);

}  // namespace s4d
