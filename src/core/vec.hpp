// Fixed-size vectors and matrices of R^D (Eigen), the one numeric vocabulary of the engine.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <span>

namespace s4d {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;
template <int D>
using Mat = Eigen::Matrix<double, D, D>;

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;
using Vec4 = Vec<4>;
using Vec3f = Eigen::Vector3f;

// True when every coordinate is finite (no NaN, no inf).
template <typename Derived>
bool all_finite(const Eigen::MatrixBase<Derived>& v) {
  return v.allFinite();
}

// The same for a whole array of points, in one branch-free pass: 0·x is 0 for a finite x and NaN
// otherwise, so the sum stays 0 only if every coordinate is finite (about a quarter of the cost
// of testing point by point).
template <int D>
bool all_finite(std::span<const Vec<D>> points) {
  Vec<D> zero = Vec<D>::Zero();
  for (const Vec<D>& p : points) zero += 0.0 * p;
  return (zero.array() == 0.0).all();
}

}  // namespace s4d
