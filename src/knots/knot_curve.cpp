#include "knots/knot_curve.hpp"

#include <cmath>

#include "core/error.hpp"

namespace s4d {

Curve<3> knot_curve_of(const Shape& shape, const std::string& where) {
  if (const auto* c3 = std::get_if<Curve<3>>(&shape)) return *c3;
  if (const auto* c4 = std::get_if<Curve<4>>(&shape)) {
    Curve<3> c;
    for (const auto& pl : c4->components) {
      Polyline<3> p;
      p.closed = pl.closed;
      for (const auto& q : pl.points) {
        if (std::abs(q.w()) > 1e-12)
          throw Error(where + ": a curve of R^4 off the w = 0 space is not a knot of R^3");
        p.points.push_back(q.head<3>());
      }
      c.components.push_back(std::move(p));
    }
    return c;
  }
  throw Error(where + " is a surface; a knot is a closed curve");
}

}  // namespace s4d
