#include "knots/sketch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "knots/depth_edit.hpp"
#include "knots/knot_diagram.hpp"
#include "knots/segments_cross.hpp"

namespace s4d {

namespace {

struct StrokePassage {
  double t;      // along its segment
  double depth;  // + over, - under
};

}  // namespace

Curve<3> stroke_as_curve(std::span<const SketchSample> stroke) { return stroke_as_curve<2>(stroke); }

std::vector<SketchSample> stroke_from_curve(const Curve<3>& curve, double dt) {
  return stroke_from_curve<2>(curve, dt);
}

SketchedKnot knot_from_sketch(std::span<const SketchSample> stroke, const SketchOptions& options) {
  check_stroke<2>(stroke, 3);
  const std::vector<PenPoint<2>> path = pen_path<2>(stroke, options.pen);
  Vec2 lo = path[0].at, hi = path[0].at;
  for (const PenPoint<2>& p : path) {
    lo = lo.cwiseMin(p.at);
    hi = hi.cwiseMax(p.at);
  }
  const double size = (hi - lo).norm();
  if (!(size > 0)) throw Error("the sketch has no extent: drag to draw");
  const double spacing =
      options.spacing > 0 && std::isfinite(options.spacing) ? options.spacing : size / 120.0;
  const std::vector<PenPoint<2>> ring = resample_pen_path<2>(path, spacing, /*closed=*/true, 24);
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
      const double later = held_under<2>(stroke, where, (1 - t) * t0 + t * t1) ? -lift : lift;
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
