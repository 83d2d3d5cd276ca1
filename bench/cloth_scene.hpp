// The cloth scene shared by the physics benchmarks and the instruction counter: an n × n grid
// cloth of side 1 m, two corners pinned and carried towards each other so that it falls, folds
// and crumples against itself.
#pragma once
#include <algorithm>
#include <memory>

#include "physics/world.hpp"
#include "shape/grid_mesh.hpp"

namespace s4d::bench {

template <int D>
Surface<D> flat_cloth(int n, double size) {
  Surface<D> s;
  s.grid = Grid{n, n, false, false};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      Vec<D> p = Vec<D>::Zero();
      p[0] = size * (static_cast<double>(i) / (n - 1) - 0.5);
      p[2] = size * (static_cast<double>(j) / (n - 1) - 0.5);  // horizontal: x-z plane, y up
      s.vertices.push_back(p);
    }
  s.triangles = grid_triangles(*s.grid);
  return s;
}

template <int D>
PhysicsParams<D> cloth_params(int n) {
  PhysicsParams<D> p;
  p.gravity[1] = -9.81;
  p.thickness = 0.4 / (n - 1);  // δ: 40 % of the grid step
  p.stiffness = 200;
  p.friction = 0.3;
  return p;
}

// Corners (0,0) and (0,n-1) pinned and carried towards each other, (n-1,·) corners free: the
// cloth falls, folds and crumples against itself. In 4D the pinned corners also move in w.
template <int D>
void drive_corners(World<D>& w, int n, double t) {
  const double u = std::min(1.0, t / 0.6);
  Vec<D> a = w.model().initial[0], b = w.model().initial[n - 1];
  a[2] += 0.35 * u;
  b[2] -= 0.35 * u;
  if constexpr (D == 4) {
    a[3] += 0.1 * u;
    b[3] -= 0.1 * u;
  }
  w.set_target(0, a);
  w.set_target(n - 1, b);
}

template <int D>
std::unique_ptr<World<D>> crumpled_cloth(int n, int settle_steps) {
  ModelBuilder<D> b(cloth_params<D>(n));
  b.add_body(flat_cloth<D>(n, 1.0));
  auto w = std::make_unique<World<D>>(b.build());
  w->pin(0);
  w->pin(n - 1);
  for (int s = 0; s < settle_steps; ++s) {
    drive_corners(*w, n, w->data().time);
    w->step();
  }
  return w;
}

}  // namespace s4d::bench
