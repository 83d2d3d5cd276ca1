// A scene's slice and critical levels, surface by surface (see scene_slice.hpp).
#include "view/scene_slice.hpp"

#include <algorithm>

#include "shape/level_set.hpp"

namespace s4d {

bool has_4d_surfaces(const Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(),
                     [](const SceneObject& o) { return std::holds_alternative<Surface<4>>(o.shape); });
}

std::pair<double, double> scene_depth_range(const Scene& scene) {
  bool any = false;
  std::pair<double, double> range{0.0, 0.0};
  for (const SceneObject& o : scene.objects)
    if (const auto* s = std::get_if<Surface<4>>(&o.shape); s && !s->vertices.empty()) {
      const auto [lo, hi] = depth_range(*s, scene.frame);
      range = any ? std::pair{std::min(range.first, lo), std::max(range.second, hi)} : std::pair{lo, hi};
      any = true;
    }
  return range;
}

SceneSlice scene_slice(const Scene& scene, double level) {
  SceneSlice out;
  out.level = level;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (const auto* s = std::get_if<Surface<4>>(&scene.objects[i].shape)) {
      LevelSet<4> set = level_set(*s, scene.frame, level);
      out.open_components += set.open_components;
      for (Polyline<3>& line : set.curve.components) {
        out.curve.components.push_back(std::move(line));
        out.object_of.push_back(static_cast<int>(i));
      }
    }
  return out;
}

std::vector<SceneCriticalPoint> scene_critical_points(const Scene& scene) {
  std::vector<SceneCriticalPoint> out;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (const auto* s = std::get_if<Surface<4>>(&scene.objects[i].shape))
      for (const CriticalPoint& p : critical_points(*s, scene.frame)) out.push_back({static_cast<int>(i), p});
  std::stable_sort(out.begin(), out.end(),
                   [](const SceneCriticalPoint& a, const SceneCriticalPoint& b) { return a.point.level < b.point.level; });
  return out;
}

SceneObject slice_object(const SceneSlice& slice, const Frame<4>& frame, const std::string& name) {
  SceneObject o;
  o.name = name;
  o.shape = lift_slice(slice.curve, frame, slice.level);
  return o;
}

}  // namespace s4d
