// The paper's force laws (Eq. 1-3, the navigation suggestion of 4.3.1, the rubber band of 5.1.4)
// and virtual coupling, each a small pure function of R^D so it can be tested against its formula.
#pragma once
#include <algorithm>
#include <cmath>

#include "core/vec.hpp"

namespace s4d {

// Eq. 1, the sticky stylus: F_m = H |N|^(1+beta) N^ with N = C' - C, C' the projection of the proxy C
// on the shadow plane or surface. Motion along the tangent leaves N, hence F, unchanged.
// H: N/m^(1+beta); beta = 0 is a linear spring.
template <int D>
Vec<D> sticky_force(const Vec<D>& c, const Vec<D>& c_projected, double h, double beta) {
  const Vec<D> n = c_projected - c;
  const double len = n.norm();
  if (!(len > 0)) return Vec<D>::Zero();
  return (h * std::pow(len, beta)) * n;  // = H |N|^(1+beta) N/|N|
}

// Eq. 2, damping: F_d = -K_d V. K_d: N s/m.
template <int D>
Vec<D> damping_force(const Vec<D>& v, double k_d) {
  return -k_d * v;
}

// The component of V along the unit direction `u` (the paper's "radial velocity"): damping it smooths
// the spring of Eq. 1 without resisting the free tangential motion.
template <int D>
Vec<D> radial_velocity(const Vec<D>& v, const Vec<D>& u) {
  return v.dot(u) * u;
}

struct RepulsionParams {
  double h = 1e-4;      // N m^(1+beta)
  double beta = 0;
  double s_min = 1e-3;  // m, below this S is held constant so the force stays bounded as S -> 0
  double max_force = 3;  // N, cap of the repulsion alone (the safety layer clamps the total again)
  double range = 0.02;   // m, no repulsion beyond this distance
};

// Eq. 3, repulsion from an impending collision: F_r = -H S^(-1-beta) V^, with S the distance (m) to
// the collision and V the radial velocity towards it. `to_obstacle` is the unit direction from the
// probe to the collision point. Only approach is resisted (moving away is free), S is floored at
// s_min and the magnitude capped, so the law is bounded near S -> 0.
template <int D>
Vec<D> repulsion_force(double s, const Vec<D>& to_obstacle, const Vec<D>& v, const RepulsionParams& p) {
  const double approach = v.dot(to_obstacle);
  if (!(approach > 0) || !(s < p.range)) return Vec<D>::Zero();
  const double s_eff = std::max(s, p.s_min);
  const double mag = std::min(p.h * std::pow(s_eff, -1 - p.beta), p.max_force);
  return -mag * to_obstacle;  // V^ of the radial velocity is to_obstacle itself
}

struct DampedSpring {
  double k = 200;  // N/m
  double b = 1;    // N s/m, damps the velocity along the spring only
};

// 4.3.1, the navigation force suggestion: C_p = C + V/R predicted one servo period ahead, C_p' its
// projection on the curve or surface image (`project`: Vec<D> -> Vec<D>), then a damped spring from
// C to C_p'. Only the velocity along the spring is damped, so gliding along the image stays free.
template <int D, typename Projector>
Vec<D> navigation_force(const Vec<D>& c, const Vec<D>& v, double rate_hz, Projector&& project,
                        const DampedSpring& spring) {
  const Vec<D> c_pred = c + v / rate_hz;
  const Vec<D> d = project(c_pred) - c;
  const double len = d.norm();
  if (!(len > 0)) return Vec<D>::Zero();
  const Vec<D> u = d / len;
  return spring.k * d - spring.b * v.dot(u) * u;
}

// Force on each end of a two-ended damped spring of rest length zero.
template <int D>
struct SpringPair {
  Vec<D> on_a;  // N
  Vec<D> on_b;  // N, = -on_a (action and reaction)
};

// 5.1.4, the rubber band: a damped zero-length spring from the pointer (a) to the picked vertex (b);
// the pointer feels on_a and the simulation receives on_b as the vertex's external force.
template <int D>
SpringPair<D> rubber_band_force(const Vec<D>& pointer, const Vec<D>& pointer_v, const Vec<D>& vertex,
                                const Vec<D>& vertex_v, const DampedSpring& spring) {
  const Vec<D> f = spring.k * (vertex - pointer) + spring.b * (vertex_v - pointer_v);
  return {f, -f};
}

// Virtual coupling between a device (a) and the proxy or tool it drives (b): the same damped spring,
// which bounds the stiffness the device ever sees to spring.k whatever the simulation does.
template <int D>
SpringPair<D> virtual_coupling_force(const Vec<D>& device, const Vec<D>& device_v, const Vec<D>& proxy,
                                     const Vec<D>& proxy_v, const DampedSpring& spring) {
  return rubber_band_force<D>(device, device_v, proxy, proxy_v, spring);
}

// Closest point of the plane through `origin` with unit normal `normal` (the shadow plane).
template <int D>
Vec<D> project_on_plane(const Vec<D>& p, const Vec<D>& origin, const Vec<D>& normal) {
  return p - (p - origin).dot(normal) * normal;
}

// Closest point of the polyline `pts` (#pts x D, open; closed adds the last-to-first segment) to p:
// the curve image used by navigation. Returns p itself for an empty polyline.
template <int D, typename Points>
Vec<D> project_on_polyline(const Vec<D>& p, const Points& pts, bool closed) {
  const int n = static_cast<int>(pts.size());
  if (n == 0) return p;
  Vec<D> best = pts[0];
  double best_d2 = (p - best).squaredNorm();
  const int segs = closed ? n : n - 1;
  for (int i = 0; i < segs; ++i) {
    const Vec<D>& a = pts[i];
    const Vec<D>& b = pts[(i + 1) % n];
    const Vec<D> ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const Vec<D> q = a + t * ab;
    const double d2 = (p - q).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best = q;
    }
  }
  return best;
}

}  // namespace s4d
