// Parsing and validation of scenario JSON (see scenario_spec.hpp).
#include "scenario_spec.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "core/plane.hpp"

namespace s4d::scenario {
namespace {

using Json = nlohmann::json;

struct Ctx {
  std::string file;
  [[noreturn]] void fail(const std::string& where, const std::string& msg) const {
    throw ParseError(file, 0, where + ": " + msg);
  }
  void keys(const Json& j, const std::string& where, std::set<std::string> allowed) const {
    if (!j.is_object()) fail(where, "must be an object");
    for (const auto& [k, v] : j.items())
      if (!allowed.count(k)) fail(where, "unknown key '" + k + "'");
  }
  double number(const Json& j, const std::string& where, double lo, double hi) const {
    if (!j.is_number()) fail(where, "must be a number");
    const double x = j.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi)
      fail(where, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return x;
  }
  std::string text(const Json& j, const std::string& where) const {
    if (!j.is_string()) fail(where, "must be a string");
    return j.get<std::string>();
  }
  std::vector<double> vec(const Json& j, const std::string& where, int n) const {
    if (!j.is_array() || static_cast<int>(j.size()) != n)
      fail(where, "must be an array of " + std::to_string(n) + " numbers");
    std::vector<double> v;
    for (std::size_t i = 0; i < j.size(); ++i)
      v.push_back(number(j[i], where + "[" + std::to_string(i) + "]", -1e6, 1e6));
    return v;
  }
};

void parse_physics(const Json& j, const Ctx& c, int dim, PhysicsParams<4>& p) {
  c.keys(j, "physics", {"time_step", "thickness", "gravity", "mass", "stiffness", "shear_scale",
                        "bending_scale", "beta", "damping", "spring_damping", "friction",
                        "integrator", "max_step_motion", "collisions"});
  if (j.contains("time_step")) p.time_step = c.number(j["time_step"], "physics.time_step", 1e-6, 0.1);
  if (j.contains("thickness")) p.thickness = c.number(j["thickness"], "physics.thickness", 1e-6, 10);
  if (j.contains("gravity")) {
    const auto g = c.vec(j["gravity"], "physics.gravity", dim);
    p.gravity.setZero();
    for (int k = 0; k < dim; ++k) p.gravity[k] = g[k];
  }
  if (j.contains("mass")) p.mass = c.number(j["mass"], "physics.mass", 1e-9, 1e3);
  if (j.contains("stiffness")) p.stiffness = c.number(j["stiffness"], "physics.stiffness", 0, 1e9);
  if (j.contains("shear_scale")) p.shear_scale = c.number(j["shear_scale"], "physics.shear_scale", 0, 10);
  if (j.contains("bending_scale"))
    p.bending_scale = c.number(j["bending_scale"], "physics.bending_scale", 0, 10);
  if (j.contains("beta")) p.beta = c.number(j["beta"], "physics.beta", 0, 4);
  if (j.contains("damping")) p.damping = c.number(j["damping"], "physics.damping", 0, 1e3);
  if (j.contains("spring_damping"))
    p.spring_damping = c.number(j["spring_damping"], "physics.spring_damping", 0, 1e3);
  if (j.contains("friction")) p.friction = c.number(j["friction"], "physics.friction", 0, 100);
  if (j.contains("max_step_motion"))
    p.max_step_motion = c.number(j["max_step_motion"], "physics.max_step_motion", 0, 10);
  if (j.contains("collisions")) {
    if (!j["collisions"].is_boolean()) c.fail("physics.collisions", "must be true or false");
    p.collisions = j["collisions"].get<bool>();
  }
  if (j.contains("integrator")) {
    try {
      p.integrator = parse_integrator(c.text(j["integrator"], "physics.integrator"));
    } catch (const ParseError&) {
      throw;
    } catch (const Error& e) {
      c.fail("physics.integrator", e.what());
    }
  }
}

Selection parse_selection(const Json& j, const Ctx& c, const std::string& where, int dim) {
  c.keys(j, where, {"object", "all", "extreme", "vertices"});
  Selection s;
  s.object = c.text(j.value("object", Json()), where + ".object");
  if (j.contains("all")) s.all = j["all"].is_boolean() && j["all"].get<bool>();
  if (j.contains("extreme")) {
    const Json& e = j["extreme"];
    c.keys(e, where + ".extreme", {"axis", "side", "count"});
    s.axis = static_cast<int>(c.number(e.value("axis", Json()), where + ".extreme.axis", 0, dim - 1));
    const std::string side = c.text(e.value("side", Json("max")), where + ".extreme.side");
    if (side != "max" && side != "min") c.fail(where + ".extreme.side", "must be \"min\" or \"max\"");
    s.max_side = side == "max";
    s.count = static_cast<int>(c.number(e.value("count", Json(1)), where + ".extreme.count", 1, 1e6));
  } else if (j.contains("vertices")) {
    if (!j["vertices"].is_array() || j["vertices"].empty())
      c.fail(where + ".vertices", "must be a non-empty array");
    for (const Json& v : j["vertices"])
      s.indices.push_back(static_cast<int>(c.number(v, where + ".vertices", -1e9, 1e9)));
  } else if (!s.all) {
    c.fail(where, "needs \"all\": true, \"vertices\" or an \"extreme\" selection");
  }
  return s;
}

}  // namespace

ScenarioSpec load_scenario(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw ParseError(path.string(), 0, "cannot open the scenario file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  Json root;
  try {
    root = Json::parse(text);
  } catch (const Json::parse_error& e) {
    const std::size_t upto = std::min<std::size_t>(e.byte, text.size());
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + upto, '\n'));
    throw ParseError(path.string(), line, "invalid JSON");
  }
  const Ctx c{path.string()};
  c.keys(root, "scenario", {"name", "description", "dim", "duration", "frames", "physics",
                            "objects", "script", "verdict"});
  ScenarioSpec s;
  s.file = path;
  s.name = c.text(root.value("name", Json()), "name");
  s.description = root.contains("description") ? c.text(root["description"], "description") : "";
  s.dim = static_cast<int>(c.number(root.value("dim", Json(4)), "dim", 3, 4));
  s.duration = c.number(root.value("duration", Json()), "duration", 1e-3, 1e4);
  s.frames = static_cast<int>(c.number(root.value("frames", Json(4)), "frames", 1, 1000));
  if (root.contains("physics")) parse_physics(root["physics"], c, s.dim, s.physics);

  const Json& objs = root.value("objects", Json());
  if (!objs.is_array() || objs.empty()) c.fail("objects", "must be a non-empty array");
  for (std::size_t i = 0; i < objs.size(); ++i) {
    const std::string w = "objects[" + std::to_string(i) + "]";
    const Json& o = objs[i];
    c.keys(o, w, {"name", "generator", "params", "scale", "matrix", "mirror", "w_by_row", "offset", "mass"});
    ObjectSpec ob;
    ob.name = c.text(o.value("name", Json()), w + ".name");
    ob.generator.name = c.text(o.value("generator", Json()), w + ".generator");
    if (!find_generator(ob.generator.name))
      c.fail(w + ".generator", "unknown generator '" + ob.generator.name + "'");
    if (o.contains("params")) {
      if (!o["params"].is_object()) c.fail(w + ".params", "must be an object");
      for (const auto& [k, v] : o["params"].items())
        ob.generator.params[k] = c.number(v, w + ".params." + k, -1e9, 1e9);
    }
    if (o.contains("scale")) ob.scale = c.number(o["scale"], w + ".scale", 1e-6, 1e6);
    if (o.contains("matrix")) ob.matrix = c.vec(o["matrix"], w + ".matrix", 16);
    if (o.contains("mirror")) {
      if (!o["mirror"].is_array()) c.fail(w + ".mirror", "must be an array of axes");
      for (const Json& a : o["mirror"])
        ob.mirror.push_back(static_cast<int>(c.number(a, w + ".mirror", 0, s.dim - 1)));
    }
    if (o.contains("w_by_row")) {
      if (s.dim != 4) c.fail(w + ".w_by_row", "only makes sense in R^4");
      ob.w_by_row = c.number(o["w_by_row"], w + ".w_by_row", -100, 100);
    }
    if (o.contains("offset")) ob.offset = c.vec(o["offset"], w + ".offset", s.dim);
    if (o.contains("mass")) ob.mass = c.number(o["mass"], w + ".mass", 0, 1e3);
    for (const ObjectSpec& prev : s.objects)
      if (prev.name == ob.name) c.fail(w + ".name", "'" + ob.name + "' is used twice");
    s.objects.push_back(std::move(ob));
  }
  auto known = [&](const std::string& name, const std::string& where) {
    for (const ObjectSpec& o : s.objects)
      if (o.name == name) return;
    c.fail(where, "no object named '" + name + "'");
  };

  if (root.contains("script")) {
    const Json& sc = root["script"];
    if (!sc.is_array()) c.fail("script", "must be an array");
    for (std::size_t i = 0; i < sc.size(); ++i) {
      const std::string w = "script[" + std::to_string(i) + "]";
      const Json& a = sc[i];
      c.keys(a, w, {"action", "select", "from", "to", "by", "stiffness", "max_force"});
      Action act;
      act.kind = c.text(a.value("action", Json()), w + ".action");
      if (act.kind != "hold" && act.kind != "move" && act.kind != "pull")
        c.fail(w + ".action", "must be hold, move or pull");
      act.select = parse_selection(a.value("select", Json()), c, w + ".select", s.dim);
      known(act.select.object, w + ".select.object");
      act.from = c.number(a.value("from", Json(0)), w + ".from", 0, 1e4);
      act.to = c.number(a.value("to", Json(act.from)), w + ".to", act.from, 1e4);
      act.by = a.contains("by") ? c.vec(a["by"], w + ".by", s.dim) : std::vector<double>(s.dim, 0.0);
      if (a.contains("stiffness")) act.stiffness = c.number(a["stiffness"], w + ".stiffness", 0, 1e9);
      if (a.contains("max_force")) act.max_force = c.number(a["max_force"], w + ".max_force", 0, 1e9);
      s.script.push_back(act);
    }
  }

  const Json& v = root.value("verdict", Json());
  c.keys(v, "verdict", {"kind", "object", "close_via", "numbers", "view"});
  s.verdict.kind = c.text(v.value("kind", Json()), "verdict.kind");
  const std::set<std::string> kinds{"untied", "knotted", "slides-off", "lifted", "deforms", "shadow-clean"};
  if (!kinds.count(s.verdict.kind))
    c.fail("verdict.kind", "must be untied, knotted, slides-off, lifted, deforms or shadow-clean");
  if (v.contains("view")) {
    s.verdict.view = c.text(v["view"], "verdict.view");
    try {
      parse_rotation_list(s.verdict.view, 4);
    } catch (const Error& e) {
      c.fail("verdict.view", e.what());
    }
  }
  if (s.verdict.kind == "shadow-clean" && s.dim != 4) c.fail("verdict.kind", "shadow-clean needs dim 4");
  s.verdict.object = c.text(v.value("object", Json()), "verdict.object");
  known(s.verdict.object, "verdict.object");
  if (v.contains("close_via")) s.verdict.close_via = c.vec(v["close_via"], "verdict.close_via", s.dim);
  if (v.contains("numbers")) {
    if (!v["numbers"].is_object()) c.fail("verdict.numbers", "must be an object");
    for (const auto& [k, x] : v["numbers"].items())
      s.verdict.numbers[k] = c.number(x, "verdict.numbers." + k, -1e9, 1e9);
  }
  return s;
}

}  // namespace s4d::scenario
