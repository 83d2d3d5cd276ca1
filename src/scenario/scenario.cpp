// The "scenario" section of a scenario file: parsed and validated here; the rest of the file is a
// scene, read by io/scene.
#include "scenario/scenario.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "core/error.hpp"
#include "core/plane.hpp"
#include "io/text_scanner.hpp"
#include "scenario/world_builder.hpp"

namespace s4d {
namespace {

using Json = nlohmann::json;

struct Ctx {
  std::string file;
  [[noreturn]] void fail(const std::string& where, const std::string& msg) const {
    throw ParseError(file, 0, "scenario." + where + ": " + msg);
  }
  void keys(const Json& j, const std::string& where, std::set<std::string> allowed) const {
    if (!j.is_object()) fail(where, "must be an object");
    for (const auto& [k, v] : j.items())
      if (!allowed.count(k)) {
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(where, "unknown key '" + k + "' (expected one of: " + list + ")");
      }
  }
  double number(const Json& j, const std::string& where, double lo, double hi) const {
    if (!j.is_number()) fail(where, "must be a number");
    const double x = j.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi)
      fail(where, "must be in [" + format_double(lo) + ", " + format_double(hi) + "]");
    return x;
  }
  int integer(const Json& j, const std::string& where, double lo, double hi) const {
    const double x = number(j, where, lo, hi);
    if (x != std::floor(x)) fail(where, "must be a whole number");
    return static_cast<int>(x);
  }
  std::string text(const Json& j, const std::string& where) const {
    if (!j.is_string()) fail(where, "must be a string");
    return j.get<std::string>();
  }
  std::vector<double> vec(const Json& j, const std::string& where, int n) const {
    if (!j.is_array() || static_cast<int>(j.size()) != n)
      fail(where, "must be an array of " + std::to_string(n) + " numbers (the scene is simulated in R^" +
                      std::to_string(n) + ")");
    std::vector<double> v;
    for (std::size_t i = 0; i < j.size(); ++i)
      v.push_back(number(j[i], where + "[" + std::to_string(i) + "]", -1e6, 1e6));
    return v;
  }
};

VertexSelection parse_selection(const Json& j, const Ctx& c, const std::string& where, int dim) {
  c.keys(j, where, {"object", "all", "extreme", "vertices"});
  VertexSelection s;
  s.object = c.text(j.value("object", Json()), where + ".object");
  if (j.contains("all")) {
    if (!j["all"].is_boolean()) c.fail(where + ".all", "must be true or false");
    s.all = j["all"].get<bool>();
  }
  if (j.contains("extreme")) {
    const Json& e = j["extreme"];
    c.keys(e, where + ".extreme", {"axis", "side", "count"});
    s.axis = c.integer(e.value("axis", Json()), where + ".extreme.axis", 0, dim - 1);
    const std::string side = c.text(e.value("side", Json("max")), where + ".extreme.side");
    if (side != "max" && side != "min") c.fail(where + ".extreme.side", "must be \"min\" or \"max\"");
    s.max_side = side == "max";
    s.count = c.integer(e.value("count", Json(1)), where + ".extreme.count", 1, 1e6);
  } else if (j.contains("vertices")) {
    if (!j["vertices"].is_array() || j["vertices"].empty())
      c.fail(where + ".vertices", "must be a non-empty array");
    for (const Json& v : j["vertices"]) s.indices.push_back(c.integer(v, where + ".vertices", -1e9, 1e9));
  } else if (!s.all) {
    c.fail(where, "needs \"all\": true, \"vertices\" or an \"extreme\" selection");
  }
  return s;
}

}  // namespace

int Scenario::object_index(const std::string& object) const {
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].name == object) return static_cast<int>(i);
  return -1;
}

Scenario scenario_of_scene(Scene scene, const std::filesystem::path& origin) {
  const Ctx c{origin.string()};
  if (scene.scenario.empty())
    throw ParseError(c.file, 0, "a scene, not a scenario: it has no \"scenario\" section (see scenarios/)");
  const Json root = Json::parse(scene.scenario);  // io/scene checked that it is a JSON object
  c.keys(root, "", {"name", "figure", "summary", "instruction", "duration", "frames", "script", "hints", "verdict"});
  Scenario s;
  s.file = origin;
  s.dim = surface_dimension(scene);
  if (s.dim == 0) throw ParseError(c.file, 0, "objects: a scenario needs at least one surface to simulate");
  s.scene = std::move(scene);
  s.description = s.scene.description;
  s.name = c.text(root.value("name", Json()), "name");
  if (s.name.empty()) c.fail("name", "must not be empty");
  s.instruction = root.contains("instruction") ? c.text(root["instruction"], "instruction") : "";
  s.figure = root.contains("figure") ? c.text(root["figure"], "figure") : "";
  s.summary = root.contains("summary") ? c.text(root["summary"], "summary") : "";
  s.duration = c.number(root.value("duration", Json()), "duration", 1e-3, 1e4);
  s.frames = c.integer(root.value("frames", Json(4)), "frames", 1, 1000);
  auto known = [&](const std::string& name, const std::string& where) {
    if (s.object_index(name) < 0) c.fail(where, "no object named '" + name + "'");
    if (!is_surface(s.scene.objects[static_cast<std::size_t>(s.object_index(name))].shape))
      c.fail(where, "'" + name + "' is a curve; scenarios simulate surfaces");
  };

  if (root.contains("script")) {
    const Json& sc = root["script"];
    if (!sc.is_array()) c.fail("script", "must be an array");
    for (std::size_t i = 0; i < sc.size(); ++i) {
      const std::string w = "script[" + std::to_string(i) + "]";
      const Json& a = sc[i];
      c.keys(a, w, {"action", "select", "from", "to", "by", "stiffness", "max_force", "by_hand", "rings", "radius"});
      ScriptAction act;
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
      if (a.contains("radius"))
        c.fail(w + ".radius", "a carried patch is counted in rings of mesh edges now: write \"rings\": N (the "
                              "vertices within N edges of the selected ones)");
      if (a.contains("rings")) act.rings = c.integer(a["rings"], w + ".rings", 0, 1000);
      if (a.contains("by_hand")) {
        const std::string h = c.text(a["by_hand"], w + ".by_hand");
        if (h == "skip") act.by_hand = ByHand::kSkip;
        else if (h == "keep") act.by_hand = ByHand::kKeep;
        else if (h == "until-grabbed") act.by_hand = ByHand::kUntilGrabbed;
        else if (h == "only") act.by_hand = ByHand::kOnly;
        else c.fail(w + ".by_hand", "must be skip, keep, until-grabbed or only");
      }
      s.script.push_back(act);
    }
  }
  if (root.contains("hints")) {
    const Json& hs = root["hints"];
    if (!hs.is_array()) c.fail("hints", "must be an array");
    for (std::size_t i = 0; i < hs.size(); ++i) {
      const std::string w = "hints[" + std::to_string(i) + "]";
      c.keys(hs[i], w, {"select", "by", "say"});
      Hint h;
      h.select = parse_selection(hs[i].value("select", Json()), c, w + ".select", s.dim);
      known(h.select.object, w + ".select.object");
      h.by = hs[i].contains("by") ? c.vec(hs[i]["by"], w + ".by", s.dim) : std::vector<double>(s.dim, 0.0);
      h.say = hs[i].contains("say") ? c.text(hs[i]["say"], w + ".say") : "";
      s.hints.push_back(std::move(h));
    }
  } else {  // the person's part of the script: its moves and pulls that by hand are theirs
    for (const ScriptAction& a : s.script)
      if (a.kind != "hold" && a.by_hand == ByHand::kSkip) s.hints.push_back({a.select, a.by, ""});
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
  if (s.verdict.kind == "shadow-clean" && s.dim != 4)
    c.fail("verdict.kind", "shadow-clean needs a surface of R^4");
  s.verdict.object = c.text(v.value("object", Json()), "verdict.object");
  known(s.verdict.object, "verdict.object");
  if (v.contains("close_via")) s.verdict.close_via = c.vec(v["close_via"], "verdict.close_via", s.dim);
  if (v.contains("numbers")) {
    if (!v["numbers"].is_object()) c.fail("verdict.numbers", "must be an object");
    for (const auto& [k, x] : v["numbers"].items())
      s.verdict.numbers[k] = k == "axis" ? c.integer(x, "verdict.numbers.axis", 0, s.dim - 1)
                                         : c.number(x, "verdict.numbers." + k, -1e9, 1e9);
  }
  return s;
}

Scenario load_scenario(const std::filesystem::path& path) { return scenario_of_scene(load_scene(path), path); }

}  // namespace s4d
