// World<D>: the 4D (and 3D) mass-spring world the haptic loop steps at 1 kHz: springs, gravity,
// damping, pins and pulled vertices, tool forces, collision avoidance that never lets surfaces
// (or curves: a knot is a chain in World<3>) pass through each other, and roll-back of exploding
// steps. A step allocates nothing.
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "physics/collision.hpp"
#include "physics/model.hpp"
#include "physics/spring_forces.hpp"

namespace s4d {

// Numerical trouble is counted here, never thrown (see STYLE.md, MuJoCo's warnings).
struct PhysicsWarnings {
  std::int64_t rollbacks = 0;        // steps undone because a value went non-finite or too fast
  std::int64_t speed_clamps = 0;     // vertex motions clamped to max_step_motion
  std::int64_t ccd_freezes = 0;      // vertices stopped by the continuous fail-safe
  std::int64_t global_freezes = 0;   // steps where the fail-safe stopped every vertex
  std::int64_t rejected_inputs = 0;  // non-finite forces or targets ignored
};

// Everything that changes during a run, sized once from the model.
template <int D>
struct Data {
  std::vector<Vec<D>> x;            // nv × D, positions, m
  std::vector<Vec<D>> v;            // nv × D, velocities, m/s
  std::vector<Vec<D>> f_ext;        // nv × D, external (tool) forces, N; kept until changed
  std::vector<Vec<D>> target;       // nv × D, where a pinned vertex must be at the end of a step
  std::vector<std::uint8_t> pinned; // nv, 1 = position prescribed by target (kinematic)
  std::vector<Vec<D>> force;        // nv × D, scratch: total force of the current substep
  std::vector<Vec<D>> x0;           // nv × D, positions at the start of the step (the fail-safe's
                                    // safe state, and where a roll-back returns)
  double time = 0;                  // s
  std::int64_t steps = 0;
  int last_substeps = 0;            // substeps used by the last step
  int last_contacts = 0;            // pairs handled by repulsion in the last step
  PhysicsWarnings warnings;
};

template <int D>
class World {
 public:
  // Takes the model; state starts at rest at model.initial.
  explicit World(Model<D> model);

  const Model<D>& model() const { return model_; }
  // Broad-phase runs of the collision query so far (it reuses its pair list while motion is small).
  long long broad_phase_runs() const { return surfaces_.broad_phase_runs() + curves_.broad_phase_runs(); }
  // The persistent contacts' work so far, surfaces' and curves' (physics/contact_cache.hpp).
  ContactCacheStats contact_stats() const {
    ContactCacheStats s = surfaces_.contact_stats();
    return s += curves_.contact_stats();
  }
  long long exact_distances() const { return surfaces_.exact_distances() + curves_.exact_distances(); }
  const Data<D>& data() const { return data_; }
  int vertex_count() const { return model_.nv; }
  std::span<const Vec<D>> positions() const { return data_.x; }
  std::span<const Vec<D>> velocities() const { return data_.v; }

  // Advances by dt seconds (params.time_step when dt <= 0). Never throws, never allocates.
  void step(double dt = 0);

  // Tool input (haptic thread). Non-finite values are ignored and counted.
  void set_external_force(int vertex, const Vec<D>& force);
  void clear_external_forces();
  // A pinned vertex follows its target (kinematic, infinite mass). Pinning keeps it where it is.
  void pin(int vertex);
  void pin(int vertex, const Vec<D>& target);
  void set_target(int vertex, const Vec<D>& target);
  void unpin(int vertex);
  bool is_pinned(int vertex) const { return data_.pinned[vertex] != 0; }

  // Replaces the state (e.g. restoring a snapshot); sizes must match. Throws s4d::Error.
  void set_state(std::span<const Vec<D>> x, std::span<const Vec<D>> v);
  // The simulated time goes on from a restored session's (s; non-finite or negative is ignored).
  void set_time(double seconds) {
    if (std::isfinite(seconds) && seconds >= 0) data_.time = seconds;
  }
  // Replaces the model (new parameters, a contact layer fitted to the current gaps) keeping the
  // state, pins, targets and tool forces; the vertex count must match. Throws s4d::Error.
  void set_model(Model<D> model);
  // Every spring's rest length becomes its length now: the shape is kept as it was left (a knot
  // edited like clay, not pulled back to where it was). Allocates nothing.
  void rest_here();
  // Stops every vertex where it is (velocities zero).
  void stop();
  // FNV-1a over the bits of positions, velocities, pins, time and step count: equal hashes
  // after N steps mean the same run (Box2D's determinism test).
  std::uint64_t state_hash() const;

  // Energies, J: kinetic, spring potential (∫ of Eq. 1), gravity potential (relative to x = 0).
  double kinetic_energy() const;
  double spring_energy() const;
  double gravity_energy() const;
  double energy() const { return kinetic_energy() + spring_energy() + gravity_energy(); }
  // Smallest distance between two cells (triangles, or segments of curves) sharing no vertex
  // (infinity if none are within `search`), using the proximity kernel. For tests and metrics;
  // allocates.
  double min_separation(double search) const;

 private:
  // Saves x into x0, then substeps of forces and integration, then the paper's clamp of each
  // vertex's motion to max_step_motion (δ by default). Returns the motions clamped, or -1 when the
  // result is non-finite or too fast.
  int integrate(double dt);

  Model<D> model_;
  Data<D> data_;
  // One of the two has cells (ModelBuilder refuses a mix); the other's solve returns at once.
  CollisionSolver<D, 3> surfaces_;
  CollisionSolver<D, 2> curves_;
};

}  // namespace s4d
