// `shadow4d slice`: the motion picture of a scene's surfaces of R^4: their slices by the
// hyperplanes w = c of the 4D view at evenly spaced levels, each drawn on the faded shadow and
// named as a link (one contact sheet), its crossing diagram as SVG, and the critical levels
// where circles are born, join or split, and die.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "command.hpp"
#include "core/error.hpp"
#include "io/image.hpp"
#include "io/scene.hpp"
#include "io/text_scanner.hpp"
#include "knots/slice_naming.hpp"
#include "render/diagram_export.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "render/scene_geometry.hpp"
#include "shape/level_set.hpp"
#include "view/scene_slice.hpp"
#include "view_options.hpp"

namespace s4d::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct SliceArgs {
  std::string input;
  std::string out;
  int levels = 9;
  int columns = 0;
  bool json_out = false;
  bool fast = false;
  ViewOptions view;
};

std::string level_text(double c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.3f", c);
  return buf;
}

// Breaks `text` at spaces into lines no wider than `width` pixels (a word wider stays whole).
std::string wrapped(const std::string& text, int width, int scale) {
  std::string out, line, word;
  auto flush_word = [&] {
    if (word.empty()) return;
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && text_width(longer, scale) > width) {
      out += (out.empty() ? "" : "\n") + line;
      line = word;
    } else {
      line = longer;
    }
    word.clear();
  };
  for (char ch : text) {
    if (ch == ' ') flush_word();
    else word += ch;
  }
  flush_word();
  if (!line.empty()) out += (out.empty() ? "" : "\n") + line;
  return out;
}

json naming_record(const SliceNaming& n, const std::string& svg) {
  json j;
  j["level"] = n.level;
  j["name"] = n.name;
  j["label"] = n.label;
  j["proven"] = n.proven;
  j["components"] = n.components;
  j["open_components"] = n.open_components;
  j["candidates"] = n.candidates;
  j["linking"] = n.linking;
  j["decided_by"] = n.decided_by;
  if (!n.error.empty()) j["error"] = n.error;
  j["svg"] = svg.empty() ? json(nullptr) : json(svg);
  return j;
}

void run_slice(const SliceArgs& a) {
  if (a.levels < 1 || a.levels > 400) throw Error("slice: --levels should be 1..400, not " + std::to_string(a.levels));
  if (a.columns < 0) throw Error("slice: --columns should be positive (or 0 for about square)");
  Scene scene = load_scene_or_object(a.input);
  a.view.apply(scene);
  if (!has_4d_surfaces(scene))
    throw Error("slice: " + a.input + " has no surface of R^4 to slice (slices cut surfaces of R^4 by w = c)");
  const auto [w, h] = a.view.parsed_size();
  const auto t0 = std::chrono::steady_clock::now();

  const auto [lo, hi] = scene_depth_range(scene);
  const std::vector<double> levels = movie_levels(lo, hi, a.levels);
  const std::vector<SceneCriticalPoint> critical = scene_critical_points(scene);
  std::vector<CriticalPoint> points;
  for (const SceneCriticalPoint& p : critical) points.push_back(p.point);
  const CriticalCount count = count_critical(points);

  // Every frame framed alike: the camera fits the whole scene, the surfaces faded behind the slice.
  Scene base = scene;
  const BoundingSphere ball = build_scene_geometry(scene, static_cast<double>(w) / h).bounds;
  base.view.fit_centre = ball.centre;
  base.view.fit_radius = ball.radius;
  base.view.slice = true;  // drawn as the window draws it: amber tubes over the faded surfaces
  if (!a.view.tube_radius) base.view.tube_radius *= 1.6;  // small frames: a thicker slice reads better

  fs::create_directories(a.out);
  NamingOptions naming;
  naming.fast = a.fast;
  OffscreenContext context;
  RenderTarget target(w, h, 4);
  Renderer renderer;  // declared after the context: destroyed first, while it is still current
  std::vector<Image> frames;
  std::vector<std::string> labels;
  json records = json::array();
  const int digits = a.levels >= 100 ? 3 : 2;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const double c = levels[i];
    const SceneSlice slice = scene_slice(scene, c);
    const SliceNaming n = name_slice(slice.curve, c, naming);
    Scene shot = base;
    shot.view.slice_level = c;
    target.bind();
    renderer.draw(shot, w, h);
    frames.push_back(target.resolve_and_read());
    labels.push_back(wrapped("w " + level_text(c) + ": " + n.label + (n.proven || n.components == 0 ? "" : " ?"),
                             w, 1));

    std::string svg;
    if (!slice.curve.components.empty()) {
      Scene flat = base;
      flat.view.slice = false;
      flat.objects = {slice_object(slice, scene.frame, "slice")};
      char name[32];
      std::snprintf(name, sizeof name, "slice-%0*d.svg", digits, static_cast<int>(i));
      svg = (fs::path(a.out) / name).string();
      write_text_file(svg, diagram_svg(view_diagram(flat, w, h), flat, w, h));
    }
    records.push_back(naming_record(n, svg));
    if (!a.json_out) std::cout << "w " << level_text(c) << "  " << n.headline() << "\n";
  }

  std::string title = a.input + ": " + std::to_string(levels.size()) + " slices w = c of the 4D view\n" +
                      "critical levels: " + std::to_string(count.births) + " births, " +
                      std::to_string(count.saddles) + " saddles, " + std::to_string(count.deaths) +
                      " deaths (Euler characteristic " + std::to_string(count.euler_characteristic()) + ")";
  SheetLayout layout;
  layout.text_scale = 1;
  layout.columns = a.columns > 0 ? a.columns
                                 : static_cast<int>(std::ceil(std::sqrt(static_cast<double>(levels.size()) * h / w)));
  const fs::path sheet = fs::path(a.out) / "slices.png";
  write_png(contact_sheet(frames, labels, title, layout), sheet);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  if (a.json_out) {
    json j;
    j["input"] = a.input;
    j["sheet"] = sheet.string();
    j["range"] = {lo, hi};
    j["levels"] = records;
    json crit = json::array();
    for (const SceneCriticalPoint& p : critical)
      crit.push_back({{"level", p.point.level},
                      {"kind", critical_kind_name(p.point.kind)},
                      {"multiplicity", p.point.multiplicity},
                      {"object", scene.objects[p.object].name},
                      {"vertex", p.point.vertex}});
    j["critical"] = crit;
    j["counts"] = {{"births", count.births},
                   {"saddles", count.saddles},
                   {"deaths", count.deaths},
                   {"euler_characteristic", count.euler_characteristic()}};
    j["seconds"] = seconds;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << "critical levels: " << count.births << " births, " << count.saddles << " saddles, "
              << count.deaths << " deaths (Euler characteristic " << count.euler_characteristic() << ")\n";
    for (const SceneCriticalPoint& p : critical)
      std::cout << "  w " << level_text(p.point.level) << "  " << critical_kind_name(p.point.kind)
                << (p.point.multiplicity > 1 ? " x" + std::to_string(p.point.multiplicity) : "") << "  ("
                << scene.objects[p.object].name << ", vertex " << p.point.vertex << ")\n";
    std::cout << sheet.string() << "\n";
  }
}

const CommandRegistrar kSlice(
    "slice",
    "the motion picture of a scene's surfaces of R^4: slices by w = c of the 4D view at evenly spaced "
    "levels, each drawn and named, as a contact sheet PNG and an SVG diagram per level, with the "
    "critical levels (e.g. shadow4d slice spun-trefoil --levels 9 --out movie --json)",
    [](CLI::App& sub) {
      auto args = std::make_shared<SliceArgs>();
      args->view.size = "320x240";
      sub.add_option("input", args->input,
                     "scene.json, scenario, mesh (.4off) or generator call such as spun-trefoil:n=64 "
                     "(see `shadow4d generators`)")
          ->required();
      sub.add_option("--out,-o", args->out, "folder for slices.png and slice-NN.svg")->required();
      sub.add_option("--levels,-n", args->levels, "how many levels, evenly spaced inside the range of w")
          ->capture_default_str();
      sub.add_option("--columns", args->columns, "frames across the sheet (0: about square)");
      sub.add_flag("--json", args->json_out,
                   "print one record per level (level, name, components, ...) and the critical levels "
                   "(level, kind birth/saddle/death) as JSON");
      sub.add_flag("--fast", args->fast, "name the slices without the slow refinements (and say so)");
      args->view.add_to(sub);
      sub.callback([args] { run_slice(*args); });
    });

}  // namespace
}  // namespace s4d::cli
