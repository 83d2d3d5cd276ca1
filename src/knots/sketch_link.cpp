// Strokes to a link: every crossing of the strokes' shadows gets the later strand's choice,
// passages carry their depth on two points each, and the depth is smoothed under the
// constraints those passages make (knots/depth_edit), so no choice is ever lost.
#include "knots/sketch_link.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "knots/depth_edit.hpp"
#include "knots/knot_diagram.hpp"
#include "knots/segments_cross.hpp"

namespace s4d {
namespace {

struct StrokeSeg {
  int comp = 0, index = 0;  // from point `index` to the next (the last one closes the component)
  Vec2 a, b;
};

// One strand's passage through a crossing: where along its segment, and the constraint it feeds.
struct StrandPassage {
  double t = 0;
  int constraint = 0;
  double sign = 1;   // +1: this strand is the over one (or above the fixed strand)
  double depth = 0;  // its starting depth
};

}  // namespace

StrokeLink link_from_strokes(std::span<const StrokeComponent> strokes, std::span<const StrokeCrossing> crossed,
                             std::span<const FixedStrand> fixed, const StrokeLinkOptions& options) {
  if (strokes.empty()) throw Error("nothing was sketched");
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  double total = 0;
  int npoints = 0;
  for (std::size_t c = 0; c < strokes.size(); ++c) {
    const StrokeComponent& s = strokes[c];
    if (s.points.size() < 3)
      throw Error("stroke " + std::to_string(c + 1) + " has " + std::to_string(s.points.size()) +
                  " point(s); a component needs at least 3");
    if (s.choices.size() != s.points.size()) throw Error("stroke " + std::to_string(c + 1) + ": one choice per point");
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      if (!s.points[i].allFinite()) throw Error("stroke " + std::to_string(c + 1) + " has a non-finite point");
      lo = lo.cwiseMin(s.points[i]);
      hi = hi.cwiseMax(s.points[i]);
      total += (s.points[(i + 1) % s.points.size()] - s.points[i]).norm();
    }
    npoints += static_cast<int>(s.points.size());
  }
  const double size = (hi - lo).norm();
  if (!(size > 0)) throw Error("the sketch has no extent: drag to draw");
  const double lift = options.clearance * size;
  const double match = options.match > 0 ? options.match : 3 * total / npoints;

  std::vector<StrokeSeg> segs;
  std::vector<int> first(strokes.size());  // each component's first segment
  for (std::size_t c = 0; c < strokes.size(); ++c) {
    first[c] = static_cast<int>(segs.size());
    const auto& p = strokes[c].points;
    for (std::size_t i = 0; i < p.size(); ++i)
      segs.push_back({static_cast<int>(c), static_cast<int>(i), p[i], p[(i + 1) % p.size()]});
  }
  // The choice for the later strand through a crossing at `where` on segment s.
  auto choice_at = [&](const StrokeSeg& s, const Vec2& where) {
    double best = match;
    CrossChoice c = CrossChoice::kNone;
    for (const StrokeCrossing& x : crossed) {
      const double d = (x.at - where).norm();
      if (d < best && x.choice != CrossChoice::kNone) {
        best = d;
        c = x.choice;
      }
    }
    if (c != CrossChoice::kNone) return c;
    const auto& ch = strokes[static_cast<std::size_t>(s.comp)].choices;
    const CrossChoice held = ch[static_cast<std::size_t>(s.index)];
    if (held != CrossChoice::kNone) return held;
    return ch[(static_cast<std::size_t>(s.index) + 1) % ch.size()] == CrossChoice::kUnder ? CrossChoice::kUnder
                                                                                           : CrossChoice::kOver;
  };

  std::vector<std::vector<StrandPassage>> passages(segs.size());
  std::vector<DepthConstraint> constraints;
  StrokeLink out;
  const int n = static_cast<int>(segs.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const StrokeSeg &a = segs[static_cast<std::size_t>(i)], &b = segs[static_cast<std::size_t>(j)];
      if (a.comp == b.comp) {
        const int m = static_cast<int>(strokes[static_cast<std::size_t>(a.comp)].points.size());
        if (b.index == a.index + 1 || (a.index == 0 && b.index == m - 1)) continue;  // neighbours
      }
      double s = 0, t = 0;
      if (!segments_cross(a.a, a.b, b.a, b.b, s, t)) continue;
      const bool later_under = choice_at(b, (1 - t) * b.a + t * b.b) == CrossChoice::kUnder;
      DepthConstraint k;
      k.gap = lift;
      constraints.push_back(k);
      const int id = static_cast<int>(constraints.size()) - 1;
      passages[static_cast<std::size_t>(j)].push_back({t, id, later_under ? -1.0 : 1.0, later_under ? -lift : lift});
      passages[static_cast<std::size_t>(i)].push_back({s, id, later_under ? 1.0 : -1.0, later_under ? lift : -lift});
      ++out.crossings;
    }
  for (int i = 0; i < n; ++i)
    for (const FixedStrand& f : fixed) {
      const std::size_t m = f.points.size();
      if (m < 2 || f.depth.size() != m) continue;
      const StrokeSeg& a = segs[static_cast<std::size_t>(i)];
      for (std::size_t k = 0; k + (f.closed ? 0 : 1) < m; ++k) {
        const Vec2 &q0 = f.points[k], &q1 = f.points[(k + 1) % m];
        double s = 0, t = 0;
        if (!segments_cross(a.a, a.b, q0, q1, s, t)) continue;
        const double d = (1 - t) * f.depth[k] + t * f.depth[(k + 1) % m];
        const bool under = choice_at(a, (1 - s) * a.a + s * a.b) == CrossChoice::kUnder;
        DepthConstraint c;
        c.gap = lift;
        c.floor = under ? -d : d;
        constraints.push_back(c);
        passages[static_cast<std::size_t>(i)].push_back(
            {s, static_cast<int>(constraints.size()) - 1, under ? -1.0 : 1.0, under ? d - lift : d + lift});
        ++out.fixed_crossings;
      }
    }

  // Two points close around each passage carry its depth; everything else starts at depth 0.
  std::vector<DepthChain> chains(strokes.size());
  std::vector<std::vector<Vec2>> shadow(strokes.size());
  for (int i = 0; i < n; ++i) {
    const StrokeSeg& sg = segs[static_cast<std::size_t>(i)];
    const std::size_t c = static_cast<std::size_t>(sg.comp);
    shadow[c].push_back(sg.a);
    chains[c].z.push_back(0.0);
    auto& here = passages[static_cast<std::size_t>(i)];
    std::sort(here.begin(), here.end(), [](const StrandPassage& p, const StrandPassage& q) { return p.t < q.t; });
    for (std::size_t k = 0; k < here.size(); ++k) {
      const double before = k > 0 ? here[k - 1].t : 0.0, after = k + 1 < here.size() ? here[k + 1].t : 1.0;
      const double half = 0.4 * std::min({here[k].t - before, after - here[k].t, 0.25});
      DepthConstraint& con = constraints[static_cast<std::size_t>(here[k].constraint)];
      for (const double t : {here[k].t - half, here[k].t + half}) {
        shadow[c].push_back((1 - t) * sg.a + t * sg.b);
        chains[c].z.push_back(here[k].depth);
        if (con.count < 4) con.terms[static_cast<std::size_t>(con.count++)] =
            {sg.comp, static_cast<int>(chains[c].z.size()) - 1, 0.5 * here[k].sign};
      }
    }
  }
  smooth_depth_values(chains, constraints, 200, 0.5);

  for (std::size_t c = 0; c < strokes.size(); ++c) {
    Polyline<3> p;
    p.closed = true;
    for (std::size_t i = 0; i < shadow[c].size(); ++i)
      p.points.emplace_back(shadow[c][i].x(), shadow[c][i].y(), chains[c].z[i]);
    out.curve.components.push_back(std::move(p));
  }
  if (diagram_from_curve(out.curve, Frame<3>()).crossing_count() != out.crossings)
    throw Error("the strokes run along each other or cross at a corner: draw it again");
  return out;
}

}  // namespace s4d
