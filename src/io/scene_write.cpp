// save_scene: the inverse of parse_scene. Generated objects keep their generator call, loaded ones
// their path (relative to the scene when possible); edited geometry goes to a mesh file beside it.
#include <cmath>
#include <set>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/object_file.hpp"
#include "io/scene.hpp"
#include "io/text_scanner.hpp"

namespace s4d {

namespace {

using Json = nlohmann::ordered_json;

// Integral values are written as integers ("n": 48, not 48.0) so the files read naturally.
Json number(double v) {
  if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e15) return static_cast<long long>(v);
  return v;
}

Json array(const auto& v, int n) {
  Json a = Json::array();
  for (int i = 0; i < n; ++i) a.push_back(number(static_cast<double>(v[i])));
  return a;
}

// A file-name-safe version of an object name: letters, digits, '-' and '_' survive.
std::string safe_name(const std::string& name) {
  std::string out;
  for (char c : name)
    out +=
        ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_')
            ? c
            : '_';
  return out.empty() ? "object" : out;
}

std::string path_for_scene(const std::string& source, const std::filesystem::path& scene_dir) {
  std::error_code ec;
  const auto abs_source = std::filesystem::absolute(source, ec);
  if (ec) return source;
  const auto abs_dir = std::filesystem::absolute(scene_dir.empty() ? "." : scene_dir, ec);
  if (ec) return abs_source.string();
  const auto rel = abs_source.lexically_relative(abs_dir);
  return rel.empty() ? abs_source.string() : rel.generic_string();
}

void write_placement(const Placement& p, Json& j) {
  if (p.matrix) {
    Json m = Json::array();
    for (int i = 0; i < 4; ++i) m.push_back(array(p.matrix->row(i), 4));
    j["matrix"] = std::move(m);
  }
  if (p.scale != 1) j["scale"] = number(p.scale);
  if (!p.mirror.empty()) j["mirror"] = p.mirror;
  if (p.w_by_row != 0) j["w_by_row"] = number(p.w_by_row);
  if (!p.offset.isZero(0)) j["offset"] = array(p.offset, 4);
}


// A shape as the "geometry" of an object: every point and triangle, inline.
Json geometry_json(const Shape& shape) {
  Json g;
  std::visit([&](const auto& s) {
    using T = std::decay_t<decltype(s)>;
    constexpr int D = T::kDim;
    g["dim"] = D;
    if constexpr (std::is_same_v<T, Surface<D>>) {
      Json v = Json::array(), t = Json::array();
      for (const auto& p : s.vertices) v.push_back(array(p, D));
      for (const Triangle& tri : s.triangles) t.push_back(Json::array({tri[0], tri[1], tri[2]}));
      g["vertices"] = std::move(v);
      g["triangles"] = std::move(t);
      if (s.grid)
        g["grid"] = {{"rows", s.grid->rows}, {"cols", s.grid->cols}, {"wrap_i", s.grid->wrap_i}, {"wrap_j", s.grid->wrap_j}};
    } else {
      Json comps = Json::array();
      for (const auto& c : s.components) {
        Json pts = Json::array();
        for (const auto& p : c.points) pts.push_back(array(p, D));
        comps.push_back({{"closed", c.closed}, {"points", std::move(pts)}});
      }
      g["components"] = std::move(comps);
    }
  }, shape);
  return g;
}

}  // namespace

void save_scene(const Scene& scene, const std::filesystem::path& path) {
  write_text_file(path, scene_text(scene, path, ObjectStorage::kByRecipe));
}

std::string scene_text(const Scene& scene, const std::filesystem::path& path, ObjectStorage storage) {
  const std::filesystem::path dir = path.parent_path();
  Json root;
  root["version"] = kSceneVersion;
  if (!scene.description.empty()) root["description"] = scene.description;
  if (!scene.instruction.empty()) root["instruction"] = scene.instruction;
  Json objects = Json::array();
  std::set<std::string> mesh_names;
  for (const SceneObject& o : scene.objects) {
    Json j;
    j["name"] = o.name;
    if (storage == ObjectStorage::kInline) {
      j["geometry"] = geometry_json(o.shape);
    } else if (o.generator) {
      j["generator"] = o.generator->name;
      Json params = Json::object();
      for (const auto& [k, v] : o.generator->params) {
        if (!std::isfinite(v))
          throw Error("cannot save scene: parameter " + k + " of " + o.name + " is not finite");
        params[k] = number(v);
      }
      if (!params.empty()) j["params"] = params;
      write_placement(o.placement, j);
    } else if (!o.source_path.empty()) {
      j["path"] = path_for_scene(o.source_path, dir);
      write_placement(o.placement, j);
    } else {
      // Edited geometry: the placement is already in the vertices, so it is not written again.
      std::string file = path.stem().string() + "." + safe_name(o.name);
      for (int k = 2; mesh_names.count(file); ++k)
        file = path.stem().string() + "." + safe_name(o.name) + "-" + std::to_string(k);
      mesh_names.insert(file);
      file += native_extension(o.shape);
      write_shape_file(o.shape, dir / file);
      j["path"] = file;
    }
    if (o.colour) j["colour"] = array(*o.colour, 3);
    if (o.mass > 0) j["mass"] = number(o.mass);
    objects.push_back(std::move(j));
  }
  root["objects"] = std::move(objects);

  Json matrix = Json::array();
  for (int i = 0; i < 4; ++i) matrix.push_back(array(scene.frame.matrix().row(i), 4));
  root["frame"] = {{"matrix", matrix}};

  const ViewSettings& v = scene.view;
  const auto& q = v.trackball;
  Json view;
  view["trackball"] = Json::array({number(q.w()), number(q.x()), number(q.y()), number(q.z())});
  view["distance"] = number(v.distance);
  view["fov_deg"] = number(v.fov_deg);
  view["depth_colour"] = v.depth_colour;
  view["colour_map"] = std::string(colour_map_name(v.colour_map));
  view["wireframe"] = v.wireframe;
  view["shadow"] = v.shadow;
  view["intersections"] = v.intersections;
  view["tube_radius"] = number(v.tube_radius);
  view["curve_mode"] = std::string(curve_mode_name(v.curve_mode));
  view["opacity"] = number(v.opacity);
  view["background"] = array(v.background, 3);
  root["view"] = std::move(view);

  const PhysicsSettings& p = scene.physics;
  Json physics;
  physics["time_step"] = number(p.time_step);
  physics["thickness"] = number(p.thickness);
  physics["gravity"] = array(p.gravity, 4);
  physics["mass"] = number(p.mass);
  physics["stiffness"] = number(p.stiffness);
  physics["shear_scale"] = number(p.shear_scale);
  physics["bending_scale"] = number(p.bending_scale);
  physics["beta"] = number(p.beta);
  physics["damping"] = number(p.damping);
  physics["spring_damping"] = number(p.spring_damping);
  physics["friction"] = number(p.friction);
  physics["max_step_motion"] = number(p.max_step_motion);
  physics["collisions"] = p.collisions;
  physics["integrator"] = p.integrator;
  root["physics"] = std::move(physics);
  if (!scene.scenario.empty()) {
    try {
      root["scenario"] = Json::parse(scene.scenario);
    } catch (const Json::exception& e) {
      throw Error("cannot save scene " + path.string() + ": its scenario section is not JSON: " + e.what());
    }
  }

  std::string text;
  try {
    text = root.dump(2) + "\n";
  } catch (const Json::exception& e) {  // e.g. an object name that is not valid UTF-8
    throw Error("cannot save scene " + path.string() + ": " + e.what());
  }
  return text;
}

}  // namespace s4d
