// Frame<D>: an orientation R in SO(D) of the viewer. A world point p has view coordinates
// q = R^T p; the depth is w = q_{D-1} (larger = nearer the viewer). The shadow is (q_0 .. q_{D-2})
// (orthographic, the default) or, seen from an eye at distance d along the depth axis, that times
// d / (d - w) (perspective, as KnotPlot and Meshview offer): the hyperplane w = 0 keeps its size,
// nearer is larger. Every shadow of the program is made by shadow()/project() and undone by lift().
#pragma once
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.hpp"

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
  Vec<D - 1> shadow(const Vec<D>& p) const { return project(to_view(p)); }
  double depth(const Vec<D>& p) const { return r_.col(D - 1).dot(p); }

  // The eye's distance d along the depth axis, 0 for the orthographic shadow.
  double perspective() const { return eye_; }
  bool is_perspective() const { return eye_ > 0; }
  // d must be finite, > 0 and at most kMaxPerspective (far beyond that the picture is the
  // orthographic one); otherwise an Error with the sentence of perspective_error.
  void set_perspective(double d) {
    if (const std::string e = perspective_error(d); !e.empty()) throw Error(e);
    eye_ = d;
  }
  void set_orthographic() { eye_ = 0; }
  static constexpr double kMaxPerspective = 1e6;  // scene units
  // Points this close to the eye plane, or behind it, are drawn as if at this fraction of d in
  // front of it: clamped, never infinite, and still undone exactly by lift().
  static constexpr double kNearestEye = 1e-2;
  static std::string perspective_error(double d) {
    // %g: a distance of 1e308 is said in a few characters, not three hundred digits.
    const auto said = [](double v) {
      char text[32];
      std::snprintf(text, sizeof text, "%g", v);
      return std::string(text);
    };
    if (std::isnan(d)) return "the perspective distance is not a number";
    if (!(d > 0)) return "the perspective distance must be > 0 (the 4D eye sits at w = d), not " + said(d);
    if (!(d <= kMaxPerspective))
      return "the perspective distance must be at most " + said(kMaxPerspective) +
             " (further away it is the orthographic shadow), not " + said(d);
    return {};
  }

  // How much a point at depth w is magnified in the shadow (1 orthographic).
  double magnification(double w) const { return magnification(eye_, w); }
  // The same for an eye at distance `eye` (<= 0: orthographic), for code that keeps only that.
  static double magnification(double eye, double w) { return eye > 0 ? eye / eye_gap(eye, w) : 1.0; }
  // The shadow of a point in view coordinates, and the point at depth w whose shadow is s.
  Vec<D - 1> project(const Vec<D>& q) const {
    if (eye_ > 0) return q.template head<D - 1>() * (eye_ / eye_gap(q[D - 1]));
    return q.template head<D - 1>();
  }
  Vec<D> lift(const Vec<D - 1>& s, double w) const {
    Vec<D> q;
    q.template head<D - 1>() = eye_ > 0 ? Vec<D - 1>(s * (eye_gap(w) / eye_)) : s;
    q[D - 1] = w;
    return q;
  }
  // The shadow of the ball of radius r about the view point q lies within this distance of
  // project(q) (r itself when orthographic): framing a ball of R^4 frames its shadow.
  double shadow_radius(const Vec<D>& q, double r) const {
    if (eye_ <= 0) return r;
    const double near = magnification(q[D - 1] + r);  // the largest magnification over the ball
    return r * near + q.template head<D - 1>().norm() * (near - magnification(q[D - 1]));
  }
  // The depth at a point of a flat piece of the shadow (a segment or triangle of a mesh) given by
  // its weights b in the shadow and its corners' depths: 1/(d - w) is affine in the shadow
  // (perspective-correct interpolation), w itself when orthographic.
  template <std::size_t N>
  double depth_at(const std::array<double, N>& b, const std::array<double, N>& w) const {
    double sum = 0;
    if (eye_ <= 0) {
      for (std::size_t i = 0; i < N; ++i) sum += b[i] * w[i];
      return sum;
    }
    for (std::size_t i = 0; i < N; ++i) sum += b[i] / eye_gap(w[i]);
    return sum > 0 ? eye_ - 1 / sum : eye_ * (1 - kNearestEye);  // past the eye: clamped
  }
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
  // The distance from the eye's hyperplane, clamped (see kNearestEye).
  double eye_gap(double w) const { return eye_gap(eye_, w); }
  static double eye_gap(double eye, double w) {
    const double g = eye - w;
    return g >= kNearestEye * eye ? g : kNearestEye * eye;  // NaN w: clamped too
  }

  Mat<D> r_;  // D × D, columns are the view axes in world coordinates
  double eye_ = 0;  // perspective eye distance along the depth axis; 0 orthographic
};

// Applies rotations in order, each in degrees (the CLI's and scene files' "xw=30,yz=10").
template <int D>
void apply_rotations(Frame<D>& frame, const std::vector<PlaneAngle>& rotations) {
  for (const auto& r : rotations) frame.rotate(r.plane, r.degrees * (3.14159265358979323846 / 180.0));
}

}  // namespace s4d
