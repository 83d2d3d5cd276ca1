// The one world builder: a scene's surfaces (or, in a scene without surfaces, its curves: a knot
// is a chain in World<3>) become the bodies of one World<D> with the scene's physics, used by
// scenario runs, the live session of the window and the benchmarks alike.
#pragma once
#include <span>
#include <vector>

#include "io/scene.hpp"
#include "physics/world.hpp"

namespace s4d {

// The dimension of a scene's surfaces: 4 when any lies in R^4, 3 when all lie in R^3, 0 when the
// scene has no surface.
int surface_dimension(const Scene& scene);
// Whether the scene's bodies are its curves: it has curves and no surface. (With surfaces, curves
// are drawn but not simulated: a world holds one kind of cell.)
bool curves_are_bodies(const Scene& scene);
// The dimension the bodies are simulated in: 4 when any lies in R^4 (those of R^3 join it at w = 0),
// 3 when all lie in R^3, 0 when the scene has nothing to simulate.
int simulation_dimension(const Scene& scene);
// Whether scene object o is a body of the world build_world makes.
bool is_body(const Scene& scene, const SceneObject& object);

// Where each scene object's vertices are in the world build_world makes: first[o] (-1 for an
// object that is no body) and count[o]; bodies follow the scene's order, a curve's vertices its
// components' points in order.
void body_vertex_ranges(const Scene& scene, std::vector<int>& first, std::vector<int>& count);

// The physics layer's parameters for a scene's settings (gravity truncated to D). Throws
// s4d::Error for an unknown integrator name.
template <int D>
PhysicsParams<D> physics_params(const PhysicsSettings& settings);

template <int D>
struct SceneWorld {
  World<D> world;
  std::vector<int> first;  // per scene object: its first vertex in the world, -1 for no body
  std::vector<int> count;  // per scene object: its vertex count (0 for no body)
  std::vector<Body<D>> bodies;     // per body, as built (grids kept): what a rebuild starts from
  std::vector<int> body_object;    // per body, its scene object

  // The object whose vertex v is, or -1.
  int object_of_vertex(int v) const;
  // A new model for `settings`, built around the world's current positions (so the contact
  // layer fits the gaps of now), keeping the state, pins and the first initial positions.
  // Throws s4d::Error like build_world; the world is unchanged then.
  void apply_settings(const PhysicsSettings& settings);
};

// Throws s4d::Error with a sentence a user can act on: nothing to simulate, a mesh with an edge
// shared by more than two triangles, a surface or curve that already meets itself, absurd
// parameters.
template <int D>
SceneWorld<D> build_world(const Scene& scene);

// The bodies' shapes with the world's positions `x` (nv × D): a body of R^3 in a world of R^4 is
// lifted to R^4 (it may have left w = 0). For drawing and saving.
template <int D>
void copy_positions_into(const SceneWorld<D>& sw, std::span<const Vec<D>> x, Scene& scene);
// The same from a flat state of any dimension (nv × dim values, a snapshot's) and the ranges
// body_vertex_ranges gives; points beyond the end of `x` are left as they are.
void copy_positions_into(std::span<const int> first, std::span<const int> count, std::span<const double> x, int dim,
                         Scene& scene);

}  // namespace s4d
