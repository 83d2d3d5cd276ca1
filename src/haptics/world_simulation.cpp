// The physics World as a rubber-band target: projection into the device space and force lifting.
#include "haptics/world_simulation.hpp"

#include "core/error.hpp"

namespace s4d {

template <int D>
WorldSimulation<D>::WorldSimulation(World<D> world, const Frame<D>& frame, double scale, const Vec3& offset)
    : world_(std::move(world)), frame_(frame), scale_(scale), offset_(offset) {
  if (!(scale > 0) || !std::isfinite(scale)) throw Error("world simulation: scale must be positive");
  zero_v_.assign(world_.vertex_count(), Vec<D>::Zero());
}

template <int D>
void WorldSimulation<D>::set_external_force(int v, const Vec3& f) {
  if (forced_ >= 0 && forced_ != v) world_.set_external_force(forced_, Vec<D>::Zero());
  forced_ = -1;
  if (v < 0 || v >= world_.vertex_count()) return;
  // A 3D device force acts within the shadow: view coordinates (f, 0 depth), rotated back to world.
  Vec<D> q = Vec<D>::Zero();
  q.template head<D - 1>() = scale_ * f.template head<D - 1>();
  world_.set_external_force(v, frame_.to_world(q));
  forced_ = v;
}

template <int D>
void WorldSimulation<D>::reset() {
  set_external_force(-1, Vec3::Zero());
  world_.set_state(world_.model().initial, zero_v_);
}

template <int D>
void WorldSimulation<D>::copy_points(std::span<double> out) const {
  const auto x = world_.positions();
  const std::size_t n = std::min(x.size(), out.size() / D);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < D; ++k) out[i * D + k] = x[i][k];
}

template class WorldSimulation<3>;
template class WorldSimulation<4>;

}  // namespace s4d
