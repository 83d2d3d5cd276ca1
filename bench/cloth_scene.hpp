// The cloth scene shared by the physics benchmarks and the instruction counter: an n × n grid
// cloth of side 1 m, two corners pinned and carried towards each other so that it falls, folds
// and crumples against itself.
#pragma once
#include <algorithm>
#include <cmath>
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

// A cloth folded in half onto itself (layers `gap` apart, joined by a tight fold).
template <int D>
Surface<D> folded_cloth(int n, double gap) {
  Surface<D> s = flat_cloth<D>(n, 1.0);
  const double r = gap / 2, fold = 0.5, pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = static_cast<double>(i) / (n - 1);  // arc length along the cloth
      Vec<D>& p = s.vertices[static_cast<std::size_t>(i) * n + j];
      if (a <= fold) {
        p[0] = a - 0.5;
        p[1] = 0;
      } else if (a < fold + pi * r) {
        const double th = (a - fold) / r;
        p[0] = fold - 0.5 + r * std::sin(th);
        p[1] = r * (1 - std::cos(th));
      } else {
        p[0] = fold - 0.5 - (a - fold - pi * r);
        p[1] = gap;
      }
    }
  return s;
}

// That cloth (layers 1.6 δ apart), its lower half pinned flat like a table: gravity lays the
// upper half onto it, so every step has a layer of resting contacts, the contact-heavy case the
// free-folding cloth lacks.
template <int D>
std::unique_ptr<World<D>> folded_cloth_on_table(int n) {
  const PhysicsParams<D> params = cloth_params<D>(n);
  ModelBuilder<D> b(params);
  b.add_body(folded_cloth<D>(n, 1.6 * params.thickness));
  auto w = std::make_unique<World<D>>(b.build());
  for (int i = 0; i < n; ++i)
    if (static_cast<double>(i) / (n - 1) < 0.5 - 1.0 / (n - 1))
      for (int j = 0; j < n; ++j) w->pin(i * n + j);
  return w;
}

}  // namespace s4d::bench
