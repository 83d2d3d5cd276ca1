// Small worlds shared by the physics tests: flat cloths in R^D and a lone triangle.
#pragma once
#include "physics/world.hpp"
#include "shape/grid_mesh.hpp"

namespace s4d::test {

// An n × n cloth of side `size` in the plane of the first two axes, shifted by `offset`.
template <int D>
Surface<D> flat_cloth(int n, double size, const Vec<D>& offset = Vec<D>::Zero()) {
  Surface<D> s;
  s.grid = Grid{n, n, false, false};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      Vec<D> p = offset;
      p[0] += size * (static_cast<double>(i) / (n - 1) - 0.5);
      p[1] += size * (static_cast<double>(j) / (n - 1) - 0.5);
      s.vertices.push_back(p);
    }
  s.triangles = grid_triangles(*s.grid);
  return s;
}

template <int D>
Surface<D> lone_triangle(double size, const Vec<D>& offset = Vec<D>::Zero()) {
  Surface<D> s;
  Vec<D> a = offset, b = offset, c = offset;
  b[0] += size;
  c[1] += size;
  s.vertices = {a, b, c};
  s.triangles = {{0, 1, 2}};
  return s;
}

template <int D>
PhysicsParams<D> quiet_params() {
  PhysicsParams<D> p;
  p.damping = 0;
  p.spring_damping = 0;
  p.gravity.setZero();
  return p;
}

}  // namespace s4d::test
