// load_object / load_scene_or_object: what the CLI and the GUI's "Open" accept — a scene, an
// object file, or a generator call such as "spun-trefoil:n=48", either placed by "@x,y,z[,w]".
// A file missing from the working folder is looked for among the examples (find_example).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include "core/data_paths.hpp"
#include "core/chars.hpp"
#include "core/error.hpp"
#include "io/object_file.hpp"
#include "io/scene.hpp"

namespace s4d {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

SceneObject load_unplaced_object(const std::string& spec) {
  if (spec.empty()) throw Error("empty object name: give a file or a generator such as clifford-torus");
  std::error_code ec;
  SceneObject o;
  // A stray file named "chain" in the working folder must not hide the generator of that name.
  const bool generator_name = find_generator(spec.substr(0, spec.find(':'))) != nullptr;
  const std::filesystem::path path = generator_name ? std::filesystem::path(spec) : find_example(spec);
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

// "SPEC@x,y,z[,w]": the offset the object is placed at, when the part after the last '@' is 3
// or 4 numbers (a file name may hold an '@' of its own).
std::optional<Vec4> offset_suffix(const std::string& spec, std::string& rest) {
  const std::size_t at = spec.rfind('@');
  if (at == std::string::npos) return std::nullopt;
  std::vector<double> v;
  std::string_view tail = std::string_view(spec).substr(at + 1);
  while (!tail.empty()) {
    const std::size_t comma = tail.find(',');
    const std::string_view item = tail.substr(0, comma);
    double x = 0;
    const auto [ptr, ec] = double_from_chars(item.data(), item.data() + item.size(), x);
    if (item.empty() || ec != std::errc() || ptr != item.data() + item.size()) return std::nullopt;
    v.push_back(x);
    tail = comma == std::string_view::npos ? std::string_view() : tail.substr(comma + 1);
  }
  if (v.size() != 3 && v.size() != 4) return std::nullopt;
  for (double x : v)
    if (!std::isfinite(x)) throw Error(spec + ": the offset after '@' must be finite");
  rest = spec.substr(0, at);
  return Vec4(v[0], v[1], v[2], v.size() == 4 ? v[3] : 0.0);
}

}  // namespace

SceneObject load_object(const std::string& full_spec) {
  std::string spec = full_spec;
  const std::optional<Vec4> offset = offset_suffix(full_spec, spec);
  SceneObject o = load_unplaced_object(spec);
  if (offset) {
    o.placement.offset = *offset;
    o.shape = placed(std::move(o.shape), o.placement);
  }
  return o;
}

Scene load_scene_or_object(const std::string& spec) {
  if (lower(std::filesystem::path(spec).extension().string()) == ".json") return load_scene(find_example(spec));
  Scene scene;
  scene.objects.push_back(load_object(spec));
  return scene;
}

}  // namespace s4d
