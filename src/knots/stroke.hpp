// A hand's stroke in a sketch space of any dimension (the knot sketch's plane, the ribbon
// sketch's 3D shadow): its checks, the Dynadraw pen's path, the modifier held at a place, and
// resampling by arc length. knot_from_sketch and ribbon_from_sketch share these.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "knots/dynadraw.hpp"
#include "shape/curve.hpp"

namespace s4d {

template <int D>
struct StrokeSample {
  Vec<D> at = Vec<D>::Zero();  // the cursor, in the sketch space
  double time = 0;             // seconds since the stroke began (never decreasing)
  bool under = false;          // the modifier held: this part passes under (below in w)
};

template <int D>
struct PenPoint {
  Vec<D> at;
  double time;  // when the pen was there
};

// Dynadraw at no more than this step: a GUI samples the cursor once a frame, and at a low frame
// rate one step a sample would make the pen's spring ring.
inline constexpr double kPenStep = 1.0 / 240.0;

// Throws s4d::Error for fewer than `min_samples` samples, non-finite values or times that go back.
template <int D>
void check_stroke(std::span<const StrokeSample<D>> stroke, std::size_t min_samples) {
  if (stroke.size() < min_samples)
    throw Error("a sketch needs at least " + std::to_string(min_samples) + " cursor samples");
  for (std::size_t i = 0; i < stroke.size(); ++i) {
    if (!stroke[i].at.allFinite() || !std::isfinite(stroke[i].time))
      throw Error("sketch sample " + std::to_string(i) + " is not finite");
    if (i > 0 && stroke[i].time < stroke[i - 1].time)
      throw Error("sketch sample " + std::to_string(i) + " goes back in time");
  }
}

// The pen's path: one point per sample (after the step to it), then a short settle on the last.
// Needs a checked, non-empty stroke.
template <int D>
std::vector<PenPoint<D>> pen_path(std::span<const StrokeSample<D>> stroke, const DynadrawParams& p) {
  Dynadraw<D> pen(p);
  pen.reset(stroke[0].at);
  std::vector<PenPoint<D>> path{{stroke[0].at, stroke[0].time}};
  for (std::size_t i = 1; i < stroke.size(); ++i) {
    const double dt = stroke[i].time - stroke[i - 1].time;
    const int n = std::clamp(static_cast<int>(std::ceil(dt / kPenStep)), 1, 100000);
    for (int k = 1; k <= n; ++k) {
      const double s = double(k) / n;
      pen.step(Vec<D>((1 - s) * stroke[i - 1].at + s * stroke[i].at), dt / n);
    }
    path.push_back({pen.position(), stroke[i].time});
  }
  for (int k = 0; k < 24; ++k) pen.step(stroke.back().at, kPenStep);
  path.push_back({pen.position(), stroke.back().time + 24 * kPenStep});
  return path;
}

// Whether the hand held the modifier where the pen passed `at` at `time`: the pen trails the
// cursor (by about damping / stiffness), so this asks the cursor sample nearest that place among
// those of the moments before, not the sample of the pen's own moment.
template <int D>
bool held_under(std::span<const StrokeSample<D>> stroke, const Vec<D>& at, double time) {
  constexpr double kLookBack = 0.3;  // seconds: several times the pen's lag
  const StrokeSample<D>* best = nullptr;
  double best_d = std::numeric_limits<double>::infinity();
  for (const StrokeSample<D>& s : stroke) {
    if (s.time < time - kLookBack) continue;
    if (s.time > time + kPenStep) break;
    const double d = (s.at - at).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best = &s;
    }
  }
  if (!best) {  // samples sparser than the look-back: the one nearest in time
    best = &stroke[0];
    for (const StrokeSample<D>& s : stroke)
      if (std::abs(s.time - time) < std::abs(best->time - time)) best = &s;
  }
  return best->under;
}

// The path resampled to points `spacing` apart along it (at least `min_segments` segments), each
// with the pen's time there. Closed: the last point joins the first and is not repeated; open:
// both ends are kept.
template <int D>
std::vector<PenPoint<D>> resample_pen_path(const std::vector<PenPoint<D>>& path, double spacing,
                                           bool closed, int min_segments) {
  const std::size_t n = path.size();
  const std::size_t segs = closed ? n : n - 1;
  std::vector<double> at(segs + 1, 0.0);  // arc length at each point; closed: at[n] closes the loop
  for (std::size_t i = 0; i < segs; ++i) at[i + 1] = at[i] + (path[(i + 1) % n].at - path[i].at).norm();
  const double length = at[segs];
  const int count = std::max(min_segments, static_cast<int>(std::ceil(length / spacing)));
  std::vector<PenPoint<D>> out;
  out.reserve(count + 1);
  std::size_t seg = 0;
  for (int k = 0; k < (closed ? count : count + 1); ++k) {
    const double s = length * k / count;
    while (seg + 1 < segs && at[seg + 1] <= s) ++seg;
    const double len = at[seg + 1] - at[seg];
    const double t = len > 0 ? std::min((s - at[seg]) / len, 1.0) : 0.0;
    out.push_back({(1 - t) * path[seg].at + t * path[(seg + 1) % n].at,
                   (1 - t) * path[seg].time + t * path[(seg + 1) % n].time});
  }
  return out;
}

// A stroke as a curve file keeps it: one open polyline of points (at, u), u = 1 where the modifier
// was held. Times are not kept.
template <int D>
Curve<D + 1> stroke_as_curve(std::span<const StrokeSample<D>> stroke) {
  Polyline<D + 1> p{{}, false};
  for (const StrokeSample<D>& s : stroke) {
    Vec<D + 1> q;
    q << s.at, s.under ? 1.0 : 0.0;
    p.points.push_back(q);
  }
  Curve<D + 1> c;
  c.components.push_back(std::move(p));
  return c;
}

// The inverse: the first component's points, `dt` seconds apart. Throws s4d::Error for no points.
template <int D>
std::vector<StrokeSample<D>> stroke_from_curve(const Curve<D + 1>& curve, double dt) {
  if (curve.components.empty() || curve.components[0].points.empty()) throw Error("the stroke has no samples");
  std::vector<StrokeSample<D>> stroke;
  for (const Vec<D + 1>& q : curve.components[0].points)
    stroke.push_back({q.template head<D>(), dt * static_cast<double>(stroke.size()), q[D] >= 0.5});
  return stroke;
}

}  // namespace s4d
