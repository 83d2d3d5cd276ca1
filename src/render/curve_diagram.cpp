// curve_diagram: the view's images of the curves (from screen_crossings) in screen coordinates, cut
// at the gaps of the under strands, and the flat strips the renderer draws them with.
//
// [SECTION] screen coordinates
// [SECTION] runs
// [SECTION] gaps
// [SECTION] strands
// [SECTION] strips
#include "render/curve_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace s4d {

// [SECTION] screen coordinates
double strand_half_width(const Camera& camera, double tube_radius) {
  const double f = 1.0 / std::tan(camera.fov_y / 2);
  return camera.distance > 0 ? f * tube_radius / camera.distance : f * tube_radius;
}

Vec2 screen_point(const Camera& camera, const Vec3& p) {
  const Vec3 e = (camera.view() * p.homogeneous()).head<3>();
  const double f = 1.0 / std::tan(camera.fov_y / 2);
  return Vec2(-f * e.x() / e.z(), -f * e.y() / e.z());
}

Vec2 screen_to_pixels(const Vec2& s, double aspect, int width, int height) {
  return Vec2((s.x() / aspect + 1) / 2 * width, (1 - s.y()) / 2 * height);
}

namespace {

// [SECTION] runs
// One component of an object's image: its points on the screen, with their depth (1/w), anchors,
// and arc length along the screen at each point (n + 1 values when closed: the last is the whole
// loop's).
struct Run {
  std::vector<Vec2> p;
  std::vector<double> depth;
  std::vector<int> anchor;
  std::vector<double> cum;
  bool closed = false;

  int size() const { return static_cast<int>(p.size()); }
  int segments() const { return closed ? size() : size() - 1; }
  double length() const { return cum.back(); }
  int next(int k) const { return (k + 1) % size(); }
};

// A place on a run: segment `seg`, at `t` of the way along it on the screen.
struct Place {
  int run = -1;
  int seg = 0;
  double t = 0;
};

double segment_parameter(const Vec2& a, const Vec2& b, const Vec2& q) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  return len2 > 0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
}

// The object's image runs, in screen coordinates, with anchors: for a whole image its points are
// the drawn points themselves; where part of it is behind the eye, each point takes the nearest
// drawn point in front of the eye.
std::vector<Run> image_runs(const Scene& scene, const Camera& camera, const ScreenImage& im) {
  const double f = 1.0 / std::tan(camera.fov_y / 2);
  std::vector<Run> runs;
  int offset = 0;
  for (const Polyline<3>& c : im.image.components) {
    Run r;
    r.closed = c.closed;
    for (const Vec3& q : c.points) {
      r.p.emplace_back(f * q.x(), f * q.y());
      r.depth.push_back(q.z());
    }
    if (im.whole)
      for (int k = 0; k < r.size(); ++k) r.anchor.push_back(offset + k);
    offset += r.size();
    r.cum.assign(1, 0.0);
    for (int k = 0; k < r.segments(); ++k) r.cum.push_back(r.cum.back() + (r.p[r.next(k)] - r.p[k]).norm());
    runs.push_back(std::move(r));
  }
  if (im.whole) return runs;
  // Seen points of the drawn curve, to colour the runs by.
  std::vector<Vec2> seen;
  std::vector<double> seen_depth;
  std::vector<int> seen_index;
  int index = 0;
  for (const Polyline<3>& poly : drawn_curve(scene.objects[static_cast<std::size_t>(im.object)].shape, scene.frame))
    for (const Vec3& q : poly.points) {
      const double w = camera.view_depth(q);
      if (w >= camera.near_plane && std::isfinite(w)) {
        seen.push_back(screen_point(camera, q));
        seen_depth.push_back(1 / w);
        seen_index.push_back(index);
      }
      ++index;
    }
  const double depth_scale = camera.distance;  // 1/w per screen unit, about
  for (Run& r : runs)
    for (int k = 0; k < r.size(); ++k) {
      double best = std::numeric_limits<double>::infinity();
      int at = 0;
      for (std::size_t j = 0; j < seen.size(); ++j) {
        const double dd = (seen_depth[j] - r.depth[k]) * depth_scale;
        const double d2 = (seen[j] - r.p[k]).squaredNorm() + dd * dd;
        if (d2 < best) {
          best = d2;
          at = seen_index[j];
        }
      }
      r.anchor.push_back(at);
    }
  return runs;
}

// Where on the runs the strand through screen point q at depth `depth` is: at `hint` when the
// crossing finder named the segment, else on the segment through q (within rounding) whose depth
// there is nearest `depth` (the other strand of the crossing passes through q too), else the
// nearest segment.
Place locate(const std::vector<Run>& runs, const Vec2& q, double depth, const SegmentRef& hint) {
  if (hint.component >= 0 && hint.component < static_cast<int>(runs.size())) {
    const Run& r = runs[static_cast<std::size_t>(hint.component)];
    if (hint.segment >= 0 && hint.segment < r.segments())
      return {hint.component, hint.segment, segment_parameter(r.p[hint.segment], r.p[r.next(hint.segment)], q)};
  }
  const double tolerance = 1e-9 * (1 + q.norm());
  Place best, nearest;
  double best_depth = std::numeric_limits<double>::infinity(), best_distance = best_depth;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Run& r = runs[i];
    for (int k = 0; k < r.segments(); ++k) {
      const Vec2 &a = r.p[k], &b = r.p[r.next(k)];
      const double t = segment_parameter(a, b, q);
      const double distance = (a + t * (b - a) - q).norm();
      const Place here{static_cast<int>(i), k, t};
      if (distance < best_distance) {
        best_distance = distance;
        nearest = here;
      }
      if (distance > tolerance) continue;
      const double error = std::abs((1 - t) * r.depth[k] + t * r.depth[r.next(k)] - depth);
      if (error < best_depth) {
        best_depth = error;
        best = here;
      }
    }
  }
  return best.run >= 0 ? best : nearest;
}

Vec2 direction_at(const Run& r, int seg) {
  const Vec2 d = r.p[r.next(seg)] - r.p[seg];
  return d.norm() > 0 ? Vec2(d.normalized()) : Vec2::UnitX();
}

// [SECTION] gaps
// How far the gap reaches either side of the crossing along the under strand, for strands of
// half-width h crossing at angle θ: the under strand's square end, whose corners stand h |cos θ|
// nearer the over strand than its centre, must clear the over strand (h from its centreline) by a
// further h, the white a pen leaves on paper: s sin θ ≥ 2h + h |cos θ|. Nearly tangent strands
// would need a gap without end; sin θ is taken as at least 1/4 there.
double gap_half_length(double h, const Vec2& under, const Vec2& over) {
  const double sin_t = std::abs(under.x() * over.y() - under.y() * over.x());
  const double cos_t = std::abs(under.dot(over));
  return h * (2 + cos_t) / std::max(sin_t, 0.25);
}

struct Interval {
  double lo, hi;
};

// Merges sorted intervals; on a loop of length `loop` (> 0), also across its start. Counts the
// intervals merged into another in `merged`.
std::vector<Interval> merge(std::vector<Interval> in, double loop, int& merged) {
  std::sort(in.begin(), in.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
  std::vector<Interval> out;
  for (const Interval& i : in) {
    if (!out.empty() && i.lo <= out.back().hi) {
      out.back().hi = std::max(out.back().hi, i.hi);
      ++merged;
    } else {
      out.push_back(i);
    }
  }
  if (loop > 0)
    while (out.size() > 1 && out.back().hi - loop >= out.front().lo) {
      out.back().hi = std::max(out.back().hi, out.front().hi + loop);
      out.erase(out.begin());
      ++merged;
    }
  return out;
}

// [SECTION] strands
// The point of run r at arc length s (taken round the loop when closed), with its depth and
// anchor.
void append_at(const Run& r, double s, DiagramStrand& out) {
  if (r.closed) s -= std::floor(s / r.length()) * r.length();
  s = std::clamp(s, 0.0, r.length());
  int k = static_cast<int>(std::upper_bound(r.cum.begin(), r.cum.end(), s) - r.cum.begin()) - 1;
  k = std::clamp(k, 0, r.segments() - 1);
  const double len = r.cum[k + 1] - r.cum[k];
  const double t = len > 0 ? std::clamp((s - r.cum[k]) / len, 0.0, 1.0) : 0.0;
  const int n = r.next(k);
  out.points.push_back(r.p[k] + t * (r.p[n] - r.p[k]));
  out.depth.push_back((1 - t) * r.depth[k] + t * r.depth[n]);  // 1/w is affine along the image
  out.anchor.push_back(t < 0.5 ? r.anchor[k] : r.anchor[n]);
}

// The strand of run r between arc lengths s0 < s1 (s1 beyond the loop's length on a closed run:
// it goes on past the start).
DiagramStrand strand_between(const Run& r, double s0, double s1) {
  DiagramStrand out;
  const double loop = r.length();
  const double base = r.closed && loop > 0 ? std::floor(s0 / loop) * loop : 0.0;
  s0 -= base;
  s1 -= base;
  append_at(r, s0, out);
  const int n = r.size();
  // The first vertex past s0, then on while before s1 (vertex j of the unrolled loop is at
  // cum[j mod n] + loop · (j div n)).
  int j = static_cast<int>(std::upper_bound(r.cum.begin(), r.cum.end(), s0) - r.cum.begin());
  const int last = r.closed ? 2 * n : n - 1;
  for (; j <= last; ++j) {
    const double at = r.closed ? r.cum[j % n] + loop * (j / n) : r.cum[j];
    if (at >= s1) break;
    if (at <= s0) continue;
    out.points.push_back(r.p[j % n]);
    out.depth.push_back(r.depth[j % n]);
    out.anchor.push_back(r.anchor[j % n]);
  }
  append_at(r, s1, out);
  return out;
}

}  // namespace

CurveDiagram curve_diagram(const Scene& scene, const Camera& camera, double half_width, bool gaps) {
  CurveDiagram d;
  d.aspect = camera.aspect;
  d.half_width = half_width;
  d.screen = screen_crossings(scene, camera);
  for (const ScreenImage& im : d.screen.images) {
    const std::vector<Run> runs = image_runs(scene, camera, im);
    std::vector<std::vector<Interval>> cut(runs.size());
    if (gaps)
      for (std::size_t c = 0; c < d.screen.crossings.size(); ++c) {
        const ScreenCrossing& x = d.screen.crossings[c];
        if (x.object != im.object) continue;
        const Vec2 q = screen_point(camera, x.under);
        const Place under = locate(runs, q, 1 / camera.view_depth(x.under), x.under_at);
        const Place over = locate(runs, screen_point(camera, x.over), 1 / camera.view_depth(x.over), x.over_at);
        if (under.run < 0 || over.run < 0) continue;
        const Run& r = runs[static_cast<std::size_t>(under.run)];
        DiagramGap g;
        g.object = im.object;
        g.crossing = static_cast<int>(c);
        g.run = under.run;
        g.at = q;
        g.under_direction = direction_at(r, under.seg);
        g.over_direction = direction_at(runs[static_cast<std::size_t>(over.run)], over.seg);
        g.half_length = gap_half_length(half_width, g.under_direction, g.over_direction);
        const double s = r.cum[under.seg] + under.t * (r.cum[under.seg + 1] - r.cum[under.seg]);
        cut[static_cast<std::size_t>(under.run)].push_back({s - g.half_length, s + g.half_length});
        d.gaps.push_back(g);
      }
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Run& r = runs[i];
      if (r.size() < 2) continue;
      const double length = r.length();
      auto add = [&](DiagramStrand s, bool closed) {
        s.object = im.object;
        s.run = static_cast<int>(i);
        s.closed = closed;
        d.strands.push_back(std::move(s));
      };
      if (cut[i].empty()) {
        DiagramStrand whole;
        whole.points = r.p;
        whole.depth = r.depth;
        whole.anchor = r.anchor;
        add(std::move(whole), r.closed);
        continue;
      }
      if (r.closed) {
        for (Interval& g : cut[i]) {  // the loop's start inside [0, length)
          const double shift = std::floor(g.lo / length) * length;
          g.lo -= shift;
          g.hi -= shift;
        }
        const std::vector<Interval> m = merge(cut[i], length, d.merged_gaps);
        if (m.size() == 1 && m[0].hi - m[0].lo >= length) continue;  // all gap
        for (std::size_t k = 0; k < m.size(); ++k) {
          const double to = k + 1 < m.size() ? m[k + 1].lo : m[0].lo + length;
          if (to > m[k].hi) add(strand_between(r, m[k].hi, to), false);
        }
      } else {
        const std::vector<Interval> m = merge(cut[i], 0, d.merged_gaps);
        double from = 0;
        for (const Interval& g : m) {
          if (g.lo > from) add(strand_between(r, from, std::min(g.lo, length)), false);
          from = std::max(from, g.hi);
        }
        if (from < length) add(strand_between(r, from, length), false);
      }
    }
  }
  return d;
}

// [SECTION] strips
RenderMesh strand_strip_mesh(const DiagramStrand& strand, double half_width, double aspect,
                             const Camera& camera) {
  RenderMesh m;
  // Repeated points have no direction: skip them (and a closed strand's last point on its first).
  std::vector<int> keep;
  for (int i = 0; i < static_cast<int>(strand.points.size()); ++i)
    if (strand.points[i].allFinite() &&
        (keep.empty() || (strand.points[i] - strand.points[keep.back()]).norm() > 1e-12))
      keep.push_back(i);
  if (strand.closed && keep.size() > 2 && (strand.points[keep.back()] - strand.points[keep.front()]).norm() <= 1e-12)
    keep.pop_back();
  const int n = static_cast<int>(keep.size());
  if (n < 2) return m;
  const bool closed = strand.closed && n > 2;
  const int segments = closed ? n : n - 1;
  auto pt = [&](int i) { return strand.points[keep[(i % n + n) % n]]; };
  std::vector<Vec2> normal(segments);
  for (int i = 0; i < segments; ++i) {
    const Vec2 d = (pt(i + 1) - pt(i)).normalized();
    normal[i] = Vec2(-d.y(), d.x());
  }
  // The depth of NDC from 1/w: z_ndc = -P22 + P23 / w for an OpenGL perspective projection.
  const Mat4 proj = camera.projection();
  const double h = half_width;
  m.positions.reserve(2 * n);
  for (int i = 0; i < n; ++i) {
    const bool has_in = closed || i > 0, has_out = closed || i < n - 1;
    const Vec2 n_in = has_in ? normal[(i - 1 + segments) % segments] : normal[0];
    const Vec2 n_out = has_out ? normal[i % segments] : n_in;
    Vec2 offset = h * n_out;
    if (has_in && has_out) {  // a mitred joint, at most twice the half-width out
      const Vec2 mid = n_in + n_out;
      if (mid.norm() > 1e-6) offset = mid.normalized() * (h / std::max(mid.normalized().dot(n_out), 0.5));
    }
    const Vec2 p = pt(i);
    const double z = -proj(2, 2) + proj(2, 3) * strand.depth[keep[i]];
    for (const double side : {1.0, -1.0}) {
      const Vec2 q = p + side * offset;
      m.positions.emplace_back(q.x() / aspect, q.y(), z);
      m.normals.push_back(Vec3::UnitZ());
      m.source.push_back(strand.anchor[keep[i]]);
    }
  }
  for (int i = 0; i < segments; ++i) {
    const auto a = static_cast<std::uint32_t>(2 * i), b = a + 1;
    const auto c = static_cast<std::uint32_t>(2 * ((i + 1) % n)), e = c + 1;
    m.indices.insert(m.indices.end(), {a, b, e, a, e, c});
  }
  return m;
}

}  // namespace s4d
