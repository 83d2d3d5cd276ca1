// The generator registry: names, parameter specs and validation, and the CLI's "name:k=v" syntax.
#include "shape/generators.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <numeric>
#include <sstream>

#include "core/chars.hpp"
#include "core/error.hpp"
#include "shape/chain.hpp"
#include "shape/knot_curves.hpp"
#include "shape/ribbons.hpp"
#include "shape/spun_knot.hpp"
#include "shape/surfaces_4d.hpp"

namespace s4d {

namespace {

ParamSpec integer(std::string name, double def, double lo, double hi, std::string help) {
  return {std::move(name), def, lo, hi, true, std::move(help)};
}
ParamSpec real(std::string name, double def, double lo, double hi, std::string help) {
  return {std::move(name), def, lo, hi, false, std::move(help)};
}

// Parameter values after defaults and validation; lookups of names not in the spec are bugs.
class Values {
 public:
  explicit Values(Params p) : p_(std::move(p)) {}
  double real(const std::string& k) const { return p_.at(k); }
  int integer(const std::string& k) const { return static_cast<int>(p_.at(k)); }

 private:
  Params p_;
};

struct Entry {
  GeneratorInfo info;
  std::function<Shape(const Values&)> build;
};

std::string format_number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

const std::vector<Entry>& entries() {
  static const std::vector<Entry> table = [] {
    std::vector<Entry> t;
    const std::vector<ParamSpec> ribbon_params{
        integer("n", 300, 64, 8000, "samples along the ribbon"),
        integer("m", 4, 2, 64, "samples across the ribbon"),
        real("width", 0.15, 0.01, kMaxTrefoilRibbonWidth, "ribbon width")};
    t.push_back({{"torus-knot", "torus knot T(p,q) on a torus around the z axis (a link if gcd > 1)",
                  3, false,
                  {integer("p", 2, 1, 64, "turns around the axis"),
                   integer("q", 3, -64, 64, "turns around the tube (negative: mirror image)"),
                   integer("n", 200, 8, 20000, "points per component"),
                   real("R", 2, 0.1, 100, "distance from the axis to the tube centre"),
                   real("r", 1, 0.01, 100, "tube radius (less than R)")}},
                 [](const Values& v) -> Shape {
                   const int p = v.integer("p"), q = v.integer("q"), n = v.integer("n");
                   const int g = std::gcd(p, std::abs(q));
                   const int need = 8 * (p + std::abs(q)) / g;
                   if (n < need)
                     throw Error("n = " + std::to_string(n) + " points cannot follow T(" +
                                 std::to_string(p) + "," + std::to_string(q) +
                                 ") faithfully; use n >= " + std::to_string(need));
                   return torus_knot(p, q, n, v.real("R"), v.real("r"));
                 }});
    t.push_back({{"figure-eight", "the figure-eight knot (4_1)", 3, false,
                  {integer("n", 200, 16, 20000, "points")}},
                 [](const Values& v) -> Shape { return figure_eight_knot(v.integer("n")); }});
    t.push_back({{"trefoil-ribbon", "open ribbon with a loose trefoil tied in it, in R^4 at w = 0",
                  4, true, ribbon_params},
                 [](const Values& v) -> Shape {
                   return lift_to_4d(
                       trefoil_ribbon(v.integer("n"), v.integer("m"), v.real("width")));
                 }});
    t.push_back({{"trefoil-ribbon-3d", "open ribbon with a loose trefoil tied in it, in R^3", 3,
                  true, ribbon_params},
                 [](const Values& v) -> Shape {
                   return trefoil_ribbon(v.integer("n"), v.integer("m"), v.real("width"));
                 }});
    t.push_back({{"cloth", "flat square cloth in the xy-plane", 4, true,
                  {integer("n", 32, 2, 2048, "vertices per side"),
                   real("size", 1, 0.01, 100, "side length")}},
                 [](const Values& v) -> Shape { return cloth(v.integer("n"), v.real("size")); }});
    t.push_back({{"clifford-torus", "flat torus (cos u, sin u, cos v, sin v) on the 3-sphere", 4,
                  true,
                  {integer("n", 48, 3, 2048, "samples of u"),
                   integer("m", 48, 3, 2048, "samples of v")}},
                 [](const Values& v) -> Shape {
                   return clifford_torus(v.integer("n"), v.integer("m"));
                 }});
    t.push_back({{"sphere", "round 2-sphere in the hyperplane w = 0", 4, true,
                  {integer("n", 32, 3, 2048, "samples around each latitude"),
                   real("radius", 1, 0.01, 100, "radius")}},
                 [](const Values& v) -> Shape {
                   return uv_sphere<4>(v.integer("n"), v.real("radius"), Vec4::Zero());
                 }});
    t.push_back({{"spun-trefoil", "Artin spin of a knotted trefoil arc: a knotted 2-sphere", 4,
                  true,
                  {integer("n", 160, 64, 4000, "samples along the arc"),
                   integer("m", 32, 8, 512, "samples of the spin angle")}},
                 [](const Values& v) -> Shape {
                   return spun_trefoil(v.integer("n"), v.integer("m"));
                 }});
    t.push_back({{"ribbon-loop", "closed ribbon (annulus) in the xy-plane, spreading along z", 4,
                  true,
                  {integer("n", 96, 3, 4096, "samples around"),
                   integer("m", 4, 2, 64, "samples across"),
                   real("radius", 1, 0.05, 100, "radius of the core circle"),
                   real("width", 0.3, 0.01, 100, "ribbon width (less than twice the radius)")}},
                 [](const Values& v) -> Shape {
                   return ribbon_loop(v.integer("n"), v.integer("m"), v.real("radius"),
                                      v.real("width"));
                 }});
    t.push_back({{"chain", "spheres and ribbon loops linked alternately in R^4, hanging along -y",
                  4, true,
                  {integer("links", 3, 1, 16, "number of elements (sphere, ribbon, sphere, ...)"),
                   integer("n", 24, 8, 512, "resolution of each element")}},
                 [](const Values& v) -> Shape { return chain(v.integer("links"), v.integer("n")); }});
    return t;
  }();
  return table;
}

const Entry* find_entry(std::string_view name) {
  for (const Entry& e : entries())
    if (e.info.name == name) return &e;
  return nullptr;
}

std::string all_names() {
  std::string s;
  for (const Entry& e : entries()) s += (s.empty() ? "" : ", ") + e.info.name;
  return s;
}

Params validated(const GeneratorInfo& info, const Params& given) {
  Params out;
  for (const ParamSpec& p : info.params) out[p.name] = p.default_value;
  for (const auto& [key, value] : given) {
    const auto spec = std::find_if(info.params.begin(), info.params.end(),
                                   [&key = key](const ParamSpec& p) { return p.name == key; });
    if (spec == info.params.end()) {
      std::string known;
      for (const ParamSpec& p : info.params) known += (known.empty() ? "" : ", ") + p.name;
      throw Error(info.name + ": unknown parameter '" + key + "' (it takes " + known + ")");
    }
    if (!std::isfinite(value))
      throw Error(info.name + ": parameter " + key + " must be a finite number");
    if (spec->integer && value != std::floor(value))
      throw Error(info.name + ": parameter " + key + " must be a whole number (got " +
                  format_number(value) + ")");
    if (value < spec->min || value > spec->max)
      throw Error(info.name + ": parameter " + key + " = " + format_number(value) +
                  " is outside [" + format_number(spec->min) + ", " + format_number(spec->max) +
                  "]");
    out[key] = value;
  }
  return out;
}

std::string_view trim(std::string_view s) {
  const auto not_space = [](char c) { return c != ' ' && c != '\t' && c != '\n' && c != '\r'; };
  while (!s.empty() && !not_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && !not_space(s.back())) s.remove_suffix(1);
  return s;
}

}  // namespace

const std::vector<GeneratorInfo>& generator_catalogue() {
  static const std::vector<GeneratorInfo> infos = [] {
    std::vector<GeneratorInfo> v;
    for (const Entry& e : entries()) v.push_back(e.info);
    return v;
  }();
  return infos;
}

const GeneratorInfo* find_generator(std::string_view name) {
  for (const GeneratorInfo& g : generator_catalogue())
    if (g.name == name) return &g;
  return nullptr;
}

Shape generate(std::string_view name, const Params& params) {
  const Entry* e = find_entry(name);
  if (!e)
    throw Error("unknown generator '" + std::string(name) + "' (known: " + all_names() + ")");
  const Values values(validated(e->info, params));
  try {
    return e->build(values);
  } catch (const Error& err) {
    // Builders report in their own terms; make sure the user sees which object failed.
    const std::string what = err.what();
    if (what.rfind(e->info.name + ":", 0) == 0) throw;
    throw Error(e->info.name + ": " + what);
  }
}

GeneratorCall parse_generator_call(std::string_view text) {
  GeneratorCall call;
  const std::string_view whole = trim(text);
  const std::size_t colon = whole.find(':');
  call.name = std::string(trim(whole.substr(0, colon)));
  if (call.name.empty())
    throw Error("'" + std::string(text) + "' does not start with a generator name");
  if (colon == std::string_view::npos) return call;

  std::string_view rest = whole.substr(colon + 1);
  if (trim(rest).empty())
    throw Error("'" + std::string(text) + "': expected key=value parameters after ':'");
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = trim(rest.substr(0, comma));
    const std::size_t eq = item.find('=');
    if (eq == std::string_view::npos)
      throw Error("'" + std::string(text) + "': parameter '" + std::string(item) +
                  "' is not of the form key=value");
    const std::string key(trim(item.substr(0, eq)));
    const std::string_view val = trim(item.substr(eq + 1));
    if (key.empty()) throw Error("'" + std::string(text) + "': a parameter has no name");
    double value = 0;
    const auto [ptr, ec] = double_from_chars(val.data(), val.data() + val.size(), value);
    if (val.empty() || ec != std::errc() || ptr != val.data() + val.size())
      throw Error("'" + std::string(text) + "': the value of " + key + " ('" + std::string(val) +
                  "') is not a number");
    if (!call.params.emplace(key, value).second)
      throw Error("'" + std::string(text) + "': parameter " + key + " is given twice");
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  return call;
}

}  // namespace s4d
