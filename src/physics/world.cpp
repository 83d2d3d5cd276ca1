// The step of World<D>, as an explicit list of stages: save → forces and integration (substeps)
// → explosion check → motion clamp → collision avoidance → final check (roll back on failure).
#include "physics/world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "proximity/mesh_proximity.hpp"

namespace s4d {

template <int D>
World<D>::World(Model<D> model) : model_(std::move(model)), collision_(model_) {
  const int n = model_.nv;
  data_.x = model_.initial;
  data_.v.assign(n, Vec<D>::Zero());
  data_.f_ext.assign(n, Vec<D>::Zero());
  data_.target = model_.initial;
  data_.pinned.assign(n, 0);
  data_.force.assign(n, Vec<D>::Zero());
  data_.x0 = data_.x;
  data_.v0 = data_.v;
}

template <int D>
void World<D>::accumulate_forces() {
  const Model<D>& m = model_;
  for (int i = 0; i < m.nv; ++i)
    data_.force[i] = m.mass[i] * m.params.gravity + data_.f_ext[i] - m.params.damping * data_.v[i];
  add_spring_forces<D>(m, data_.x, data_.v, data_.force);
}

template <int D>
bool World<D>::integrate(double dt) {
  const Model<D>& m = model_;
  int n = m.substeps(dt);
  if (m.params.beta > 0 && m.params.integrator == Integrator::kSymplecticEuler) {
    // A stiffening spring (β > 0) has tangent stiffness (1+β) k |e|^β: scale the bound by the
    // largest one in the current state.
    double scale = 1;
    for (const Spring& s : m.springs) {
      const double e = std::abs((data_.x[s.b] - data_.x[s.a]).norm() - s.rest);
      scale = std::max(scale, (1 + m.params.beta) * std::pow(e, m.params.beta));
    }
    n = std::clamp(static_cast<int>(std::ceil(n * std::sqrt(scale))), 1, m.params.max_substeps);
  }
  data_.last_substeps = n;
  const double h = dt / n;
  const double max_speed = m.params.max_speed;
  for (int s = 0; s < n; ++s) {
    accumulate_forces();
    const double along = static_cast<double>(s + 1) / n;
    for (int i = 0; i < m.nv; ++i) {
      if (data_.pinned[i]) {
        data_.x[i] = data_.x0[i] + along * (data_.target[i] - data_.x0[i]);
        data_.v[i] = (data_.target[i] - data_.x0[i]) / dt;
        continue;
      }
      // Paper Eq. 4: a = F/m, v += h a, x += h v (the new velocity moves the position).
      data_.v[i] += (h * m.inv_mass[i]) * data_.force[i];
      data_.x[i] += h * data_.v[i];
    }
  }
  // Pinned vertices follow their targets at any speed; a NaN squared norm is dropped by std::max,
  // but not by all_finite.
  double fastest2 = 0;
  for (int i = 0; i < m.nv; ++i)
    fastest2 = std::max(fastest2, data_.pinned[i] ? 0.0 : data_.v[i].squaredNorm());
  return all_finite<D>(data_.x) && all_finite<D>(data_.v) && std::sqrt(fastest2) <= max_speed;
}

template <int D>
void World<D>::clamp_motion(double dt) {
  // The paper clamps any motion between two frames to δ, which keeps contacts from being skipped
  // between proximity queries; the fail-safe would catch them, at the price of a freeze.
  const double limit =
      model_.params.max_step_motion > 0 ? model_.params.max_step_motion : model_.params.thickness;
  for (int i = 0; i < model_.nv; ++i) {
    const Vec<D> d = data_.x[i] - data_.x0[i];
    if (!(d.squaredNorm() > limit * limit)) continue;  // the common case, without a square root
    const double len = d.norm();
    if (len > limit) {
      data_.x[i] = data_.x0[i] + d * (limit / len);
      if (!data_.pinned[i]) data_.v[i] *= limit / len;
      ++data_.warnings.speed_clamps;
    }
  }
}

template <int D>
void World<D>::step(double dt) {
  if (!(dt > 0) || !std::isfinite(dt)) dt = model_.params.time_step;
  std::copy(data_.x.begin(), data_.x.end(), data_.x0.begin());
  std::copy(data_.v.begin(), data_.v.end(), data_.v0.begin());
  bool ok = integrate(dt);
  if (ok) {
    clamp_motion(dt);
    const CollisionStats cs = collision_.solve(model_, data_.x0, data_.x, data_.v, data_.pinned, dt);
    data_.last_contacts = cs.contacts;
    data_.warnings.ccd_freezes += cs.frozen;
    if (cs.global_freeze) ++data_.warnings.global_freezes;
    ok = all_finite<D>(data_.x) && all_finite<D>(data_.v);
  }
  if (!ok) {
    // Roll back to the safe start and drop the momentum that blew up: repeating the same step
    // would only explode again.
    std::copy(data_.x0.begin(), data_.x0.end(), data_.x.begin());
    std::fill(data_.v.begin(), data_.v.end(), Vec<D>::Zero());
    ++data_.warnings.rollbacks;
  }
  data_.time += dt;
  ++data_.steps;
}

template <int D>
void World<D>::set_external_force(int vertex, const Vec<D>& force) {
  if (vertex < 0 || vertex >= model_.nv || !force.allFinite()) {
    ++data_.warnings.rejected_inputs;
    return;
  }
  data_.f_ext[vertex] = force;
}

template <int D>
void World<D>::clear_external_forces() {
  std::fill(data_.f_ext.begin(), data_.f_ext.end(), Vec<D>::Zero());
}

template <int D>
void World<D>::pin(int vertex) {
  if (vertex < 0 || vertex >= model_.nv) {
    ++data_.warnings.rejected_inputs;
    return;
  }
  pin(vertex, data_.x[vertex]);
}

template <int D>
void World<D>::pin(int vertex, const Vec<D>& target) {
  if (vertex < 0 || vertex >= model_.nv || !target.allFinite()) {
    ++data_.warnings.rejected_inputs;
    return;
  }
  data_.pinned[vertex] = 1;
  data_.target[vertex] = target;
  data_.v[vertex].setZero();
}

template <int D>
void World<D>::set_target(int vertex, const Vec<D>& target) {
  if (vertex < 0 || vertex >= model_.nv || !target.allFinite()) {
    ++data_.warnings.rejected_inputs;
    return;
  }
  data_.target[vertex] = target;
}

template <int D>
void World<D>::unpin(int vertex) {
  if (vertex < 0 || vertex >= model_.nv) return;
  data_.pinned[vertex] = 0;
}

template <int D>
void World<D>::set_state(std::span<const Vec<D>> x, std::span<const Vec<D>> v) {
  if (x.size() != static_cast<std::size_t>(model_.nv) || v.size() != x.size())
    throw Error("physics: set_state needs " + std::to_string(model_.nv) + " positions and velocities");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!x[i].allFinite() || !v[i].allFinite()) throw Error("physics: set_state got a non-finite value");
  std::copy(x.begin(), x.end(), data_.x.begin());
  std::copy(v.begin(), v.end(), data_.v.begin());
}

template <int D>
double World<D>::kinetic_energy() const {
  double e = 0;
  for (int i = 0; i < model_.nv; ++i) e += 0.5 * model_.mass[i] * data_.v[i].squaredNorm();
  return e;
}

template <int D>
double World<D>::spring_energy() const {
  const double beta = model_.params.beta;
  double e = 0;
  for (const Spring& s : model_.springs) {
    const double ext = std::abs((data_.x[s.b] - data_.x[s.a]).norm() - s.rest);
    e += s.k * std::pow(ext, 2 + beta) / (2 + beta);
  }
  return e;
}

template <int D>
double World<D>::gravity_energy() const {
  double e = 0;
  for (int i = 0; i < model_.nv; ++i) e -= model_.mass[i] * model_.params.gravity.dot(data_.x[i]);
  return e;
}

template <int D>
double World<D>::min_separation(double search) const {
  std::vector<Cell<3>> cells(model_.triangles.begin(), model_.triangles.end());
  SelfProximity<D, 3> prox(std::move(cells));
  std::vector<ProximityPair<D>> pairs;
  prox.pairs_within(data_.x, search, pairs);
  double d = std::numeric_limits<double>::infinity();
  for (const auto& p : pairs) d = std::min(d, p.closest.distance);
  return d;
}

template class World<2>;
template class World<3>;
template class World<4>;

}  // namespace s4d
