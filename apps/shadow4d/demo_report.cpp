#include "demo_report.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "shape/describe.hpp"

namespace s4d::cli {

double coverage(const Image& image) {
  if (image.width == 0 || image.height == 0) return 0;
  const std::uint8_t* bg = image.pixel(0, 0);
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 12) ++n;
    }
  return static_cast<double>(n) / (static_cast<double>(image.width) * image.height);
}

std::string describe_scene(const Scene& scene, const Image& image, double render_ms) {
  std::ostringstream out;
  for (const auto& obj : scene.objects) out << "  " << obj.name << ": " << describe_shape(obj.shape) << "\n";
  char line[160];
  std::snprintf(line, sizeof line, "  picture: %dx%d, %.1f%% covered, rendered in %.0f ms\n",
                image.width, image.height, 100.0 * coverage(image), render_ms);
  out << line;
  return out.str();
}

std::string verdict_line(const RunFacts& f) {
  auto g = [](double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", x);
    return std::string(b);
  };
  std::ostringstream out;
  out << (f.pass() ? "PASS " : "FAIL ") << f.name << ": " << f.verdict.detail << "; " << f.intersections
      << " true intersections in " << f.checks << " states checked (min gap " << g(f.min_gap)
      << ", hard layer " << g(f.model.hard_thickness) << "); " << f.model.vertices << " vertices, " << f.steps
      << " steps, " << g(f.ms_per_step) << " ms/step, " << f.warnings.rollbacks << " rollbacks, "
      << f.warnings.global_freezes << " global freezes";
  return out.str();
}

}  // namespace s4d::cli
