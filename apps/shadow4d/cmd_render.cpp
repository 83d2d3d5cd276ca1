// `shadow4d render`: draws a scene, file or generated object to a PNG without a display, and writes
// the crossing diagram of the same view as SVG or TikZ (no OpenGL needed for those).
#include <cmath>
#include <iostream>
#include <optional>

#include "command.hpp"
#include "core/error.hpp"
#include "io/image.hpp"
#include "io/scene.hpp"
#include "io/text_scanner.hpp"
#include "render/diagram_export.hpp"
#include "render/renderer.hpp"
#include "view_options.hpp"

namespace s4d::cli {
namespace {

struct RenderArgs {
  std::string input;
  std::string out;
  std::string svg;
  std::string tikz;
  std::optional<double> slice;
  ViewOptions view;
};

const CommandRegistrar kRender(
    "render",
    "render a scene, mesh, curve or generated object to PNG (no display needed), and its curves' "
    "crossing diagram to SVG or TikZ",
    [](CLI::App& sub) {
      auto args = std::make_shared<RenderArgs>();
      sub.add_option("input", args->input,
                     "scene.json, mesh (.off/.4off), curve (.vect/.txt) or generator call such as "
                     "clifford-torus:n=64 (see `shadow4d generators`)")
          ->required();
      sub.add_option("--out,-o", args->out, "PNG file to write");
      sub.add_option("--svg", args->svg,
                     "write the crossing diagram of the view (the curves' strands with a gap in the "
                     "under strand at each crossing, in the picture's pixels) as SVG, whatever --mode");
      sub.add_option("--tikz", args->tikz, "write the same diagram as a LaTeX tikzpicture of \\draw commands");
      sub.add_option("--slice", args->slice,
                     "draw the slice of the R^4 surfaces by the hyperplane w = W of the 4D view (as amber "
                     "tubes over the faded surfaces; `shadow4d slice` draws and names a whole movie)");
      args->view.add_to(sub);
      sub.callback([args] {
        if (args->out.empty() && args->svg.empty() && args->tikz.empty())
          throw Error("render: nothing to write: give --out PNG, --svg FILE or --tikz FILE");
        Scene scene = load_scene_or_object(args->input);
        args->view.apply(scene);
        std::cout << "view: " << args->view.described(args->input) << "\n";
        if (args->slice) {
          if (!std::isfinite(*args->slice)) throw Error("render: --slice needs a finite level w");
          scene.view.slice = true;
          scene.view.slice_level = *args->slice;
        }
        const auto [w, h] = args->view.parsed_size();
        if (!args->out.empty()) {
          IntersectionSummary drawn;
          write_png(render_offscreen(scene, w, h, &drawn), args->out);
          std::cout << args->out << "\n";
          if (drawn.computed) {
            std::cout << "intersections: " << intersection_text(drawn) << "\n";
            for (const std::string& code : drawn.gauss_codes) std::cout << code << "\n";
          }
        }
        if (!args->svg.empty() || !args->tikz.empty()) {
          const CurveDiagram diagram = view_diagram(scene, w, h);
          if (diagram.screen.images.empty()) throw Error("render: " + args->input + " has no curves to draw a diagram of");
          if (!args->svg.empty()) {
            write_text_file(args->svg, diagram_svg(diagram, scene, w, h));
            std::cout << args->svg << "\n";
          }
          if (!args->tikz.empty()) {
            write_text_file(args->tikz, diagram_tikz(diagram, scene, w, h));
            std::cout << args->tikz << "\n";
          }
          std::cout << "diagram: " << diagram.gaps.size() << " crossing(s), " << diagram.strands.size()
                    << " strand(s)";
          if (diagram.merged_gaps > 0) std::cout << ", " << diagram.merged_gaps << " gap(s) merged with a neighbour";
          if (diagram.screen.non_generic > 0) std::cout << " (not a regular diagram here: turn it)";
          if (diagram.screen.behind_eye > 0) std::cout << " (part of a curve is behind the eye)";
          std::cout << "\n";
        }
      });
    });

}  // namespace
}  // namespace s4d::cli
