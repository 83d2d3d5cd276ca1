// `shadow4d check <mesh.4off|scene.json|generator-call>`: reports true 4D self-intersections
// and the shadow's intersection curves (count, length, shadow-only vs true) per surface object and
// between objects. Exit code 0: embedded; 2: true intersections exist; 1: error.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "command.hpp"
#include "view_options.hpp"
#include "core/error.hpp"
#include "io/scene.hpp"
#include "proximity/self_intersections.hpp"
#include "proximity/shadow_crossings.hpp"
#include "proximity/shadow_intersections.hpp"

namespace s4d::cli {
namespace {

struct CheckOptions {
  std::string input;
  std::string rotate;
  bool json = false;
  double tolerance = -1;
};

nlohmann::json shadow_json(const ShadowIntersections& s) {
  return {{"curves", s.curves.size()},
          {"segments", s.segments.size()},
          {"total_length", s.total_length},
          {"shadow_only_curves", s.shadow_only_curves},
          {"true_curves", s.true_curves},
          {"coplanar_pairs", s.coplanar_pairs},
          {"generic_view", s.coplanar_pairs == 0}};
}

std::string shadow_text(const ShadowIntersections& s) {
  ShadowCurveCounts c;
  c.add(s);
  std::string t = counts_text(c) + "\n";
  // Where sheets of the shadow overlap in area (the Clifford torus or the spun trefoil seen
  // straight along w), the curves are only where those areas happen to cut: say what to do.
  if (s.coplanar_pairs > 0)
    t += "  note: " + std::to_string(s.coplanar_pairs) +
         " triangle pair(s) of the shadow overlap in area, where no curve is defined;\n"
         "  a turned view (e.g. --rotate xw=30,yw=20) gives curves that mean something\n";
  return t;
}

// Sheets of surfaces in R^3 meet along curves, not at points: seen straight on, lifted surfaces
// are their own shadow, whose curves are exactly those. Adds them to o; returns the text line.
std::string curves_in_r3(const std::string& label, std::size_t pairs,
                         const ShadowIntersections& in3, nlohmann::json& o) {
  o["true_intersection_curves"] = in3.curves.size();
  o["true_intersection_length"] = in3.total_length;
  std::ostringstream t;
  t << "  " << label << " in R^3: " << pairs << " triangle pair(s), " << in3.curves.size()
    << " curve(s) of total length " << std::setprecision(6) << in3.total_length << "\n";
  return t.str();
}

// Two sheets in R^4 meet at isolated points: the line for a surface itself or a pair of them.
std::string points_in_r4(const std::string& label, std::size_t pairs, std::size_t points) {
  return "  " + label + ": " + std::to_string(pairs) + " triangle pair(s), " +
         std::to_string(points) + " distinct point(s)\n";
}

Surface<4> as_4d_surface(const Shape& shape) {
  if (const auto* s4 = std::get_if<Surface<4>>(&shape)) return *s4;
  return lift_to_4d(std::get<Surface<3>>(shape));
}

// Runs the check; returns the number of true 4D intersection points found.
std::size_t run_check(const CheckOptions& opt) {
  Scene scene = load_scene_or_object(opt.input);
  apply_rotations(scene.frame, parse_rotation_list(opt.rotate, 4));
  IntersectionOptions iopt;
  iopt.tolerance = opt.tolerance;

  // Which view the shadow's numbers are of: the window turns a bare object of R^4 (no scene file
  // saying how to look at it) by xw 30, zw 20, so say how to see what it shows.
  const std::string view = view_described(opt.input, opt.rotate);
  if (!opt.json) std::cout << "view: " << view << "\n";
  nlohmann::json out = {{"input", opt.input}, {"view", view}, {"objects", nlohmann::json::array()},
                        {"between", nlohmann::json::array()}};
  std::size_t true_points = 0;
  struct Checked {
    std::string name;
    int dim = 4;
    Surface<4> surface;
  };
  std::vector<Checked> surfaces;
  // Seen straight on (no --rotate, no frame in the scene), the shadow's intersection curves of
  // surfaces in R^3 are their true ones: found once.
  const bool straight = scene.frame.matrix() == Frame<4>().matrix();
  for (const SceneObject& obj : scene.objects) {
    if (is_surface(obj.shape)) {
      Surface<4> s = as_4d_surface(obj.shape);
      const auto self = self_intersections<4>(s, iopt);
      const ShadowIntersections shadow = shadow_intersections(s, scene.frame);
      true_points += self.points.size();
      const int dim = ambient_dim(obj.shape);
      nlohmann::json o = {{"name", obj.name},
                          {"kind", "surface"},
                          {"dim", dim},
                          {"vertices", s.vertices.size()},
                          {"triangles", s.triangles.size()},
                          {"true_intersection_pairs", self.pairs.size()},
                          {"true_intersection_points", self.points.size()},
                          {"shadow", shadow_json(shadow)}};
      const std::string own =
          dim == 3 ? curves_in_r3("true self-intersections", self.pairs.size(),
                                  straight ? shadow : shadow_intersections(s, Frame<4>()), o)
                   : points_in_r4("true 4D self-intersections", self.pairs.size(),
                                  self.points.size());
      out["objects"].push_back(std::move(o));
      if (!opt.json)
        std::cout << "object '" << obj.name << "' (surface in R^" << dim << ", "
                  << s.triangles.size() << " triangles)\n"
                  << own << "  shadow intersection curves: " << shadow_text(shadow);
      surfaces.push_back({obj.name, dim, std::move(s)});
    } else {
      // Curves: segments of the same curve that touch, and crossings of the 2D/3D shadow.
      std::size_t pairs = 0, points = 0, crossings = 0;
      auto check_curve = [&](const auto& curve) {
        constexpr int D = std::decay_t<decltype(curve)>::kDim;
        std::vector<Vec<D>> x;
        std::vector<Cell<2>> cells;
        for (const auto& c : curve.components) {
          const int base = static_cast<int>(x.size());
          const int n = static_cast<int>(c.points.size());
          for (const auto& p : c.points) x.push_back(p);
          for (int k = 0; k < static_cast<int>(c.segment_count()); ++k)
            cells.push_back({base + k, base + (k + 1) % n});
        }
        Box<D> box;
        for (const auto& p : x) box.add(p);
        const double diag = x.empty() ? 1.0 : std::max((box.hi - box.lo).norm(), 1e-300);
        const double tol = opt.tolerance >= 0 ? opt.tolerance : 1e-9 * diag;
        const auto hits = intersecting_pairs<D, 2>(x, cells, tol);
        std::vector<Vec<D>> mids;
        for (const auto& h : hits) mids.push_back(0.5 * (h.closest.p + h.closest.q));
        pairs = hits.size();
        points = merge_points<D>(mids, 1e-6 * diag).size();
        if constexpr (D == 3) {
          // A 3D curve is seen through the 3D part of the frame: the same 4D frame restricted
          // to xyz would mix in w; knots are viewed straight on.
          crossings = shadow_crossings<3>(curve, Frame<3>()).crossings.size();
        } else {
          crossings = shadow_crossings<4>(curve, scene.frame).crossings.size();
        }
      };
      std::visit(
          [&](const auto& shape) {
            if constexpr (requires { shape.components; }) check_curve(shape);
          },
          obj.shape);
      true_points += points;
      out["objects"].push_back({{"name", obj.name},
                                {"kind", "curve"},
                                {"dim", ambient_dim(obj.shape)},
                                {"true_intersection_pairs", pairs},
                                {"true_intersection_points", points},
                                {"shadow_crossings", crossings}});
      if (!opt.json)
        std::cout << "object '" << obj.name << "' (curve in R^" << ambient_dim(obj.shape) << ")\n"
                  << "  true self-intersections: " << pairs << " segment pair(s), " << points
                  << " distinct point(s)\n"
                  << "  shadow crossings: " << crossings << "\n";
    }
  }
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    for (std::size_t j = i + 1; j < surfaces.size(); ++j) {
      const auto& [na, da, a] = surfaces[i];
      const auto& [nb, db, b] = surfaces[j];
      const auto meet = surface_intersections<4>(a, b, iopt);
      const ShadowIntersections shadow = shadow_intersections(a, b, scene.frame);
      true_points += meet.points.size();
      nlohmann::json o = {{"a", na},
                          {"b", nb},
                          {"true_intersection_pairs", meet.pairs.size()},
                          {"true_intersection_points", meet.points.size()},
                          {"shadow", shadow_json(shadow)}};
      const std::string both =
          da == 3 && db == 3
              ? curves_in_r3("true intersections", meet.pairs.size(),
                             straight ? shadow : shadow_intersections(a, b, Frame<4>()), o)
              : points_in_r4("true 4D intersections", meet.pairs.size(), meet.points.size());
      out["between"].push_back(std::move(o));
      if (!opt.json)
        std::cout << "objects '" << na << "' and '" << nb << "'\n"
                  << both << "  shadow intersection curves: " << shadow_text(shadow);
    }
  out["true_intersection_points"] = true_points;
  out["embedded"] = true_points == 0;
  if (opt.json)
    std::cout << out.dump(2) << "\n";
  else
    std::cout << (true_points == 0 ? "result: embedded, no true intersections\n"
                                   : "result: not embedded: " + std::to_string(true_points) +
                                         " true intersection(s)\n");
  return true_points;
}

const CommandRegistrar kCheck(
    "check",
    "report true 4D self-intersections and the shadow's intersection curves (exit 0 embedded, 2 "
    "intersecting, 1 error)",
    [](CLI::App& sub) {
      auto opt = std::make_shared<CheckOptions>();
      sub.add_option("input", opt->input, "scene (.json), mesh (.off/.4off), curve or generator call")
          ->required();
      sub.add_option("--rotate", opt->rotate,
                     "rotations of the 4D view, degrees, in order, e.g. xw=30,yz=10");
      sub.add_flag("--json", opt->json, "machine-readable output");
      const CLI::Option* tolerance = sub.add_option(
          "--tolerance", opt->tolerance,
          "distance below which primitives count as meeting (scene units; default 1e-9 of the "
          "object's size)");
      sub.callback([opt, tolerance] {
        // Negative stands for the default inside: a user's negative or NaN is a mistake to say.
        if (tolerance->count() > 0 && !(opt->tolerance >= 0 && std::isfinite(opt->tolerance)))
          throw Error("check: --tolerance must be a finite distance >= 0 (scene units)");
        if (run_check(*opt) > 0) throw ExitStatus{2};
      });
    });

}  // namespace
}  // namespace s4d::cli
