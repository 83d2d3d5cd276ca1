// The relaxation step as an explicit list of stages: forces (repulsion, springs, bending), the
// no-pass-through cap from segment gaps, then the move.
#include "knots/relax.hpp"

#include <algorithm>
#include <cmath>

#include "knots/knot_diagram.hpp"
#include "proximity/closest_points.hpp"

namespace s4d {

void relax_setup(const Curve<3>& curve, RelaxModel& model, RelaxData& data) {
  validate_knot_curve(curve);
  model.first.clear();
  model.count.clear();
  model.rest_length.clear();
  data.x.clear();
  data.comp.clear();
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    const auto& pl = curve.components[c];
    model.first.push_back(static_cast<int>(data.x.size()));
    model.count.push_back(static_cast<int>(pl.points.size()));
    model.rest_length.push_back(pl.length() / static_cast<double>(pl.points.size()));
    for (const auto& p : pl.points) {
      data.x.push_back(p);
      data.comp.push_back(static_cast<int>(c));
    }
  }
  data.force.assign(data.x.size(), Vec3::Zero());
  data.min_gap = 0;
  data.limited_steps = 0;
}

namespace {
inline int next_of(const RelaxModel& m, int c, int i) {
  const int f = m.first[c], n = m.count[c];
  return f + (i - f + 1) % n;
}
inline int prev_of(const RelaxModel& m, int c, int i) {
  const int f = m.first[c], n = m.count[c];
  return f + (i - f + n - 1) % n;
}
// Segments i -> next(i) and j -> next(j) share a vertex (or are the same).
inline bool neighbours(const RelaxModel& m, const RelaxData& d, int i, int j) {
  if (d.comp[i] != d.comp[j]) return false;
  const int c = d.comp[i];
  return i == j || next_of(m, c, i) == j || next_of(m, c, j) == i;
}
double mean_rest(const RelaxModel& m) {
  double mean = 0;
  for (double l : m.rest_length) mean += l;
  return mean / static_cast<double>(m.rest_length.size());
}
}  // namespace

void relax_forces(const RelaxModel& m, RelaxData& d) {
  const int n = static_cast<int>(d.x.size());
  const double l0 = mean_rest(m), l2 = l0 * l0;
  for (auto& f : d.force) f.setZero();

  // [1] Repulsion between all vertex pairs that are not curve neighbours, and in the same sweep a
  // lower bound on every non-neighbour segment gap: |m_i - m_j| - (len_i + len_j) / 2, refined
  // with the exact segment distance when that bound is small.
  double gap = INFINITY;
  const double near = 3.0 * l0;
  const double thick = m.thickness * l0;
  for (int i = 0; i < n; ++i) {
    const int ci = d.comp[i];
    const Vec3& xi = d.x[i];
    const Vec3& xi1 = d.x[next_of(m, ci, i)];
    const Vec3 mi = 0.5 * (xi + xi1);
    const double hi = 0.5 * (xi1 - xi).norm();
    for (int j = i + 1; j < n; ++j) {
      const Vec3 r = xi - d.x[j];
      const double r2 = r.squaredNorm();
      const bool close_on_curve =
          d.comp[j] == ci &&
          (std::min(j - i, m.count[ci] - (j - i)) <= 1);  // same or adjacent vertex
      if (!close_on_curve && r2 > 0) {
        // E = repulsion * l0^4 / (2 r^2): force = repulsion * l0^4 r / r^4 (scaled by 1/l0 below).
        const Vec3 f = (m.repulsion * l2 * l2 / (r2 * r2)) * r;
        d.force[i] += f;
        d.force[j] -= f;
      }
      if (neighbours(m, d, i, j)) continue;
      const Vec3& xj1 = d.x[next_of(m, d.comp[j], j)];
      const double bound = (mi - 0.5 * (d.x[j] + xj1)).norm() - hi - 0.5 * (xj1 - d.x[j]).norm();
      if (bound < near) {
        const ClosestPoints<3> cp = segment_segment<3>(xi, xi1, d.x[j], xj1);
        gap = std::min(gap, cp.distance);
        if (cp.distance < thick && cp.distance > 0) {
          const Vec3 push = (m.contact * l0 * (thick / cp.distance - 1.0) / cp.distance) * (cp.p - cp.q);
          const int i1 = next_of(m, ci, i), j1 = next_of(m, d.comp[j], j);
          d.force[i] += cp.wa[0] * push;
          d.force[i1] += cp.wa[1] * push;
          d.force[j] -= cp.wb[0] * push;
          d.force[j1] -= cp.wb[1] * push;
        }
      }
    }
  }
  d.min_gap = std::min(gap, near);

  // [2] Springs towards the rest length and Laplacian bending.
  for (int i = 0; i < n; ++i) {
    const int c = d.comp[i];
    const int j = next_of(m, c, i), h = prev_of(m, c, i);
    const Vec3 e = d.x[j] - d.x[i];
    const double len = e.norm();
    if (len > 0) {
      const Vec3 f = (m.spring * (len - m.rest_length[c]) / m.rest_length[c]) * (e / len) * l0;
      d.force[i] += f;
      d.force[j] -= f;
    }
    d.force[i] += m.bending * (d.x[j] + d.x[h] - 2.0 * d.x[i]);
  }
}

// [3] Move, each vertex by at most the cap: two segments whose vertices each move less than
// gap / 2 cannot meet during the linear motion, so the knot type is kept.
Vec3 relax_move(const RelaxModel& m, const RelaxData& d, int i, bool& limited) {
  const double cap = std::min(m.max_move * mean_rest(m), m.safety * d.min_gap);
  Vec3 step = m.step * d.force[static_cast<std::size_t>(i)];
  if (!step.allFinite()) return Vec3::Zero();  // counted as a limited step, the vertex stays
  const double s = step.norm();
  if (s > cap) {
    step *= cap / s;
    limited = true;
  }
  return step;
}

void relax_step(const RelaxModel& m, RelaxData& d) {
  relax_forces(m, d);
  const int n = static_cast<int>(d.x.size());
  bool limited = false;
  for (int i = 0; i < n; ++i) d.x[static_cast<std::size_t>(i)] += relax_move(m, d, i, limited);
  if (limited) ++d.limited_steps;
}

Curve<3> relax_curve(const RelaxModel& m, const RelaxData& d) {
  Curve<3> out;
  for (std::size_t c = 0; c < m.first.size(); ++c) {
    Polyline<3> pl;
    pl.closed = true;
    pl.points.assign(d.x.begin() + m.first[c], d.x.begin() + m.first[c] + m.count[c]);
    out.components.push_back(std::move(pl));
  }
  return out;
}

Curve<3> relax(const Curve<3>& curve, int iterations, const RelaxModel& params) {
  RelaxModel m = params;
  RelaxData d;
  relax_setup(curve, m, d);
  for (int i = 0; i < iterations; ++i) relax_step(m, d);
  return relax_curve(m, d);
}

}  // namespace s4d
