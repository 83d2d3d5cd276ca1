#include "view_options.hpp"

#include <cmath>
#include <cstdio>

#include "core/error.hpp"

namespace s4d::cli {

void ViewOptions::add_to(CLI::App& app, bool with_size) {
  if (with_size) app.add_option("--size", size, "image size WxH")->capture_default_str();
  app.add_option("--rotate", rotate,
                 "rotations of the 4D view, degrees, in order, e.g. xw=30,yz=10 (planes xy xz xw yz yw zw)");
  app.add_option("--orbit", orbit, "camera yaw,pitch in degrees, e.g. 30,20");
  app.add_option("--colour-map", colour_map, "depth colour map: coolwarm, rainbow or grey");
  app.add_flag("--no-depth-colour", no_depth_colour, "plain colour instead of depth colouring");
  app.add_option("--mode", curve_mode,
                 "how curves are drawn: tubes (lit, the default), shadow (their flat image, no 3D "
                 "cues) or diagram (the crossing diagram: flat, a gap in the under strand at each "
                 "crossing)");
  app.add_flag("--wireframe", wireframe, "draw triangle edges");
  app.add_flag("--shadow", shadow, "flat-shaded shadow drawing (no lighting)");
  app.add_flag("--intersections", intersections,
               "draw the shadow's intersection curves (yellow shadow-only, with a red line on the "
               "sheet nearer in w and a blue one on the farther; magenta true 4D; a bead at each "
               "pinch point) and mark the crossings of the curves as seen (a white dot on the over "
               "strand)");
  app.add_option("--tube-radius", tube_radius, "radius of curve tubes, scene units");
  app.add_option("--zoom", zoom, "closer (> 1) or farther (< 1) than the view that fits the scene");
  app.add_option("--perspective", perspective,
                 "the shadow of R^4 in perspective from a 4D eye at distance D along w (scene units, "
                 "> 0; nearer in w is drawn larger), instead of the orthographic shadow");
  app.add_option("--opacity", opacity,
                 "surfaces' opacity in [0.05, 1]: below 1 a sheet behind shows through (1 = opaque)");
}

std::pair<int, int> ViewOptions::parsed_size() const {
  int w = 0, h = 0;
  char extra = 0;
  if (std::sscanf(size.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 16 || h < 16 || w > 8192 ||
      h > 8192)
    throw Error("--size '" + size + "' should be WxH with 16..8192 pixels each, e.g. 800x600");
  return {w, h};
}

std::string view_described(const std::string& input, const std::string& rotate, double perspective) {
  const bool scene_file = input.size() > 5 && input.ends_with(".json");
  std::string s = !rotate.empty() ? "the input's frame turned " + rotate
                  : scene_file    ? "the scene's own frame (the window's first view)"
                                  : "straight along w (the window opens it turned: --rotate xw=30,zw=20 gives its view)";
  if (perspective > 0) {
    char d[32];
    std::snprintf(d, sizeof d, "%g", perspective);
    s += std::string(", in perspective from a 4D eye at w = ") + d;
  }
  return s;
}

std::string ViewOptions::described(const std::string& input) const {
  return view_described(input, rotate, perspective.value_or(0));
}

void ViewOptions::apply(Scene& scene) const {
  apply_rotations(scene.frame, parse_rotation_list(rotate, 4));
  if (perspective) {
    if (const std::string e = Frame<4>::perspective_error(*perspective); !e.empty()) throw Error("--perspective: " + e);
    scene.frame.set_perspective(*perspective);
  }
  if (!orbit.empty()) {
    double yaw = 0, pitch = 0;
    char extra = 0;
    if (std::sscanf(orbit.c_str(), "%lf,%lf%c", &yaw, &pitch, &extra) != 2 || !std::isfinite(yaw) ||
        !std::isfinite(pitch))
      throw Error("--orbit '" + orbit + "' should be yaw,pitch in degrees, e.g. 30,20");
    constexpr double kDeg = 3.14159265358979323846 / 180.0;
    const Eigen::Quaterniond turn = Eigen::AngleAxisd(pitch * kDeg, Eigen::Vector3d::UnitX()) *
                                    Eigen::AngleAxisd(yaw * kDeg, Eigen::Vector3d::UnitY());
    scene.view.trackball = (turn * scene.view.trackball).normalized();
  }
  if (!colour_map.empty()) {
    const auto map = parse_colour_map(colour_map);
    if (!map) throw Error("--colour-map '" + colour_map + "': use coolwarm, rainbow or grey");
    scene.view.colour_map = *map;
  }
  if (!curve_mode.empty()) {
    const auto mode = parse_curve_mode(curve_mode);
    if (!mode) throw Error("--mode '" + curve_mode + "': use tubes, shadow or diagram");
    scene.view.curve_mode = *mode;
  }
  if (no_depth_colour) scene.view.depth_colour = false;
  if (wireframe) scene.view.wireframe = true;
  if (shadow) scene.view.shadow = true;
  if (intersections) scene.view.intersections = true;
  if (tube_radius) {
    if (!std::isfinite(*tube_radius) || *tube_radius <= 0 || *tube_radius > 100)
      throw Error("--tube-radius must be a positive number (scene units)");
    scene.view.tube_radius = *tube_radius;
  }
  if (zoom) {
    if (!std::isfinite(*zoom) || *zoom < 0.01 || *zoom > 100)
      throw Error("--zoom must be a number in [0.01, 100] (1 = the view that fits the scene)");
    scene.view.zoom = *zoom;
  }
  if (opacity) {
    if (!(*opacity >= 0.05 && *opacity <= 1)) {
      char got[32];
      std::snprintf(got, sizeof got, "%g", *opacity);
      throw Error(std::string("--opacity must be in [0.05, 1] (1 = opaque), got ") + got);
    }
    scene.view.opacity = *opacity;
  }
}

}  // namespace s4d::cli
