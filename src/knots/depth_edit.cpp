// Depth-only edits: crossing flips and constrained depth smoothing.
#include "knots/depth_edit.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "knots/knot_diagram.hpp"

namespace s4d {

Curve<3> flip_crossing(const Curve<3>& curve, const Frame<3>& frame, int label) {
  Frame<3> used;
  KnotDiagram d = diagram_from_curve(curve, frame, {}, &used);
  if (label < 1 || label > d.crossing_count())
    throw Error("crossing " + std::to_string(label) + " does not exist (the diagram has " +
                std::to_string(d.crossing_count()) + " crossings)");
  // A crossing right at a vertex of the under strand leaves no room for the inserted points:
  // turn the view a little (the same diagram, the crossing slides along the strand).
  const std::string code = d.gauss_code();
  for (int attempt = 0; attempt < 8; ++attempt) {
    const double t = d.passages[d.crossings[label - 1].under].position;
    const double frac = t - std::floor(t);
    if (frac > 1e-6 && frac < 1 - 1e-6) break;
    Frame<3> turned = used;
    turned.rotate(Plane{0, 2}, 1e-4 * std::pow(2.0, attempt));
    turned.rotate(Plane{1, 2}, 0.7e-4 * std::pow(2.0, attempt));
    Frame<3> u2;
    KnotDiagram d2 = diagram_from_curve(curve, turned, {}, &u2);
    if (d2.gauss_code() == code) {
      d = std::move(d2);
      used = u2;
    }
  }
  const DiagramCrossing& c = d.crossings[label - 1];
  const Passage& under = d.passages[c.under];
  const int seg = static_cast<int>(std::floor(under.position));
  const double t = under.position - seg;

  // Neighbouring passages on the same segment bound how far the new points may spread.
  double lo = 0, hi = 1;
  for (int p : d.components[under.component]) {
    const Passage& v = d.passages[p];
    if (p == c.under || static_cast<int>(std::floor(v.position)) != seg) continue;
    const double tv = v.position - seg;
    if (tv < t) lo = std::max(lo, tv);
    if (tv > t) hi = std::min(hi, tv);
  }
  const double delta = 0.5 * std::min(t - lo, hi - t);

  Curve<3> out = curve;
  auto& pts = out.components[under.component].points;
  const Vec3 a = pts[seg], b = pts[(seg + 1) % pts.size()];
  const Vec3 axis = used.axis(2);
  const double gap = std::max(c.depth_over - c.depth_under, 1e-3 * curve_scale(curve));
  const Vec3 at = a + t * (b - a) + (c.depth_over - c.depth_under + gap) * axis;
  // Points closer than this to the segment's ends are dropped (a crossing next to a vertex):
  // the lifted point then joins that vertex directly, which still moves no other crossing.
  const double min_len = 1e-9 * curve_scale(curve) / std::max((b - a).norm(), 1e-300);
  std::vector<Vec3> inserted;
  if (t - delta > min_len) inserted.push_back(a + (t - delta) * (b - a));
  inserted.push_back(at);
  if (1 - (t + delta) > min_len) inserted.push_back(a + (t + delta) * (b - a));
  pts.insert(pts.begin() + seg + 1, inserted.begin(), inserted.end());
  return out;
}

Curve<3> smooth_depth(const Curve<3>& curve, const Frame<3>& frame, const DepthSmoothing& s) {
  Frame<3> used;
  const KnotDiagram d = diagram_from_curve(curve, frame, {}, &used);
  const Vec3 axis = used.axis(2);
  const double clearance = s.clearance * curve_scale(curve);

  // Depth of every vertex, per component; crossings as (over seg, t, under seg, t).
  std::vector<std::vector<double>> depth;
  for (const auto& pl : curve.components) {
    std::vector<double> z;
    for (const auto& p : pl.points) z.push_back(axis.dot(p));
    depth.push_back(std::move(z));
  }
  struct Constraint {
    int co, so, cu, su;
    double to, tu;
  };
  std::vector<Constraint> cons;
  for (const auto& c : d.crossings) {
    const Passage& o = d.passages[c.over];
    const Passage& u = d.passages[c.under];
    const int so = static_cast<int>(o.position), su = static_cast<int>(u.position);
    cons.push_back({o.component, so, u.component, su, o.position - so, u.position - su});
  }
  auto at = [&](int comp, int seg, double t) {
    const auto& z = depth[comp];
    return (1 - t) * z[seg] + t * z[(seg + 1) % z.size()];
  };
  std::vector<double> next;
  for (int it = 0; it < s.iterations; ++it) {
    for (auto& z : depth) {  // Laplacian step: pull each depth towards its neighbours' mean
      const std::size_t n = z.size();
      next.resize(n);
      for (std::size_t k = 0; k < n; ++k)
        next[k] = (1 - s.rate) * z[k] + s.rate * 0.5 * (z[(k + n - 1) % n] + z[(k + 1) % n]);
      z.swap(next);
    }
    // Projection onto the crossing constraints (a few sweeps: they share vertices).
    for (int sweep = 0; sweep < 8; ++sweep) {
      bool ok = true;
      for (const auto& k : cons) {
        const double zo = at(k.co, k.so, k.to);
        const double zu = at(k.cu, k.su, k.tu);
        const double deficit = clearance - (zo - zu);
        if (deficit <= 0) continue;
        ok = false;
        // Raise the over segment's ends and lower the under one's, by weights that close the gap
        // exactly when applied (minimum-norm correction of a linear constraint).
        const double wo0 = 1 - k.to, wo1 = k.to, wu0 = 1 - k.tu, wu1 = k.tu;
        const double norm2 = wo0 * wo0 + wo1 * wo1 + wu0 * wu0 + wu1 * wu1;
        const double lambda = deficit / norm2;
        auto& zo_v = depth[k.co];
        auto& zu_v = depth[k.cu];
        zo_v[k.so] += lambda * wo0;
        zo_v[(k.so + 1) % zo_v.size()] += lambda * wo1;
        zu_v[k.su] -= lambda * wu0;
        zu_v[(k.su + 1) % zu_v.size()] -= lambda * wu1;
      }
      if (ok) break;
    }
  }
  // Every crossing must keep its over/under order whatever happened above (a final guard).
  for (const auto& k : cons) {
    if (at(k.co, k.so, k.to) <= at(k.cu, k.su, k.tu))
      throw Error("depth smoothing could not keep a crossing's order (too many crossings on one segment)");
  }
  Curve<3> out = curve;
  for (std::size_t c = 0; c < out.components.size(); ++c)
    for (std::size_t k = 0; k < out.components[c].points.size(); ++k) {
      Vec3& p = out.components[c].points[k];
      p += (depth[c][k] - axis.dot(p)) * axis;
    }
  return out;
}

}  // namespace s4d
