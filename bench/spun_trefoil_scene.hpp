// The spun trefoil the physics benchmarks step: the scenario's sphere (n = 64, m = 12, 746
// vertices) with its two poles pulled apart by 2 N, after 500 steps (mid-deformation). One
// builder for physics_bench's BM_SpunTrefoilStep and step_times, so both time the same state.
#pragma once
#include "io/scene.hpp"
#include "physics/world.hpp"
#include "scenario/world_builder.hpp"
#include "shape/generators.hpp"

namespace s4d::bench {

inline World<4> pulled_spun_trefoil() {
  Scene scene;
  SceneObject o;
  o.name = "sphere";
  o.generator = GeneratorCall{"spun-trefoil", {{"n", 64}, {"m", 12}}};
  o.shape = generate("spun-trefoil", o.generator->params);
  scene.objects.push_back(std::move(o));
  scene.physics.thickness = 0.03;  // m
  scene.physics.stiffness = 300;   // N/m
  World<4> w = build_world<4>(scene).world;
  w.set_external_force(0, Vec4(-2, 0, 0, 0));
  w.set_external_force(w.vertex_count() - 1, Vec4(2, 0, 0, 0));
  for (int i = 0; i < 500; ++i) w.step();
  return w;
}

}  // namespace s4d::bench
