// Parametric knots (see knot_curves.hpp).
#include "shape/knot_curves.hpp"

#include <cmath>
#include <numbers>
#include <numeric>
#include <string>

#include "core/error.hpp"

namespace s4d {

Curve<3> torus_knot(int p, int q, int n, double R, double r) {
  if (p < 1) throw Error("torus-knot: p must be at least 1 (got " + std::to_string(p) + ")");
  if (n < 3) throw Error("torus-knot: needs at least 3 points per component");
  if (!(R > 0 && r > 0 && r < R))
    throw Error("torus-knot: the tube radius r must be positive and smaller than R, or the torus "
                "(and the knot on it) would cross itself");
  const int g = std::gcd(p, std::abs(q));
  const int pp = p / g, qq = q / g;
  const double two_pi = 2.0 * std::numbers::pi;
  Curve<3> c;
  for (int k = 0; k < g; ++k) {
    // A (p', q') curve meets each meridian p' times, equally spaced; g copies shifted by a
    // g-th of that spacing fill the gaps without ever meeting.
    const double phase = two_pi * k / (static_cast<double>(g) * pp);
    Polyline<3> line;
    line.closed = true;
    line.points.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const double t = two_pi * i / n;
      const double around = pp * t, tube = qq * t + phase;
      const double rad = R + r * std::cos(tube);
      line.points.emplace_back(rad * std::cos(around), rad * std::sin(around), r * std::sin(tube));
    }
    c.components.push_back(std::move(line));
  }
  return c;
}

Curve<3> figure_eight_knot(int n) {
  if (n < 8) throw Error("figure-eight: needs at least 8 points");
  Polyline<3> line;
  line.closed = true;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    const double rad = 2.0 + std::cos(2 * t);
    line.points.emplace_back(rad * std::cos(3 * t), rad * std::sin(3 * t), std::sin(4 * t));
  }
  Curve<3> c;
  c.components.push_back(std::move(line));
  return c;
}

Vec3 trefoil_point(double t) {
  return {std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t)};
}

Vec3 trefoil_derivative(double t) {
  return {std::cos(t) + 4 * std::cos(2 * t), -std::sin(t) + 4 * std::sin(2 * t),
          -3 * std::cos(3 * t)};
}

}  // namespace s4d
