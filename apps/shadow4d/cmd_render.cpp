// `shadow4d render`: draws a scene, file or generated object to a PNG without a display.
#include <iostream>

#include "command.hpp"
#include "io/image.hpp"
#include "io/scene.hpp"
#include "render/renderer.hpp"
#include "view_options.hpp"

namespace s4d::cli {
namespace {

struct RenderArgs {
  std::string input;
  std::string out;
  ViewOptions view;
};

const CommandRegistrar kRender(
    "render", "render a scene, mesh, curve or generated object to PNG (no display needed)",
    [](CLI::App& sub) {
      auto args = std::make_shared<RenderArgs>();
      sub.add_option("input", args->input,
                     "scene.json, mesh (.off/.4off), curve (.vect/.txt) or generator call such as "
                     "clifford-torus:n=64 (see `shadow4d generators`)")
          ->required();
      sub.add_option("--out,-o", args->out, "PNG file to write")->required();
      args->view.add_to(sub);
      sub.callback([args] {
        Scene scene = load_scene_or_object(args->input);
        args->view.apply(scene);
        const auto [w, h] = args->view.parsed_size();
        IntersectionSummary drawn;
        write_png(render_offscreen(scene, w, h, &drawn), args->out);
        std::cout << args->out << "\n";
        if (drawn.computed) {
          std::cout << "intersections: " << intersection_text(drawn) << "\n";
          for (const std::string& code : drawn.gauss_codes) std::cout << code << "\n";
        }
      });
    });

}  // namespace
}  // namespace s4d::cli
