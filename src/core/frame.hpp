// Frame<D>: an orientation R in SO(D) of the viewer. A world point p has view coordinates
// q = R^T p; the shadow is (q_0 .. q_{D-2}) and the depth is q_{D-1} (larger = nearer the viewer).
#pragma once
#include <cmath>
#include <vector>

#include "core/plane.hpp"
#include "core/vec.hpp"

namespace s4d {

template <int D>
class Frame {
 public:
  static_assert(D >= 2, "a frame needs at least two axes");

  Frame() : r_(Mat<D>::Identity()) {}
  // Takes any matrix close to a rotation; it is re-orthonormalised (det forced to +1).
  explicit Frame(const Mat<D>& r) : r_(r) { reorthonormalize(); }

  // Rotates the view by `angle` radians in the view plane `p`: the object appears to turn from
  // axis p.a towards axis p.b. Re-orthonormalises every time, so any number of small
  // incremental rotations (mouse drags) stays in SO(D) to ~1e-15.
  void rotate(Plane p, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    for (int i = 0; i < D; ++i) {
      const double ra = r_(i, p.a), rb = r_(i, p.b);
      r_(i, p.a) = c * ra - s * rb;
      r_(i, p.b) = s * ra + c * rb;
    }
    reorthonormalize();
  }

  const Mat<D>& matrix() const { return r_; }
  Vec<D> to_view(const Vec<D>& p) const { return r_.transpose() * p; }
  Vec<D> to_world(const Vec<D>& q) const { return r_ * q; }
  Vec<D - 1> shadow(const Vec<D>& p) const { return to_view(p).template head<D - 1>(); }
  double depth(const Vec<D>& p) const { return r_.col(D - 1).dot(p); }
  // The world direction the viewer looks along is -axis(D-1); the shadow ray is axis(D-1).
  Vec<D> axis(int i) const { return r_.col(i); }

  // Modified Gram-Schmidt on the columns, then a sign fix so that det = +1.
  void reorthonormalize() {
    for (int j = 0; j < D; ++j) {
      for (int k = 0; k < j; ++k) r_.col(j) -= r_.col(k).dot(r_.col(j)) * r_.col(k);
      const double n = r_.col(j).norm();
      if (!(n > 1e-300) || !std::isfinite(n)) {  // degenerate input: fall back to identity
        r_.setIdentity();
        return;
      }
      r_.col(j) /= n;
    }
    if (r_.determinant() < 0) r_.col(D - 1) *= -1.0;
  }

  // Largest deviation of R^T R from the identity; used by tests and sanity checks.
  double orthonormality_error() const {
    return (r_.transpose() * r_ - Mat<D>::Identity()).cwiseAbs().maxCoeff();
  }

 private:
  Mat<D> r_;  // D × D, columns are the view axes in world coordinates
};

// Applies rotations in order, each in degrees (the CLI's and scene files' "xw=30,yz=10").
template <int D>
void apply_rotations(Frame<D>& frame, const std::vector<PlaneAngle>& rotations) {
  for (const auto& r : rotations) frame.rotate(r.plane, r.degrees * (3.14159265358979323846 / 180.0));
}

}  // namespace s4d
