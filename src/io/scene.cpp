// Scene files: JSON (nlohmann, insertion-ordered so "rotate" applies in the order written) in,
// validated field by field with the JSON path in every message; JSON out, with meshes beside it.
#include "io/scene.hpp"

#include <cmath>
#include <numbers>
#include <set>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/object_file.hpp"
#include "io/text_scanner.hpp"

namespace s4d {

namespace {

using Json = nlohmann::ordered_json;

// Where we are in the document, for messages such as "objects[2].params.n: must be a number".
struct Ctx {
  const std::string& file;
  std::string where;
  Ctx at(const std::string& key) const { return {file, where.empty() ? key : where + "." + key}; }
  Ctx at(std::size_t i) const { return {file, where + "[" + std::to_string(i) + "]"}; }
  [[noreturn]] void fail(const std::string& message) const {
    throw ParseError(file, 0, (where.empty() ? std::string() : where + ": ") + message);
  }
};

const char* type_name(const Json& j) { return j.type_name(); }

void check_keys(const Json& obj, const Ctx& ctx, std::initializer_list<const char*> allowed) {
  for (const auto& [key, value] : obj.items()) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || key == a;
    if (!ok) {
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      ctx.fail("unknown key '" + key + "' (expected one of: " + list + ")");
    }
  }
}

const Json& require_object(const Json& j, const Ctx& ctx) {
  if (!j.is_object()) ctx.fail(std::string("must be an object, found ") + type_name(j));
  return j;
}

double number(const Json& j, const Ctx& ctx) {
  if (!j.is_number()) ctx.fail(std::string("must be a number, found ") + type_name(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) ctx.fail("must be finite");
  return v;
}

// A number in [lo, hi]; `lo_open` makes the lower bound strict (time_step > 0, not >= 0).
double number_in(const Json& j, const Ctx& ctx, double lo, double hi, bool lo_open = false) {
  const double v = number(j, ctx);
  if (v < lo || v > hi || (lo_open && v == lo))
    ctx.fail(format_double(v) + " is out of range: must be in " + (lo_open ? "(" : "[") + format_double(lo) +
             ", " + format_double(hi) + "]");
  return v;
}

bool boolean(const Json& j, const Ctx& ctx) {
  if (!j.is_boolean()) ctx.fail(std::string("must be true or false, found ") + type_name(j));
  return j.get<bool>();
}

std::string string(const Json& j, const Ctx& ctx) {
  if (!j.is_string()) ctx.fail(std::string("must be a string, found ") + type_name(j));
  return j.get<std::string>();
}

// A fixed-size numeric array; `sizes` lists the lengths accepted (e.g. {3, 4} for an offset).
std::vector<double> numbers(const Json& j, const Ctx& ctx, std::initializer_list<std::size_t> sizes) {
  if (!j.is_array()) ctx.fail(std::string("must be an array of numbers, found ") + type_name(j));
  bool ok = false;
  for (std::size_t s : sizes) ok = ok || j.size() == s;
  if (!ok) {
    std::string list;
    for (std::size_t s : sizes) list += (list.empty() ? "" : " or ") + std::to_string(s);
    ctx.fail("must have " + list + " numbers, has " + std::to_string(j.size()));
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < j.size(); ++i) out.push_back(number(j[i], ctx.at(i)));
  return out;
}

Vec3f colour(const Json& j, const Ctx& ctx) {
  const auto v = numbers(j, ctx, {3});
  for (std::size_t i = 0; i < 3; ++i)
    if (v[i] < 0 || v[i] > 1) ctx.at(i).fail("colour components must be in [0, 1]");
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

Vec4 vec4_or_3(const Json& j, const Ctx& ctx) {
  const auto v = numbers(j, ctx, {3, 4});
  return {v[0], v[1], v[2], v.size() == 4 ? v[3] : 0.0};
}

Frame<4> parse_frame(const Json& j, const Ctx& ctx) {
  require_object(j, ctx);
  check_keys(j, ctx, {"matrix", "rotate"});
  if (j.contains("matrix") && j.contains("rotate")) ctx.fail("give either 'matrix' or 'rotate', not both");
  if (j.contains("matrix")) {
    const Ctx mc = ctx.at("matrix");
    const Json& m = j["matrix"];
    if (!m.is_array() || m.size() != 4) mc.fail("must be 4 rows of 4 numbers");
    Mat<4> r;
    for (std::size_t i = 0; i < 4; ++i) {
      const auto row = numbers(m[i], mc.at(i), {4});
      for (int k = 0; k < 4; ++k) r(static_cast<int>(i), k) = row[static_cast<std::size_t>(k)];
    }
    const double err = (r.transpose() * r - Mat<4>::Identity()).cwiseAbs().maxCoeff();
    if (err > 1e-6) mc.fail("is not a rotation: R^T R differs from the identity by " + format_double(err));
    if (r.determinant() < 0) mc.fail("is a reflection (determinant -1), not a rotation");
    return Frame<4>(r);
  }
  Frame<4> f;
  if (j.contains("rotate")) {
    const Ctx rc = ctx.at("rotate");
    require_object(j["rotate"], rc);
    for (const auto& [name, angle] : j["rotate"].items()) {
      const auto plane = parse_plane(name, 4);
      if (!plane) rc.fail("unknown rotation plane '" + name + "' (use two of x, y, z, w, such as \"xw\")");
      const double deg = number_in(angle, rc.at(name), -1e6, 1e6);
      // "wx" names the same plane as "xw" turning the other way.
      const double sign = name[0] == kAxisNames[plane->a] ? 1.0 : -1.0;
      f.rotate(*plane, sign * deg * std::numbers::pi / 180.0);
    }
  }
  return f;
}

ViewSettings parse_view(const Json& j, const Ctx& ctx) {
  require_object(j, ctx);
  check_keys(j, ctx, {"trackball", "distance", "fov_deg", "depth_colour", "colour_map", "wireframe", "shadow",
                      "intersections", "tube_radius", "curve_mode", "opacity", "background"});
  ViewSettings v;
  if (j.contains("trackball")) {
    const auto q = numbers(j["trackball"], ctx.at("trackball"), {4});
    Eigen::Quaterniond t(q[0], q[1], q[2], q[3]);
    if (!(t.norm() > 1e-9)) ctx.at("trackball").fail("quaternion [w, x, y, z] must not be zero");
    t.normalize();
    v.trackball = t;
  }
  if (j.contains("distance")) v.distance = number_in(j["distance"], ctx.at("distance"), 0, 1e9);
  if (j.contains("fov_deg")) v.fov_deg = number_in(j["fov_deg"], ctx.at("fov_deg"), 0, 179, true);
  if (j.contains("depth_colour")) v.depth_colour = boolean(j["depth_colour"], ctx.at("depth_colour"));
  if (j.contains("colour_map")) {
    const std::string name = string(j["colour_map"], ctx.at("colour_map"));
    const auto map = parse_colour_map(name);
    if (!map) ctx.at("colour_map").fail("unknown colour map '" + name + "'");
    v.colour_map = *map;
  }
  if (j.contains("wireframe")) v.wireframe = boolean(j["wireframe"], ctx.at("wireframe"));
  if (j.contains("shadow")) v.shadow = boolean(j["shadow"], ctx.at("shadow"));
  if (j.contains("intersections")) v.intersections = boolean(j["intersections"], ctx.at("intersections"));
  if (j.contains("tube_radius"))
    v.tube_radius = number_in(j["tube_radius"], ctx.at("tube_radius"), 0, 1e6, true);
  if (j.contains("curve_mode")) {
    const std::string name = string(j["curve_mode"], ctx.at("curve_mode"));
    const auto mode = parse_curve_mode(name);
    if (!mode) ctx.at("curve_mode").fail("unknown curve mode '" + name + "' (use tubes, shadow or diagram)");
    v.curve_mode = *mode;
  }
  // Below 0.05 a surface all but vanishes, which reads as a bug rather than a setting.
  if (j.contains("opacity")) v.opacity = number_in(j["opacity"], ctx.at("opacity"), 0.05, 1);
  if (j.contains("background")) v.background = colour(j["background"], ctx.at("background"));
  return v;
}

PhysicsSettings parse_physics(const Json& j, const Ctx& ctx) {
  require_object(j, ctx);
  check_keys(j, ctx, {"time_step", "thickness", "gravity", "mass", "stiffness", "shear_scale", "bending_scale",
                      "beta", "damping", "spring_damping", "friction", "max_step_motion", "collisions",
                      "integrator"});
  PhysicsSettings p;
  if (j.contains("time_step")) p.time_step = number_in(j["time_step"], ctx.at("time_step"), 0, 1, true);
  if (j.contains("thickness")) p.thickness = number_in(j["thickness"], ctx.at("thickness"), 0, 1e6, true);
  if (j.contains("gravity")) {
    p.gravity = vec4_or_3(j["gravity"], ctx.at("gravity"));
    if (p.gravity.norm() > 1e4) ctx.at("gravity").fail("magnitude above 1e4 m/s² is not physical");
  }
  if (j.contains("mass")) p.mass = number_in(j["mass"], ctx.at("mass"), 0, 1e6, true);
  if (j.contains("stiffness")) p.stiffness = number_in(j["stiffness"], ctx.at("stiffness"), 0, 1e9);
  if (j.contains("shear_scale")) p.shear_scale = number_in(j["shear_scale"], ctx.at("shear_scale"), 0, 10);
  if (j.contains("bending_scale"))
    p.bending_scale = number_in(j["bending_scale"], ctx.at("bending_scale"), 0, 10);
  if (j.contains("spring_damping"))
    p.spring_damping = number_in(j["spring_damping"], ctx.at("spring_damping"), 0, 1e6);
  if (j.contains("max_step_motion"))
    p.max_step_motion = number_in(j["max_step_motion"], ctx.at("max_step_motion"), 0, 1e6);
  if (j.contains("collisions")) p.collisions = boolean(j["collisions"], ctx.at("collisions"));
  // |N|^(1+β) must grow with |N|, so β > -1; large β makes the spring numerically explosive.
  if (j.contains("beta")) p.beta = number_in(j["beta"], ctx.at("beta"), -1, 4, true);
  if (j.contains("damping")) p.damping = number_in(j["damping"], ctx.at("damping"), 0, 1e6);
  if (j.contains("friction")) p.friction = number_in(j["friction"], ctx.at("friction"), 0, 100);
  if (j.contains("integrator")) {
    p.integrator = string(j["integrator"], ctx.at("integrator"));
    bool ok = !p.integrator.empty() && p.integrator.size() <= 64;
    for (char c : p.integrator) ok = ok && ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-');
    if (!ok) ctx.at("integrator").fail("'" + p.integrator + "' is not an integrator name (kebab-case)");
  }
  return p;
}

// A point of R^dim.
template <int D>
Vec<D> point(const Json& j, const Ctx& ctx) {
  const auto v = numbers(j, ctx, {static_cast<std::size_t>(D)});
  Vec<D> p;
  for (int k = 0; k < D; ++k) p[k] = v[static_cast<std::size_t>(k)];
  return p;
}

template <int D>
Shape parse_geometry_in(const Json& j, const Ctx& ctx) {
  if (j.contains("components")) {
    Curve<D> c;
    const Ctx cc = ctx.at("components");
    if (!j["components"].is_array()) cc.fail("must be an array of curve components");
    for (std::size_t i = 0; i < j["components"].size(); ++i) {
      const Json& comp = j["components"][i];
      const Ctx pc = cc.at(i);
      require_object(comp, pc);
      check_keys(comp, pc, {"closed", "points"});
      Polyline<D> line;
      if (comp.contains("closed")) line.closed = boolean(comp["closed"], pc.at("closed"));
      if (!comp.contains("points") || !comp["points"].is_array()) pc.at("points").fail("must be an array of points");
      for (std::size_t k = 0; k < comp["points"].size(); ++k)
        line.points.push_back(point<D>(comp["points"][k], pc.at("points").at(k)));
      if (line.points.size() < 2) pc.at("points").fail("a component needs at least 2 points");
      c.components.push_back(std::move(line));
    }
    return c;
  }
  Surface<D> s;
  if (!j.contains("vertices") || !j["vertices"].is_array()) ctx.at("vertices").fail("must be an array of points");
  for (std::size_t k = 0; k < j["vertices"].size(); ++k) s.vertices.push_back(point<D>(j["vertices"][k], ctx.at("vertices").at(k)));
  if (!j.contains("triangles") || !j["triangles"].is_array()) ctx.at("triangles").fail("must be an array of index triples");
  const double nv = static_cast<double>(s.vertices.size());
  for (std::size_t k = 0; k < j["triangles"].size(); ++k) {
    const Ctx tc = ctx.at("triangles").at(k);
    const auto t = numbers(j["triangles"][k], tc, {3});
    Triangle tri;
    for (int c = 0; c < 3; ++c) {
      const double i = t[static_cast<std::size_t>(c)];
      if (i < 0 || i >= nv || i != std::floor(i)) tc.fail("vertex index " + format_double(i) + " is not one of the " +
                                                             format_double(nv) + " vertices");
      tri[static_cast<std::size_t>(c)] = static_cast<int>(i);
    }
    s.triangles.push_back(tri);
  }
  if (j.contains("grid")) {
    const Ctx gc = ctx.at("grid");
    require_object(j["grid"], gc);
    check_keys(j["grid"], gc, {"rows", "cols", "wrap_i", "wrap_j"});
    Grid g;
    g.rows = static_cast<int>(number_in(j["grid"].value("rows", Json()), gc.at("rows"), 1, 1e7));
    g.cols = static_cast<int>(number_in(j["grid"].value("cols", Json()), gc.at("cols"), 1, 1e7));
    if (j["grid"].contains("wrap_i")) g.wrap_i = boolean(j["grid"]["wrap_i"], gc.at("wrap_i"));
    if (j["grid"].contains("wrap_j")) g.wrap_j = boolean(j["grid"]["wrap_j"], gc.at("wrap_j"));
    if (static_cast<double>(g.rows) * g.cols != nv) gc.fail("rows x cols must be the vertex count");
    s.grid = g;
  }
  return s;
}

// Inline geometry (what a session stores): {"dim": 3|4, "vertices", "triangles"[, "grid"]} for
// a surface, {"dim", "components": [{"closed", "points"}]} for a curve.
Shape parse_geometry(const Json& j, const Ctx& ctx) {
  require_object(j, ctx);
  check_keys(j, ctx, {"dim", "vertices", "triangles", "grid", "components"});
  const double dim = number(j.value("dim", Json()), ctx.at("dim"));
  if (dim != 3 && dim != 4) ctx.at("dim").fail("must be 3 or 4");
  if (j.contains("components") && (j.contains("vertices") || j.contains("triangles")))
    ctx.fail("a curve (components) or a surface (vertices, triangles), not both");
  return dim == 3 ? parse_geometry_in<3>(j, ctx) : parse_geometry_in<4>(j, ctx);
}

// An object's placement keys: "matrix" (4 rows of 4 numbers, or 16 in a row), "scale",
// "mirror" (axes 0-3), "w_by_row", "offset" (3 or 4 numbers).
Placement parse_placement(const Json& j, const Ctx& ctx) {
  Placement p;
  if (j.contains("matrix")) {
    const Ctx mc = ctx.at("matrix");
    const Json& m = j["matrix"];
    std::vector<double> v;
    if (m.is_array() && m.size() == 4 && m[0].is_array()) {
      for (std::size_t i = 0; i < 4; ++i) {
        const auto row = numbers(m[i], mc.at(i), {4});
        v.insert(v.end(), row.begin(), row.end());
      }
    } else {
      v = numbers(m, mc, {16});
    }
    Mat<4> r;
    for (int i = 0; i < 16; ++i) r(i / 4, i % 4) = v[static_cast<std::size_t>(i)];
    p.matrix = r;
  }
  if (j.contains("scale")) p.scale = number_in(j["scale"], ctx.at("scale"), 1e-6, 1e6);
  if (j.contains("mirror")) {
    const Ctx mc = ctx.at("mirror");
    if (!j["mirror"].is_array()) mc.fail(std::string("must be an array of axes, found ") + type_name(j["mirror"]));
    for (std::size_t i = 0; i < j["mirror"].size(); ++i) {
      const double a = number_in(j["mirror"][i], mc.at(i), 0, 3);
      if (a != std::floor(a)) mc.at(i).fail("an axis is 0 (x), 1 (y), 2 (z) or 3 (w)");
      p.mirror.push_back(static_cast<int>(a));
    }
  }
  if (j.contains("w_by_row")) p.w_by_row = number_in(j["w_by_row"], ctx.at("w_by_row"), -1e3, 1e3);
  if (j.contains("offset")) p.offset = vec4_or_3(j["offset"], ctx.at("offset"));
  return p;
}

SceneObject parse_object(const Json& j, const Ctx& ctx, const std::filesystem::path& base) {
  require_object(j, ctx);
  check_keys(j, ctx, {"name", "generator", "params", "path", "geometry", "offset", "colour", "matrix", "scale",
                      "mirror", "w_by_row", "mass"});
  const bool gen = j.contains("generator"), file = j.contains("path"), inline_shape = j.contains("geometry");
  if (gen + file + inline_shape != 1) ctx.fail("needs exactly one of 'generator', 'path' or 'geometry'");
  if (inline_shape) {
    SceneObject o;
    o.name = j.contains("name") ? string(j["name"], ctx.at("name")) : "object";
    if (o.name.empty()) ctx.at("name").fail("must not be empty");
    for (const char* k : {"params", "offset", "matrix", "scale", "mirror", "w_by_row"})
      if (j.contains(k)) ctx.at(k).fail("inline geometry is stored as it is placed: no placement keys");
    if (j.contains("colour")) o.colour = colour(j["colour"], ctx.at("colour"));
    if (j.contains("mass")) o.mass = number_in(j["mass"], ctx.at("mass"), 0, 1e6);
    o.shape = parse_geometry(j["geometry"], ctx.at("geometry"));
    return o;
  }
  if (j.contains("params") && !gen) ctx.fail("'params' is only allowed with 'generator'");
  SceneObject o;
  if (j.contains("name")) {
    o.name = string(j["name"], ctx.at("name"));
    if (o.name.empty()) ctx.at("name").fail("must not be empty");
  }
  o.placement = parse_placement(j, ctx);
  if (j.contains("mass")) o.mass = number_in(j["mass"], ctx.at("mass"), 0, 1e6);
  if (j.contains("colour")) o.colour = colour(j["colour"], ctx.at("colour"));
  if (gen) {
    GeneratorCall call;
    call.name = string(j["generator"], ctx.at("generator"));
    if (!find_generator(call.name)) {
      std::string known;
      for (const auto& g : generator_catalogue()) known += (known.empty() ? "" : ", ") + g.name;
      ctx.at("generator").fail("unknown generator '" + call.name + "' (known: " + known + ")");
    }
    if (j.contains("params")) {
      const Ctx pc = ctx.at("params");
      require_object(j["params"], pc);
      for (const auto& [key, value] : j["params"].items()) call.params[key] = number(value, pc.at(key));
    }
    try {
      o.shape = generate(call.name, call.params);
    } catch (const ParseError&) {
      throw;
    } catch (const std::exception& e) {
      ctx.fail(e.what());
    }
    if (o.name.empty()) o.name = call.name;
    o.generator = std::move(call);
  } else {
    const std::string rel = string(j["path"], ctx.at("path"));
    if (rel.empty()) ctx.at("path").fail("must not be empty");
    std::filesystem::path p(rel);
    if (p.is_relative()) p = base / p;
    p = p.lexically_normal();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) ctx.at("path").fail("mesh file not found: " + p.string());
    if (!is_shape_file_extension(p)) ctx.at("path").fail("unknown mesh file type: " + p.string());
    o.shape = read_shape_file(p);  // its own ParseError names the mesh file and line
    o.source_path = p.string();
    if (o.name.empty()) o.name = p.stem().string();
  }
  try {
    o.shape = placed(std::move(o.shape), o.placement);
  } catch (const ParseError&) {
    throw;
  } catch (const std::exception& e) {
    ctx.fail(e.what());
  }
  return o;
}

// Converts nlohmann's byte offset into a 1-based line number.
int line_of_byte(const std::string& text, std::size_t byte) {
  const std::size_t end = std::min(byte, text.size());
  int line = 1;
  for (std::size_t i = 0; i < end; ++i) line += text[i] == '\n';
  return line;
}

Json parse_json(const std::string& text, const std::string& file) {
  try {
    return Json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const Json::parse_error& e) {
    // e.byte is 1-based and points just past the offending character.
    const int line = line_of_byte(text, e.byte > 0 ? e.byte - 1 : 0);
    std::string msg = e.what();
    const std::size_t colon = msg.find(": ", msg.find("parse error"));
    if (colon != std::string::npos) msg = msg.substr(colon + 2);
    throw ParseError(file, line, "JSON syntax error: " + msg);
  } catch (const Json::exception& e) {
    // Number overflow (1e999) is reported without a position; find the number in the text.
    std::string msg = e.what();
    int line = 0;
    const std::size_t q = msg.find('\'');
    const std::size_t q2 = q == std::string::npos ? q : msg.find('\'', q + 1);
    if (q2 != std::string::npos) {
      const std::size_t at = text.find(msg.substr(q + 1, q2 - q - 1));
      if (at != std::string::npos) line = line_of_byte(text, at);
    }
    const std::size_t bracket = msg.find("] ");
    if (bracket != std::string::npos) msg = msg.substr(bracket + 2);
    throw ParseError(file, line, "JSON error: " + msg);
  }
}

}  // namespace

Scene parse_scene(const std::string& text, const std::filesystem::path& origin) {
  const std::string file = origin.string();
  const Json root = parse_json(text, file);
  const Ctx ctx{file, ""};
  if (!root.is_object()) ctx.fail(std::string("a scene must be a JSON object, found ") + type_name(root));
  check_keys(root, ctx, {"version", "description", "instruction", "objects", "frame", "view", "physics", "scenario"});
  if (!root.contains("version")) ctx.fail("missing \"version\" (this program reads version " +
                                          std::to_string(kSceneVersion) + ")");
  const Json& ver = root["version"];
  if (!ver.is_number_integer() || ver.get<long long>() != kSceneVersion)
    ctx.at("version").fail("unsupported scene version " + ver.dump() + " (this program reads version " +
                           std::to_string(kSceneVersion) + ")");
  Scene scene;
  if (root.contains("description")) scene.description = string(root["description"], ctx.at("description"));
  if (root.contains("instruction")) scene.instruction = string(root["instruction"], ctx.at("instruction"));
  const std::filesystem::path base = origin.parent_path();
  if (root.contains("objects")) {
    const Json& objs = root["objects"];
    const Ctx oc = ctx.at("objects");
    if (!objs.is_array()) oc.fail(std::string("must be an array, found ") + type_name(objs));
    std::set<std::string> explicit_names;
    for (std::size_t i = 0; i < objs.size(); ++i)
      if (objs[i].is_object() && objs[i].contains("name") && objs[i]["name"].is_string())
        if (!explicit_names.insert(objs[i]["name"].get<std::string>()).second)
          oc.at(i).at("name").fail("duplicate object name '" + objs[i]["name"].get<std::string>() + "'");
    std::set<std::string> used = explicit_names;
    for (std::size_t i = 0; i < objs.size(); ++i) {
      SceneObject o = parse_object(objs[i], oc.at(i), base);
      if (!objs[i].contains("name")) {  // default names ("sphere") are made unique ("sphere-2")
        const std::string stem = o.name;
        for (int k = 2; used.count(o.name); ++k) o.name = stem + "-" + std::to_string(k);
        used.insert(o.name);
      }
      scene.objects.push_back(std::move(o));
    }
  }
  if (root.contains("frame")) scene.frame = parse_frame(root["frame"], ctx.at("frame"));
  if (root.contains("view")) scene.view = parse_view(root["view"], ctx.at("view"));
  if (root.contains("physics")) scene.physics = parse_physics(root["physics"], ctx.at("physics"));
  if (root.contains("scenario")) scene.scenario = require_object(root["scenario"], ctx.at("scenario")).dump();
  return scene;
}

Scene load_scene(const std::filesystem::path& path) { return parse_scene(read_text_file(path), path); }

}  // namespace s4d
