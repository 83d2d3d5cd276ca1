// Curves shared by the physics and interact tests: the closure of a two-strand braid drawn round a
// circle, whose crossings can be turned over one by one (an unknot that looks knotted, a trefoil).
#pragma once
#include <cmath>
#include <numbers>
#include <vector>

#include "shape/curve.hpp"

namespace s4d::test {

// The closure of a two-strand braid with q crossings drawn round a circle of radius R (the torus
// knot T(2, q) when every crossing is `standard`): crossing c has the strand of its first pass on
// top in the standard way when standard[c], turned over otherwise. Its depth is ±h at crossings.
inline Curve<3> braid_closure(const std::vector<bool>& standard, int n, double R = 2, double r = 0.6, double h = 0.35) {
  const int q = static_cast<int>(standard.size());
  std::vector<double> sigma(2 * static_cast<std::size_t>(q));
  for (int c = 0; c < q; ++c) {
    sigma[static_cast<std::size_t>(c)] = (standard[static_cast<std::size_t>(c)] ? 1 : -1) * (c % 2 == 0 ? 1 : -1);
    sigma[static_cast<std::size_t>(c + q)] = -sigma[static_cast<std::size_t>(c)];
  }
  Polyline<3> p;
  for (int i = 0; i < n; ++i) {
    const double u = 2.0 * i / n;
    const double phi = 2 * std::numbers::pi * u, theta = q * std::numbers::pi * u;
    // Between crossing parameters u_k = (k + 1/2) / q the depth eases from sigma_k to sigma_k+1.
    const double k_real = u * q - 0.5;
    const int k = static_cast<int>(std::floor(k_real));
    const double frac = k_real - k;
    const double s0 = sigma[static_cast<std::size_t>((k + 2 * q) % (2 * q))];
    const double s1 = sigma[static_cast<std::size_t>((k + 1 + 2 * q) % (2 * q))];
    const double s = s0 + (s1 - s0) * 0.5 * (1 - std::cos(std::numbers::pi * frac));
    const double rho = R + r * std::cos(theta);
    p.points.emplace_back(rho * std::cos(phi), rho * std::sin(phi), h * s);
  }
  Curve<3> c;
  c.components.push_back(std::move(p));
  return c;
}

}  // namespace s4d::test
