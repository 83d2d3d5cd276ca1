// The step of World<D>, as an explicit list of stages: save → forces and integration (substeps)
// → explosion check → motion clamp → collision avoidance → final check (roll back on failure).
#include "physics/world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "physics/vertex_pass.hpp"
#include "proximity/mesh_proximity.hpp"
#include "proximity/smallest_within.hpp"

namespace s4d {

namespace {

// The solvers of a model: only the kind it has cells of is built.
template <int D>
void make_solvers(const Model<D>& m, CollisionSolver<D, 3>& surfaces, CollisionSolver<D, 2>& curves) {
  surfaces = m.curves() ? CollisionSolver<D, 3>() : CollisionSolver<D, 3>(m);
  curves = m.curves() ? CollisionSolver<D, 2>(m) : CollisionSolver<D, 2>();
}

}  // namespace

template <int D>
World<D>::World(Model<D> model) : model_(std::move(model)) {
  make_solvers(model_, surfaces_, curves_);
  const int n = model_.nv;
  data_.x = model_.initial;
  data_.v.assign(n, Vec<D>::Zero());
  data_.f_ext.assign(n, Vec<D>::Zero());
  data_.target = model_.initial;
  data_.pinned.assign(n, 0);
  data_.force.assign(n, Vec<D>::Zero());
  data_.x0 = data_.x;
}

template <int D>
int World<D>::integrate(double dt) {
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
  const VertexArrays<D> arrays{data_.x,      data_.v,      data_.force, data_.x0,
                               data_.target, data_.f_ext,  data_.pinned, m.mass,
                               m.inv_mass};
  VertexPassParams<D> pass;
  pass.h = h;
  pass.dt = dt;
  // The paper clamps the motion of a frame to δ unless told otherwise.
  pass.limit = m.params.max_step_motion > 0 ? m.params.max_step_motion : m.params.thickness;
  pass.gravity = m.params.gravity;
  pass.damping = m.params.damping;
  VertexPassResult<D> result;
  start_step<D>(arrays, data_.x0, pass.gravity, pass.damping);
  for (int s = 0; s < n; ++s) {
    add_spring_forces<D>(m, data_.x, data_.v, data_.force);
    pass.along = static_cast<double>(s + 1) / n;
    pass.last = s + 1 == n;
    vertex_pass<D>(arrays, pass, result);
  }
  const bool ok = (result.nonfinite.array() == 0.0).all() &&
                  std::sqrt(result.fastest2) <= m.params.max_speed;
  return ok ? result.clamps : -1;
}

template <int D>
void World<D>::step(double dt) {
  if (!(dt > 0) || !std::isfinite(dt)) dt = model_.params.time_step;
  const int clamps = integrate(dt);  // saves x into x0 first
  bool ok = clamps >= 0;
  if (ok) {
    data_.warnings.speed_clamps += clamps;
    const CollisionStats cs = model_.curves() ? curves_.solve(model_, data_.x0, data_.x, data_.v, data_.pinned, dt)
                                              : surfaces_.solve(model_, data_.x0, data_.x, data_.v, data_.pinned, dt);
    data_.last_contacts = cs.contacts;
    data_.warnings.ccd_freezes += cs.frozen;
    if (cs.global_freeze) ++data_.warnings.global_freezes;
    ok = !cs.nonfinite;
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
void World<D>::set_model(Model<D> model) {
  if (model.nv != model_.nv)
    throw Error("physics: set_model needs " + std::to_string(model_.nv) + " vertices, got " +
                std::to_string(model.nv));
  model_ = std::move(model);
  make_solvers(model_, surfaces_, curves_);
}

template <int D>
void World<D>::rest_here() {
  for (Spring& s : model_.springs) s.rest = (data_.x[s.b] - data_.x[s.a]).norm();
  if constexpr (D == 4) repack_rest_lengths(model_.springs, model_.spring_groups);
}

template <int D>
void World<D>::stop() {
  std::fill(data_.v.begin(), data_.v.end(), Vec<D>::Zero());
}

template <int D>
std::uint64_t World<D>::state_hash() const {
  std::uint64_t h = 14695981039346656037ull;
  auto add = [&h](const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  add(data_.x.data(), data_.x.size() * sizeof(Vec<D>));
  add(data_.v.data(), data_.v.size() * sizeof(Vec<D>));
  add(data_.pinned.data(), data_.pinned.size());
  add(&data_.time, sizeof data_.time);
  add(&data_.steps, sizeof data_.steps);
  return h;
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

namespace {

template <int D, int K>
double smallest_gap(const std::vector<std::array<int, K>>& cells, std::span<const Vec<D>> x, double search) {
  SelfProximity<D, K> prox(std::vector<Cell<K>>(cells.begin(), cells.end()));
  std::vector<ProximityPair<D>> pairs;
  return smallest_within(search, [&](double within) {
    prox.pairs_within(x, within, pairs);
    double d = std::numeric_limits<double>::infinity();
    for (const auto& p : pairs) d = std::min(d, p.closest.distance);
    return d;
  });
}

}  // namespace

template <int D>
double World<D>::min_separation(double search) const {
  if (model_.curves()) return smallest_gap<D, 2>(model_.segments, data_.x, search);
  return smallest_gap<D, 3>(model_.triangles, data_.x, search);
}

template class World<2>;
template class World<3>;
template class World<4>;

}  // namespace s4d
