// Spring and damping forces (paper Eq. 1 with relative-velocity damping along each spring): the
// hot loop of every substep.
#pragma once
#include <span>
#include <vector>

#include "physics/model.hpp"

namespace s4d {

// Spring and damping forces of the state (x, v) added into force (for the world, tests and tools).
template <int D>
void add_spring_forces(const Model<D>& model, std::span<const Vec<D>> x,
                       std::span<const Vec<D>> v, std::span<Vec<D>> force);

// The whole groups of four springs, packed for the R^4 AVX kernel (Model::spring_groups).
std::vector<SpringGroup4> pack_spring_groups(std::span<const Spring> springs);
// The groups' rest lengths from their springs' (after the springs were given new ones), in place.
void repack_rest_lengths(std::span<const Spring> springs, std::span<SpringGroup4> groups);

namespace spring_detail {
// The two kernels of linear springs (β = 0) in R^4, apart so that tests can hold them equal.
// Portable: one spring at a time (Eigen's SSE2 pairs).
void linear_springs_portable(std::span<const Spring> springs, double kd,
                             std::span<const Vec<4>> x, std::span<const Vec<4>> v,
                             std::span<Vec<4>> force);
// Four springs at a time in 256-bit registers, with the same operations in the same order, so
// the forces are bit for bit those of the portable kernel (a run is reproducible across
// machines). `groups` is pack_spring_groups(springs). False, and nothing done, when the CPU has
// no AVX.
bool linear_springs_avx(std::span<const Spring> springs, std::span<const SpringGroup4> groups,
                        double kd, std::span<const Vec<4>> x, std::span<const Vec<4>> v,
                        std::span<Vec<4>> force);
}  // namespace spring_detail

}  // namespace s4d
