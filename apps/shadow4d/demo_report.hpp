// The metrics the demo prints for a rendered scene: per object its size and topology, and the
// picture's coverage, so a reader can tell at a glance that the right thing was drawn.
#pragma once
#include <string>

#include "io/image.hpp"
#include "io/scene.hpp"

namespace s4d::cli {

std::string describe_scene(const Scene& scene, const Image& image, double render_ms);
// Fraction of pixels that differ from the top-left (background) pixel.
double coverage(const Image& image);

}  // namespace s4d::cli
