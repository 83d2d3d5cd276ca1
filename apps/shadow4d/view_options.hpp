// Command-line options shared by commands that render or look at a scene from a viewpoint
// (render, demo, check): size, 4D rotation, camera orbit and drawing style.
#pragma once
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "io/scene.hpp"

namespace s4d::cli {

struct ViewOptions {
  std::string size = "1024x768";
  std::string rotate;      // 4D (or 3D) plane rotations, "xw=30,yz=10", degrees, applied in order
  std::string orbit;       // camera yaw,pitch in degrees
  std::string colour_map;  // coolwarm | rainbow | grey
  std::string curve_mode;  // tubes | shadow | diagram (view.curve_mode)
  bool no_depth_colour = false;
  bool wireframe = false;
  bool shadow = false;
  bool intersections = false;
  std::optional<double> tube_radius;
  std::optional<double> opacity;  // surfaces' opacity, [0.05, 1]
  std::optional<double> zoom;     // multiplies the fitted view, > 1 closer
  std::optional<double> perspective;  // the 4D eye's distance along w (Frame::set_perspective)

  // Adds --size only when `with_size`.
  void add_to(CLI::App& app, bool with_size = true);
  // Applies the options on top of the scene's own settings. Throws s4d::Error on bad values.
  void apply(Scene& scene) const;
  // Parses "WxH"; throws s4d::Error unless 16 <= W, H <= 8192.
  std::pair<int, int> parsed_size() const;
  // Which view the numbers and pictures of `input` are of, in words: the window opens a bare
  // object of R^4 (no scene file to say how to look at it) turned xw 30, zw 20, so commands that
  // look along w say so, and how to get the window's view.
  std::string described(const std::string& input) const;
};

// The same for a command with only --rotate (check).
// A perspective distance (> 0) adds "in perspective from a 4D eye at w = D".
std::string view_described(const std::string& input, const std::string& rotate, double perspective = 0);

}  // namespace s4d::cli
