// Fixed-size vectors and matrices of R^D (Eigen), the one numeric vocabulary of the engine.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

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

}  // namespace s4d
