// `shadow4d sketch-ribbon SCENE STROKE --out OUT.json`: Create > Sketch a ribbon without the
// window. A recorded stroke (x y z u in the shadow, u = 1 where the modifier was held) becomes a
// ribbon of R^4 that passes above the other surfaces, or below where u = 1, added to the scene.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "command.hpp"
#include "core/error.hpp"
#include "core/plane.hpp"
#include "interact/tools/ribbon_sketch.hpp"
#include "io/scene.hpp"

namespace s4d::cli {
namespace {

struct SketchRibbonOptions {
  std::string scene, stroke, out, rotate, name = "ribbon";
  double dt = 1.0 / 120.0;
  bool open = false;  // keep a stroke that comes back to its start open
  RibbonSketchOptions ribbon;
};

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

void run(const SketchRibbonOptions& opt) {
  Scene scene = load_scene_or_object(opt.scene);
  apply_rotations(scene.frame, parse_rotation_list(opt.rotate, 4));
  const std::vector<RibbonStrokeSample> stroke = read_ribbon_stroke(opt.stroke, opt.dt);

  const SketchObstacles others = sketch_obstacles(scene);
  // The eye of the scene's camera, as the window's sketch plane faces it.
  const Vec3 eye = scene.view.trackball.normalized() * Vec3::UnitZ();
  RibbonSketchOptions o = opt.ribbon;
  if (opt.open && o.closed) throw Error("--open and --closed contradict each other; give one of them");
  // As in the window: a stroke that comes back to where it began is a loop.
  const bool came_back = !o.closed && !opt.open && ribbon_stroke_comes_back(stroke, o.width);
  if (came_back) {
    o.closed = true;
    std::cout << "a loop: the stroke came back to its start (--open keeps it open)\n";
  }
  const SketchedRibbon r = ribbon_from_sketch(stroke, others.surfaces, scene.frame, eye, o, others.names);
  const std::string name = add_sketched_ribbon(scene, r, opt.name);
  if (const auto dir = std::filesystem::path(opt.out).parent_path(); !dir.empty()) std::filesystem::create_directories(dir);
  save_scene(scene, opt.out);

  if (!r.changes.empty()) std::cout << r.changes << "\n";
  const Grid& g = *r.surface.grid;
  std::cout << "ribbon '" << name << "': " << g.rows << " rows x " << g.cols << " ("
            << r.surface.vertex_count() << " vertices, " << r.surface.triangle_count() << " triangles), length "
            << num(r.length) << ", width " << num(opt.ribbon.width) << ", " << (g.wrap_i ? "closed" : "open")
            << "; clearance " << num(r.clearance) << " in w\n";
  if (r.passages.empty()) std::cout << "no passages: its shadow meets no other surface's shadow, nor its own\n";
  for (std::size_t k = 0; k < r.passages.size(); ++k) {
    const RibbonPassage& p = r.passages[k];
    const std::string what = p.surface < 0 ? "itself" : "'" + others.names[p.surface] + "'";
    std::cout << "passage " << k + 1 << " at " << num(p.at_length) << " along it, (" << num(p.place.x()) << ", "
              << num(p.place.y()) << ", " << num(p.place.z()) << "): " << (p.below ? "below " : "above ") << what
              << " (w " << num(p.ribbon_w) << (p.below ? " under " : " over ") << num(p.other_w) << ", gap >= "
              << num(p.gap) << ")\n";
  }
  if (std::isfinite(r.gap_to_others))
    std::cout << "embedded: smallest 4D gap to the other surfaces " << num(r.gap_to_others) << "\n";
  else if (!others.surfaces.empty())
    std::cout << "embedded: no other surface within " << num(4 * r.clearance) << " in R^4\n";
  else
    std::cout << "embedded\n";
  if (others.curves > 0)
    std::cout << "note: " << others.curves << " curve object(s) are not surfaces; the ribbon was not checked against them\n";
  std::cout << "wrote " << opt.out << "\n";
}

const CommandRegistrar kSketchRibbon(
    "sketch-ribbon",
    "sketch a ribbon of R^4 from a recorded stroke in the shadow (x y z u, u = 1 where it passes below)",
    [](CLI::App& sub) {
      auto opt = std::make_shared<SketchRibbonOptions>();
      sub.add_option("scene", opt->scene, "scene (.json), mesh or generator call the ribbon is drawn into")
          ->required();
      sub.add_option("stroke", opt->stroke, "stroke file: one sample per line, x y z u (u = 1: modifier held)")
          ->required();
      sub.add_option("--out", opt->out, "the scene with the ribbon added (.json)")->required();
      sub.add_option("--rotate", opt->rotate, "rotations of the 4D view, degrees, in order, e.g. xw=30,yz=10");
      sub.add_option("--width", opt->ribbon.width, "ribbon width, scene units")->capture_default_str();
      sub.add_flag("--closed", opt->ribbon.closed,
                   "join the stroke's end to its start (a ribbon loop; the default when it comes back there)");
      sub.add_flag("--open", opt->open, "keep a stroke that comes back to its start open");
      sub.add_option("--clearance", opt->ribbon.clearance, "w gap at every passage (default 0.05 of the stroke's size)");
      sub.add_option("--spacing", opt->ribbon.spacing, "between rows (default min(width/2, size/60))");
      sub.add_option("--across", opt->ribbon.across, "vertices across (2..64)")->capture_default_str();
      sub.add_option("--smoothing", opt->ribbon.smoothing, "length over which w is smoothed (default 0.25 of the size)");
      sub.add_option("--max-move", opt->ribbon.max_move,
                     "widths the centre line may be smoothed off the stroke where the ribbon would fold (0: never)")
          ->capture_default_str();
      sub.add_option("--dt", opt->dt, "seconds between stroke samples")->capture_default_str();
      sub.add_option("--name", opt->name, "the new object's name")->capture_default_str();
      sub.callback([opt] { run(*opt); });
    });

}  // namespace
}  // namespace s4d::cli
