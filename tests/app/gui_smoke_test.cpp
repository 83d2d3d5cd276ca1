// Runs the real window for a few frames and inspects its screenshot. Needs a display: ctest runs it
// under xvfb-run (see tests/CMakeLists.txt); in the plain run without DISPLAY it is skipped.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "app/gui_app.hpp"
#include "io/image.hpp"

namespace s4d {
namespace {

TEST(GuiSmoke, WindowShowsTheObjectAndThePanels) {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) GTEST_SKIP() << "no display; ctest runs this under xvfb-run";
  const auto shot = std::filesystem::temp_directory_path() / "s4d_gui_smoke.png";
  std::filesystem::remove(shot);
  GuiOptions options;
  options.open_spec = "clifford-torus";
  options.frames = 10;
  options.window_shot = shot.string();
  options.width = 900;
  options.height = 600;
  ASSERT_EQ(run_gui_app(options), 0);
  const Image image = read_png(shot);
  ASSERT_GT(image.width, 0);
  // The object is drawn: many pixels are neither background nor panel grey, and some are red/blue.
  std::size_t reddish = 0, bluish = 0, lit = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      if (p[0] + p[1] + p[2] > 150) ++lit;
      if (p[0] > p[2] + 40) ++reddish;
      if (p[2] > p[0] + 40) ++bluish;
    }
  const double n = static_cast<double>(image.width) * image.height;
  EXPECT_GT(lit / n, 0.05);
  EXPECT_GT(reddish / n, 0.005);
  EXPECT_GT(bluish / n, 0.005);
}

TEST(GuiSmoke, BadFileIsReportedNotFatal) {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) GTEST_SKIP() << "no display; ctest runs this under xvfb-run";
  GuiOptions options;
  options.open_spec = "/nonexistent/file.4off";
  options.frames = 3;
  EXPECT_EQ(run_gui_app(options), 1);  // the window still opened and closed cleanly
}

}  // namespace
}  // namespace s4d
