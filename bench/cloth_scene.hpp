// The cloth scenes shared by the physics benchmarks, the instruction counter and the live haptics
// benchmark: an n × n grid cloth of side 1 m, lying horizontally (x–z plane, y up), as a Scene built
// by the one world builder (scenario/world_builder). Two corners pinned and carried towards each
// other make it fall, fold and crumple against itself; folded in half onto a pinned lower half it
// rests on itself, the contact-heavy case.
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "io/scene.hpp"
#include "physics/world.hpp"
#include "scenario/world_builder.hpp"
#include "shape/generators.hpp"
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

// The scene's physics: δ is 40 % of the grid step.
inline PhysicsSettings cloth_settings(int n) {
  PhysicsSettings p;
  p.gravity = Vec4(0, -9.81, 0, 0);  // m/s²
  p.thickness = 0.4 / (n - 1);       // m
  p.stiffness = 200;                 // N/m
  p.friction = 0.3;
  return p;
}

template <int D>
PhysicsParams<D> cloth_params(int n) {
  return physics_params<D>(cloth_settings(n));
}

// The flat cloth as a scene. In R^4 it is the "cloth" generator's (xy plane) turned a quarter in yz,
// the same vertices and triangles as flat_cloth<4>; in R^3, where there is no cloth generator, the
// mesh flat_cloth<3> itself.
template <int D>
Scene flat_cloth_scene(int n) {
  Scene s;
  s.description = "a horizontal cloth of side 1 m";
  SceneObject o;
  o.name = "cloth";
  if constexpr (D == 4) {
    o.generator = GeneratorCall{"cloth", {{"n", n}, {"size", 1.0}}};
    Mat<4> m = Mat<4>::Identity();
    m(1, 1) = m(2, 2) = 0;
    m(2, 1) = 1;   // y → z
    m(1, 2) = -1;  // z → −y
    o.placement.matrix = m;
    o.shape = placed(generate("cloth", o.generator->params), o.placement);
  } else {
    o.shape = flat_cloth<D>(n, 1.0);
  }
  s.objects.push_back(std::move(o));
  s.physics = cloth_settings(n);
  return s;
}

template <int D>
std::unique_ptr<World<D>> world_of(const Scene& scene) {
  return std::make_unique<World<D>>(build_world<D>(scene).world);
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
  auto w = world_of<D>(flat_cloth_scene<D>(n));
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

// That cloth (layers 1.6 δ apart) as a scene: a mesh object, there being no generator of it.
template <int D>
Scene folded_cloth_scene(int n) {
  Scene s;
  s.description = "a cloth folded in half onto itself, its lower half pinned flat like a table";
  s.physics = cloth_settings(n);
  SceneObject o;
  o.name = "cloth";
  o.shape = folded_cloth<D>(n, 1.6 * s.physics.thickness);
  s.objects.push_back(std::move(o));
  return s;
}

// The lower half's vertices, pinned like a table (all but the rows next to the fold).
inline std::vector<int> folded_cloth_table(int n) {
  std::vector<int> v;
  for (int i = 0; i < n; ++i)
    if (static_cast<double>(i) / (n - 1) < 0.5 - 1.0 / (n - 1))
      for (int j = 0; j < n; ++j) v.push_back(i * n + j);
  return v;
}

// That cloth, its table pinned: gravity lays the upper half onto it, so every step has a layer of
// resting contacts, the contact-heavy case the free-folding cloth lacks.
template <int D>
std::unique_ptr<World<D>> folded_cloth_on_table(int n) {
  auto w = world_of<D>(folded_cloth_scene<D>(n));
  for (int v : folded_cloth_table(n)) w->pin(v);
  return w;
}

// The upper layer's free edge (row n − 1), held by the hand: pinned and slid along the fold's axis
// (p[2]) 3 cm over 1 s and back over the next, smoothly, from `start` s on. The upper layer slides
// across the lower one: every pair between the layers changes, the case a global bound of the
// motion pays for in full (issue 36).
inline constexpr double kDragDistance = 0.03;  // m
inline constexpr double kDragSeconds = 1.0;   // each way

template <int D>
void grab_free_edge(World<D>& w, int n) {
  for (int j = 0; j < n; ++j) w.pin((n - 1) * n + j, w.positions()[static_cast<std::size_t>((n - 1) * n + j)]);
}

// Where the free edge is carried at time t (grab_free_edge at `start` recorded `grabbed`).
template <int D>
void drag_free_edge(World<D>& w, int n, const std::vector<Vec<D>>& grabbed, double start, double t) {
  const double u = std::clamp((t - start) / kDragSeconds, 0.0, 2.0);
  const double s = u <= 1 ? u * u * (3 - 2 * u) : 1 - (u - 1) * (u - 1) * (3 - 2 * (u - 1));
  for (int j = 0; j < n; ++j) {
    Vec<D> p = grabbed[static_cast<std::size_t>(j)];
    p[2] += kDragDistance * s;
    w.set_target((n - 1) * n + j, p);
  }
}

// The folded cloth settled for `settle` steps, its free edge then grabbed: drag(t) moves it.
template <int D>
struct FoldedDrag {
  std::unique_ptr<World<D>> world;
  int n = 0;
  double start = 0;
  std::vector<Vec<D>> grabbed;
  FoldedDrag(int n_, int settle, bool persistent) : world(folded_cloth_on_table<D>(n_)), n(n_) {
    Model<D> m = world->model();
    m.params.persistent_contacts = persistent;
    world->set_model(std::move(m));
    for (int s = 0; s < settle; ++s) world->step();
    grab_free_edge(*world, n);
    for (int j = 0; j < n; ++j) grabbed.push_back(world->positions()[static_cast<std::size_t>((n - 1) * n + j)]);
    start = world->data().time;
  }
  void step() {
    drag_free_edge(*world, n, grabbed, start, world->data().time);
    world->step();
  }
};

}  // namespace s4d::bench
