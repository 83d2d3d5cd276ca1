// Construction of the open trefoil arc (see knotted_arc.hpp). All lengths below are in the
// trefoil's own units (body radius about 3); the result is scaled by kScale at the end.
#include "shape/knotted_arc.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "shape/knot_curves.hpp"
#include "shape/polyline_ops.hpp"

namespace s4d {

namespace {

constexpr double kScale = 0.5;       // body radius ~3 -> ~1.5, comparable to the other objects
constexpr double kCutT = std::numbers::pi / 6;  // a lowest point of the trefoil (z = -1)
constexpr double kGap = 0.3;         // parameter removed on each side of the cut
constexpr double kBodyLift = 1.5;    // height of the body's lowest point above z = 0
constexpr double kLeadInset = 0.5;   // the drops sit this far inside the cut ends, towards the gap
constexpr double kDropTop = 1.1;     // where the straight drop meets the curved join to the body
constexpr double kFloorBend = 0.4;   // radius of the turn from drop to tail
constexpr double kTailEnd = 5.0;     // |x| at the tips of the tails
constexpr int kDense = 4000;         // samples of the body before resampling

// The trefoil turned about z so that it runs along +x at the cut, and lifted so that its
// lowest point is at height kBodyLift.
struct Body {
  double c, s;  // cos/sin of the turn
  Vec3 point(double t) const {
    const Vec3 p = trefoil_point(t);
    return {c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z() + 1.0 + kBodyLift};
  }
  Vec3 direction(double t) const {
    const Vec3 d = trefoil_derivative(t);
    return Vec3(c * d.x() - s * d.y(), s * d.x() + c * d.y(), d.z()).normalized();
  }
};

Body make_body() {
  const Vec3 d = trefoil_derivative(kCutT);
  const double phi = std::atan2(d.y(), d.x());
  return {std::cos(-phi), std::sin(-phi)};
}

// Cubic Hermite from a (unit tangent ta) to b (unit tangent tb), k samples excluding a.
// Points are taken by value: callers pass out.back(), which push_back may reallocate.
void hermite(std::vector<Vec3>& out, Vec3 a, Vec3 ta, Vec3 b, Vec3 tb, int k) {
  const double len = (b - a).norm();
  for (int i = 1; i <= k; ++i) {
    const double u = static_cast<double>(i) / k, u2 = u * u, u3 = u2 * u;
    out.push_back((2 * u3 - 3 * u2 + 1) * a + (u3 - 2 * u2 + u) * len * ta +
                  (-2 * u3 + 3 * u2) * b + (u3 - u2) * len * tb);
  }
}

// Straight segment from a to b, k samples excluding a.
void line(std::vector<Vec3>& out, Vec3 a, Vec3 b, int k) {
  for (int i = 1; i <= k; ++i) out.push_back(a + (b - a) * (static_cast<double>(i) / k));
}

// Quarter circle around `centre` from centre + r*u to centre + r*v, k samples excluding the first.
void quarter(std::vector<Vec3>& out, Vec3 centre, Vec3 u, Vec3 v, double r, int k) {
  for (int i = 1; i <= k; ++i) {
    const double a = 0.5 * std::numbers::pi * i / k;
    out.push_back(centre + r * (std::cos(a) * u + std::sin(a) * v));
  }
}

}  // namespace

std::vector<Vec3> trefoil_arc(int n, bool tails) {
  if (n < 16) throw Error("the trefoil arc needs at least 16 points");
  const Body body = make_body();
  const Vec3 ex(1, 0, 0), ez(0, 0, 1);

  const Vec3 start = body.point(kCutT + kGap), start_dir = body.direction(kCutT + kGap);
  const Vec3 end = body.point(kCutT + 2 * std::numbers::pi - kGap);
  const Vec3 end_dir = body.direction(kCutT + 2 * std::numbers::pi - kGap);
  // The arc runs +x through the cut, so the start lies on the +x side of the gap and the end on
  // the -x side; each drop is pulled back towards the gap so it can turn down smoothly.
  const Vec3 start_drop(start.x() - kLeadInset, start.y(), kDropTop);
  const Vec3 end_drop(end.x() + kLeadInset, end.y(), kDropTop);

  std::vector<Vec3> pts;
  pts.reserve(kDense + 1000);
  // Start: tail along -x into the turn, or the bare foot on z = 0; then the drop and the join.
  if (tails) {
    const double bend_z = kFloorBend;
    pts.emplace_back(kTailEnd, start_drop.y(), 0.0);
    line(pts, pts.back(), Vec3(start_drop.x() + kFloorBend, start_drop.y(), 0.0), 200);
    quarter(pts, Vec3(start_drop.x() + kFloorBend, start_drop.y(), bend_z), -ez, -ex, kFloorBend,
            60);
  } else {
    pts.emplace_back(start_drop.x(), start_drop.y(), 0.0);
  }
  line(pts, pts.back(), start_drop, 100);
  hermite(pts, start_drop, ez, start, start_dir, 150);
  // The body.
  for (int i = 1; i < kDense; ++i)
    pts.push_back(body.point(kCutT + kGap + (2 * std::numbers::pi - 2 * kGap) * i / kDense));
  pts.push_back(end);
  hermite(pts, end, end_dir, end_drop, -ez, 150);
  if (tails) {
    line(pts, end_drop, Vec3(end_drop.x(), end_drop.y(), kFloorBend), 100);
    quarter(pts, Vec3(end_drop.x() - kFloorBend, end_drop.y(), kFloorBend), ex, -ez, kFloorBend,
            60);
    line(pts, pts.back(), Vec3(-kTailEnd, end_drop.y(), 0.0), 200);
  } else {
    line(pts, end_drop, Vec3(end_drop.x(), end_drop.y(), 0.0), 100);
  }

  std::vector<Vec3> out = resample_by_arc_length<3>(pts, n, false);
  for (Vec3& p : out) p *= kScale;
  return out;
}

}  // namespace s4d
