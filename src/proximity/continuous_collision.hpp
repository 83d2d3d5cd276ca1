// Continuous collision of two simplices whose vertices move linearly over one step: the earliest
// time at which they come within a thickness, by conservative advancement on exact distances.
#pragma once
#include <algorithm>

#include "proximity/closest_points.hpp"

namespace s4d {

struct CcdOptions {
  double thickness = 0;          // δ >= 0, scene units: contact means distance <= δ
  // Stop (and report contact) once the next provably safe advance is shorter than this fraction
  // of the step: the reported time is then at most this early, never late.
  double time_tolerance = 1e-6;
  int max_iterations = 200;      // past this, contact is reported at the current time (safe side)
  double t_max = 1;              // search [0, t_max] only (mesh queries pass the best time so far)
};

template <int D>
struct CcdResult {
  bool hit = false;              // contact within [0, t_max]
  double t = 1;                  // earliest contact time when hit (conservative: never later)
  ClosestPoints<D> at_t;         // closest points at time t (when hit)
  int iterations = 0;            // distance evaluations made
};

template <int D, int K>
inline Simplex<D, K> lerp_simplex(const Simplex<D, K>& s0, const Simplex<D, K>& s1, double t) {
  Simplex<D, K> s;
  for (int i = 0; i < K; ++i) s[i] = s0[i] + t * (s1[i] - s0[i]);
  return s;
}

// Largest speed of p(t) - q(t) over any pair of points of the two moving simplices. Every point
// moves with a convex combination of its simplex's vertex velocities, so the relative velocity is
// a convex combination of the v_i - w_j: the distance is Lipschitz in t with this constant.
template <int D, int KA, int KB>
inline double relative_speed_bound(const Simplex<D, KA>& a0, const Simplex<D, KA>& a1,
                                   const Simplex<D, KB>& b0, const Simplex<D, KB>& b1) {
  double l2 = 0;
  for (int i = 0; i < KA; ++i)
    for (int j = 0; j < KB; ++j)
      l2 = std::max(l2, ((a1[i] - a0[i]) - (b1[j] - b0[j])).squaredNorm());
  return std::sqrt(l2);
}

// Earliest t in [0, t_max] with dist(A(t), B(t)) <= δ, where every vertex moves linearly from its
// position in *0 to its position in *1. Conservative: the distance stays above δ on every time
// interval skipped (Lipschitz bound above), so a contact is never missed; the reported time may
// be early by at most time_tolerance (or wherever the iteration cap stopped it). Works in any D.
template <int D, int KA, int KB>
CcdResult<D> earliest_contact(const Simplex<D, KA>& a0, const Simplex<D, KA>& a1,
                              const Simplex<D, KB>& b0, const Simplex<D, KB>& b1,
                              const CcdOptions& opt = {}) {
  CcdResult<D> r;
  const double speed = relative_speed_bound<D, KA, KB>(a0, a1, b0, b1);
  const double delta = std::max(0.0, opt.thickness);
  double t = 0;
  for (;;) {
    const ClosestPoints<D> cp =
        closest_points<D, KA, KB>(lerp_simplex<D, KA>(a0, a1, t), lerp_simplex<D, KB>(b0, b1, t));
    ++r.iterations;
    const double gap = cp.distance - delta;
    if (!(gap > 0) || r.iterations >= opt.max_iterations) {  // touching, or NaN: report (safe side)
      r.hit = true;
      r.t = t;
      r.at_t = cp;
      return r;
    }
    if (!(speed > 0)) return r;  // rigidly translating together: the distance never changes
    const double advance = gap / speed;
    if (t + advance > opt.t_max) return r;
    if (advance < opt.time_tolerance) {
      r.hit = true;
      r.t = t;
      r.at_t = cp;
      return r;
    }
    t += advance;
  }
}

}  // namespace s4d
