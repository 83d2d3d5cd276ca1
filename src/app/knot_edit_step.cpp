#include "app/knot_edit_step.hpp"

#include <variant>

namespace s4d {

std::string edit_curve_object(Session& session, int object, const std::string& label,
                              const std::function<Curve<3>(const Curve<3>&)>& edit) {
  Scene& scene = session.scene();
  if (object < 0 || object >= static_cast<int>(scene.objects.size())) return "no such curve";
  SceneObject& obj = scene.objects[static_cast<std::size_t>(object)];
  const auto* curve = std::get_if<Curve<3>>(&obj.shape);
  if (!curve) return "'" + obj.name + "' is not a curve of R^3";
  Curve<3> changed;
  try {
    changed = edit(*curve);
  } catch (const std::exception& e) {
    return std::string("cannot ") + label + ": " + e.what();
  }
  const bool same_points = changed.point_count() == curve->point_count();
  session.record(label + " '" + obj.name + "'");
  obj.shape = std::move(changed);
  obj.generator.reset();  // edited geometry: saved as a file beside the scene
  obj.source_path.clear();
  // A simulated knot takes the new shape as its rest (as a crossing change does); a deleted
  // component changes its points, so the bodies are built again (the others keep their motion).
  if (session.first_vertex(object) >= 0) {
    if (same_points) session.shapes_edited();
    else session.objects_changed();
  }
  return label + " '" + obj.name + "'";
}

}  // namespace s4d
