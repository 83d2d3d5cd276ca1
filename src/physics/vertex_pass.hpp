// The per-vertex half of a substep: symplectic Euler on every vertex (pinned ones follow their
// targets), the next substep's gravity, tool and damping forces, and on the last substep the
// checks and the paper's motion clamp — one pass over the vertices, where separate
// force / integrate / check / clamp passes read every array three or four times.
#pragma once
#include <cstdint>
#include <span>

#include "core/vec.hpp"

namespace s4d {

// What one pass reads and writes; every span has one entry per vertex.
template <int D>
struct VertexArrays {
  std::span<Vec<D>> x, v;           // positions, m; velocities, m/s (updated)
  std::span<Vec<D>> force;          // this substep's total force in; the next one's start out, N
  std::span<const Vec<D>> x0;       // positions at the start of the step, m
  std::span<const Vec<D>> target;   // where pinned vertices end the step, m
  std::span<const Vec<D>> f_ext;    // tool forces, N
  std::span<const std::uint8_t> pinned;
  std::span<const double> mass, inv_mass;  // kg, 1/kg
};

template <int D>
struct VertexPassParams {
  double h = 0;      // substep, s
  double dt = 0;     // step, s
  double along = 0;  // fraction of the step done at the end of this substep
  bool last = false;  // the step's last substep: check and clamp instead of starting forces
  double limit = 0;  // largest motion of a vertex over the step, m (the clamp)
  Vec<D> gravity = Vec<D>::Zero();  // m/s²
  double damping = 0;               // N·s/m (paper Eq. 2)
};

// Gathered by the last substep's pass.
template <int D>
struct VertexPassResult {
  double fastest2 = 0;                     // largest squared speed of an unpinned vertex (NaN dropped)
  Vec<D> nonfinite = Vec<D>::Zero();       // sum of 0·x + 0·v: NaN once a value is not finite
  int clamps = 0;                          // motions clamped to the limit
};

// Starts a step in one pass: saves every position into x0 (a.x0's storage, the step's start) and
// starts every vertex's force (gravity, tool force and damping).
template <int D>
void start_step(const VertexArrays<D>& a, std::span<Vec<D>> x0, const Vec<D>& gravity, double damping);

// One substep over the vertices, after the springs have added their forces.
template <int D>
void vertex_pass(const VertexArrays<D>& a, const VertexPassParams<D>& p, VertexPassResult<D>& r);

namespace vertex_detail {
// The two R^4 paths, apart so that tests can hold them equal: the portable one (Eigen's SSE2
// pairs) and one point a 256-bit register, the same operations in the same order (no FMA), so
// the bits agree. The AVX one returns false, doing nothing, when the CPU has no AVX.
void pass_portable(const VertexArrays<4>& a, const VertexPassParams<4>& p, VertexPassResult<4>& r);
bool pass_avx(const VertexArrays<4>& a, const VertexPassParams<4>& p, VertexPassResult<4>& r);
}  // namespace vertex_detail

}  // namespace s4d
