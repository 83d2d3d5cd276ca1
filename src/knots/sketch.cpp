#include "knots/sketch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "knots/depth_edit.hpp"
#include "knots/knot_diagram.hpp"

namespace s4d {

namespace {

// Dynadraw at no more than this step: a GUI samples the cursor once a frame, and at a low frame
// rate one step a sample would make the pen's spring ring.
constexpr double kPenStep = 1.0 / 240.0;

struct PenPoint {
  Vec2 at;
  double time;  // when the pen was there
};

// The pen's path: one point per sample (after the step to it), then a short settle on the last.
std::vector<PenPoint> pen_path(std::span<const SketchSample> stroke, const DynadrawParams& p) {
  Dynadraw<2> pen(p);
  pen.reset(stroke[0].at);
  std::vector<PenPoint> path{{stroke[0].at, stroke[0].time}};
  for (std::size_t i = 1; i < stroke.size(); ++i) {
    const double dt = stroke[i].time - stroke[i - 1].time;
    const int n = std::clamp(static_cast<int>(std::ceil(dt / kPenStep)), 1, 100000);
    for (int k = 1; k <= n; ++k) {
      const double s = double(k) / n;
      pen.step(Vec2((1 - s) * stroke[i - 1].at + s * stroke[i].at), dt / n);
    }
    path.push_back({pen.position(), stroke[i].time});
  }
  for (int k = 0; k < 24; ++k) pen.step(stroke.back().at, kPenStep);
  path.push_back({pen.position(), stroke.back().time + 24 * kPenStep});
  return path;
}

// Whether the hand held the modifier where the pen crossed at `at` at `time`: the pen trails the
// cursor (by about damping / stiffness), so this asks the cursor sample nearest that place among
// those of the moments before, not the sample of the pen's own moment.
bool held_under(std::span<const SketchSample> stroke, const Vec2& at, double time) {
  constexpr double kLookBack = 0.3;  // seconds: several times the pen's lag
  const SketchSample* best = nullptr;
  double best_d = std::numeric_limits<double>::infinity();
  for (const SketchSample& s : stroke) {
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
    for (const SketchSample& s : stroke)
      if (std::abs(s.time - time) < std::abs(best->time - time)) best = &s;
  }
  return best->under;
}

// The closed path resampled to points `spacing` apart along it, each with the pen's time there.
std::vector<PenPoint> resample_closed(const std::vector<PenPoint>& path, double spacing) {
  const std::size_t n = path.size();
  std::vector<double> at(n + 1, 0.0);  // arc length at each point; at[n] closes the loop
  for (std::size_t i = 0; i < n; ++i) at[i + 1] = at[i] + (path[(i + 1) % n].at - path[i].at).norm();
  const double length = at[n];
  const int count = std::max(24, static_cast<int>(std::ceil(length / spacing)));
  std::vector<PenPoint> out;
  out.reserve(count);
  std::size_t seg = 0;
  for (int k = 0; k < count; ++k) {
    const double s = length * k / count;
    while (seg + 1 < n && at[seg + 1] <= s) ++seg;
    const double len = at[seg + 1] - at[seg];
    const double t = len > 0 ? (s - at[seg]) / len : 0.0;
    out.push_back({(1 - t) * path[seg].at + t * path[(seg + 1) % n].at,
                   (1 - t) * path[seg].time + t * path[(seg + 1) % n].time});
  }
  return out;
}

// Where segments p0p1 and q0q1 cross at interior points: their parameters.
bool segments_cross(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1, double& s, double& t) {
  const Vec2 r = p1 - p0, d = q1 - q0, w = q0 - p0;
  const double den = r.x() * d.y() - r.y() * d.x();
  if (den == 0) return false;
  s = (w.x() * d.y() - w.y() * d.x()) / den;
  t = (w.x() * r.y() - w.y() * r.x()) / den;
  return s > 0 && s < 1 && t > 0 && t < 1;
}

struct StrokePassage {
  double t;      // along its segment
  double depth;  // + over, - under
};

}  // namespace

Curve<3> stroke_as_curve(std::span<const SketchSample> stroke) {
  Polyline<3> p{{}, false};
  for (const SketchSample& s : stroke) p.points.emplace_back(s.at.x(), s.at.y(), s.under ? 1.0 : 0.0);
  Curve<3> c;
  c.components.push_back(std::move(p));
  return c;
}

std::vector<SketchSample> stroke_from_curve(const Curve<3>& curve, double dt) {
  if (curve.components.empty() || curve.components[0].points.empty()) throw Error("the stroke has no samples");
  std::vector<SketchSample> stroke;
  for (const Vec3& q : curve.components[0].points)
    stroke.push_back({q.head<2>(), dt * static_cast<double>(stroke.size()), q.z() >= 0.5});
  return stroke;
}

SketchedKnot knot_from_sketch(std::span<const SketchSample> stroke, const SketchOptions& options) {
  if (stroke.size() < 3) throw Error("a sketch needs at least 3 cursor samples");
  for (std::size_t i = 0; i < stroke.size(); ++i) {
    if (!stroke[i].at.allFinite() || !std::isfinite(stroke[i].time))
      throw Error("sketch sample " + std::to_string(i) + " is not finite");
    if (i > 0 && stroke[i].time < stroke[i - 1].time)
      throw Error("sketch sample " + std::to_string(i) + " goes back in time");
  }
  const std::vector<PenPoint> path = pen_path(stroke, options.pen);
  Vec2 lo = path[0].at, hi = path[0].at;
  for (const PenPoint& p : path) {
    lo = lo.cwiseMin(p.at);
    hi = hi.cwiseMax(p.at);
  }
  const double size = (hi - lo).norm();
  if (!(size > 0)) throw Error("the sketch has no extent: drag to draw");
  const double spacing =
      options.spacing > 0 && std::isfinite(options.spacing) ? options.spacing : size / 120.0;
  const std::vector<PenPoint> ring = resample_closed(path, spacing);
  const int n = static_cast<int>(ring.size());

  // Each crossing: the strand drawn later (the higher segment index; the closing segment last)
  // passes over, or under where its modifier was held.
  const double lift = options.clearance * size;
  std::vector<std::vector<StrokePassage>> passages(n);
  int crossings = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the closing point
      double s = 0, t = 0;
      if (!segments_cross(ring[i].at, ring[(i + 1) % n].at, ring[j].at, ring[(j + 1) % n].at, s, t))
        continue;
      // The closing stretch (from the last point back to the first) is the pen's last move.
      const double t0 = ring[j].time, t1 = j + 1 < n ? ring[j + 1].time : ring[j].time;
      const Vec2 where = (1 - t) * ring[j].at + t * ring[(j + 1) % n].at;
      const double later = held_under(stroke, where, (1 - t) * t0 + t * t1) ? -lift : lift;
      passages[i].push_back({s, -later});
      passages[j].push_back({t, later});
      ++crossings;
    }

  // Two points close around each passage carry its depth; everything else starts at depth 0.
  Polyline<3> poly;
  poly.closed = true;
  for (int i = 0; i < n; ++i) {
    const Vec2 a = ring[i].at, b = ring[(i + 1) % n].at;
    poly.points.emplace_back(a.x(), a.y(), 0.0);
    auto& here = passages[i];
    std::sort(here.begin(), here.end(), [](const StrokePassage& p, const StrokePassage& q) { return p.t < q.t; });
    for (std::size_t k = 0; k < here.size(); ++k) {
      const double before = k > 0 ? here[k - 1].t : 0.0, after = k + 1 < here.size() ? here[k + 1].t : 1.0;
      const double half = 0.4 * std::min({here[k].t - before, after - here[k].t, 0.25});
      for (const double t : {here[k].t - half, here[k].t + half}) {
        const Vec2 p = (1 - t) * a + t * b;
        poly.points.emplace_back(p.x(), p.y(), here[k].depth);
      }
    }
  }
  Curve<3> start;
  start.components.push_back(std::move(poly));
  DepthSmoothing smooth;
  smooth.clearance = options.clearance;
  SketchedKnot out{smooth_depth(start, Frame<3>(), smooth), crossings};
  if (diagram_from_curve(out.curve, Frame<3>()).crossing_count() != crossings)
    throw Error("the sketch runs along itself or crosses at a corner: draw it again");
  return out;
}

}  // namespace s4d
