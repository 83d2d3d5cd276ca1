// load_object / load_scene_or_object: what the CLI and the GUI's "Open" accept — a scene, an
// object file, or a generator call such as "spun-trefoil:n=48".
#include <algorithm>
#include <cctype>

#include "core/error.hpp"
#include "io/object_file.hpp"
#include "io/scene.hpp"

namespace s4d {

namespace {
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}
}  // namespace

SceneObject load_object(const std::string& spec) {
  if (spec.empty()) throw Error("empty object name: give a file or a generator such as clifford-torus");
  const std::filesystem::path path(spec);
  std::error_code ec;
  SceneObject o;
  // A stray file named "chain" in the working folder must not hide the generator of that name.
  const bool generator_name = find_generator(spec.substr(0, spec.find(':'))) != nullptr;
  if (std::filesystem::is_regular_file(path, ec) && (is_shape_file_extension(path) || !generator_name)) {
    o.shape = read_shape_file(path);
    o.source_path = path.lexically_normal().string();
    o.name = path.stem().string();
  } else if (!generator_name && (is_shape_file_extension(path) || spec.find('/') != std::string::npos ||
                                 lower(path.extension().string()) == ".json")) {
    // It looks like a file name, so "unknown generator" would be the wrong complaint.
    throw Error(spec + (std::filesystem::exists(path, ec) ? ": not a regular file" : ": no such file"));
  } else {
    GeneratorCall call = parse_generator_call(spec);
    o.shape = generate(call.name, call.params);
    o.name = call.name;
    o.generator = std::move(call);
  }
  return o;
}

Scene load_scene_or_object(const std::string& spec) {
  if (lower(std::filesystem::path(spec).extension().string()) == ".json") return load_scene(spec);
  Scene scene;
  scene.objects.push_back(load_object(spec));
  return scene;
}

}  // namespace s4d
