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

bool project_depth(std::vector<DepthChain>& chains, std::span<const DepthConstraint> constraints,
                   int sweeps, double tolerance) {
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    bool ok = true;
    for (const DepthConstraint& k : constraints) {
      const double deficit = k.floor + k.gap - k.value(chains);
      if (deficit <= tolerance) continue;
      ok = false;
      // Move every term by its weight, scaled so that the gap closes exactly when applied
      // (minimum-norm correction of a linear constraint).
      double norm2 = 0;
      for (int t = 0; t < k.count; ++t) norm2 += k.terms[t].weight * k.terms[t].weight;
      if (!(norm2 > 0)) continue;
      const double lambda = deficit / norm2;
      for (int t = 0; t < k.count; ++t) chains[k.terms[t].chain].z[k.terms[t].index] += lambda * k.terms[t].weight;
    }
    if (ok) return true;
  }
  return false;
}

int smooth_depth_values(std::vector<DepthChain>& chains, std::span<const DepthConstraint> constraints,
                        int iterations, double rate, int sweeps) {
  std::vector<double> next;
  for (int it = 0; it < iterations; ++it) {
    for (DepthChain& c : chains) {  // Laplacian step: pull each depth towards its neighbours' mean
      std::vector<double>& z = c.z;
      const std::size_t n = z.size();
      if (n < 2) continue;
      next.resize(n);
      for (std::size_t k = 0; k < n; ++k) {
        // An open chain's end has one neighbour: mirrored, so the end follows it (free ends).
        const double before = k > 0 ? z[k - 1] : c.closed ? z[n - 1] : z[1];
        const double after = k + 1 < n ? z[k + 1] : c.closed ? z[0] : z[n - 2];
        next[k] = (1 - rate) * z[k] + rate * 0.5 * (before + after);
      }
      z.swap(next);
    }
    // Projection onto the constraints (a few sweeps: they share vertices).
    project_depth(chains, constraints, sweeps);
  }
  for (std::size_t i = 0; i < constraints.size(); ++i)
    if (!(constraints[i].value(chains) > constraints[i].floor)) return static_cast<int>(i);
  return -1;
}

Curve<3> smooth_depth(const Curve<3>& curve, const Frame<3>& frame, const DepthSmoothing& s) {
  Frame<3> used;
  const KnotDiagram d = diagram_from_curve(curve, frame, {}, &used);
  const Vec3 axis = used.axis(2);
  const double clearance = s.clearance * curve_scale(curve);

  std::vector<DepthChain> depth;
  for (const auto& pl : curve.components) {
    DepthChain z;
    for (const auto& p : pl.points) z.z.push_back(axis.dot(p));
    depth.push_back(std::move(z));
  }
  // At every crossing the over strand's point (on its segment) stays `clearance` above the under
  // strand's.
  std::vector<DepthConstraint> cons;
  for (const auto& c : d.crossings) {
    const Passage& o = d.passages[c.over];
    const Passage& u = d.passages[c.under];
    const int so = static_cast<int>(o.position), su = static_cast<int>(u.position);
    const double to = o.position - so, tu = u.position - su;
    const int no = static_cast<int>(depth[o.component].z.size()), nu = static_cast<int>(depth[u.component].z.size());
    DepthConstraint k;
    k.terms = {DepthTerm{o.component, so, 1 - to}, DepthTerm{o.component, (so + 1) % no, to},
               DepthTerm{u.component, su, -(1 - tu)}, DepthTerm{u.component, (su + 1) % nu, -tu}};
    k.count = 4;
    k.gap = clearance;
    cons.push_back(k);
  }
  // Every crossing must keep its over/under order whatever happened (a final guard).
  if (smooth_depth_values(depth, cons, s.iterations, s.rate) >= 0)
    throw Error("depth smoothing could not keep a crossing's order (too many crossings on one segment)");
  Curve<3> out = curve;
  for (std::size_t c = 0; c < out.components.size(); ++c)
    for (std::size_t k = 0; k < out.components[c].points.size(); ++k) {
      Vec3& p = out.components[c].points[k];
      p += (depth[c].z[k] - axis.dot(p)) * axis;
    }
  return out;
}

}  // namespace s4d
