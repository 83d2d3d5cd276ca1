// The slice of a scene by the hyperplane w = c of its 4D frame: every surface of R^4 cut at the
// level, the pieces together one link of R^3 drawn on the shadow (shape/level_set.hpp), with the
// scene's critical levels. What the Slice panel, `shadow4d slice` and its movie sheet show.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "io/scene.hpp"
#include "shape/critical_levels.hpp"

namespace s4d {

struct SceneSlice {
  double level = 0;
  Curve<3> curve;                  // shadow coordinates, every surface's curves in object order
  std::vector<int> object_of;      // per component of `curve`, its object's index in the scene
  int open_components = 0;         // arcs ending on a surface's boundary
};

// True when the scene has a surface of R^4 (what a slice cuts).
bool has_4d_surfaces(const Scene& scene);
// The w (4D depth in scene.frame) of every R^4 surface's vertices together; {0, 0} for none.
std::pair<double, double> scene_depth_range(const Scene& scene);
// Throws Error for a mesh that cannot be sliced (see level_set).
SceneSlice scene_slice(const Scene& scene, double level);

struct SceneCriticalPoint {
  int object = 0;
  CriticalPoint point;
};
// Every R^4 surface's critical levels, by increasing level.
std::vector<SceneCriticalPoint> scene_critical_points(const Scene& scene);

// The slice as an object of R^4 on the level (its points back on the surfaces), named `name`,
// ready to draw beside the surfaces or to add to the scene as a curve of its own.
SceneObject slice_object(const SceneSlice& slice, const Frame<4>& frame, const std::string& name);

}  // namespace s4d
