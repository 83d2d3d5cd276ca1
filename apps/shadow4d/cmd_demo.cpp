// `shadow4d demo`: the headless main job. Renders the paper's objects (scenes/*.json) to PNG and
// prints, for each, where the picture is and the object's measured facts.
#include <chrono>
#include <filesystem>
#include <iostream>

#include "command.hpp"
#include "demo_report.hpp"
#include "io/image.hpp"
#include "io/scene.hpp"
#include "render/renderer.hpp"
#include "view_options.hpp"

#ifndef S4D_SCENES_DIR
#define S4D_SCENES_DIR "scenes"
#endif

namespace s4d::cli {
namespace {

namespace fs = std::filesystem;

struct DemoArgs {
  std::string out = "shadow4d-demo";
  std::string scenes = S4D_SCENES_DIR;
  ViewOptions view;
};

// The paper's objects, in the order its figures show them.
constexpr const char* kDemoScenes[] = {
    "trefoil-knot",       // Fig. 1: a knot as a lit tube
    "trefoil-ribbon-3d",  // Fig. 10a: a knot tied in a 3D ribbon
    "trefoil-ribbon-4d",  // Fig. 10b: the same ribbon in R^4
    "spun-trefoil",       // Fig. 11: the knotted sphere
    "clifford-torus",     // Fig. 12: the flat torus and its pinch lines
    "cloth",              // Fig. 13: cloth
    "sphere-and-ribbon",  // Fig. 14: a ribbon linked with a sphere
    "chain",              // Fig. 8: a 4D chain
};

const CommandRegistrar kDemo(
    "demo", "render the paper's objects to PNG files headless and print their metrics",
    [](CLI::App& sub) {
      auto args = std::make_shared<DemoArgs>();
      args->view.size = "800x600";
      sub.add_option("--out,-o", args->out, "folder for the PNG files")->capture_default_str();
      sub.add_option("--scenes", args->scenes, "folder holding the scene files")->capture_default_str();
      args->view.add_to(sub);
      sub.callback([args] {
        fs::create_directories(args->out);
        const auto [w, h] = args->view.parsed_size();
        int failures = 0;
        for (const char* name : kDemoScenes) {
          const fs::path scene_path = fs::path(args->scenes) / (std::string(name) + ".json");
          const fs::path png = fs::path(args->out) / (std::string(name) + ".png");
          try {
            Scene scene = load_scene(scene_path);
            args->view.apply(scene);
            const auto t0 = std::chrono::steady_clock::now();
            const Image image = render_offscreen(scene, w, h);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            write_png(image, png);
            std::cout << png.string() << "\n" << describe_scene(scene, image, ms);
          } catch (const std::exception& e) {
            ++failures;
            std::cerr << "demo: " << name << ": " << e.what() << "\n";
          }
        }
        std::cout << "demo: " << (std::size(kDemoScenes) - failures) << " of " << std::size(kDemoScenes)
                  << " pictures written to " << fs::absolute(args->out).string() << "\n";
        if (failures) throw ExitStatus{1};
      });
    });

}  // namespace
}  // namespace s4d::cli
