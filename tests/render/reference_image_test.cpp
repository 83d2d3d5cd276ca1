// Reference images: renders small scenes and compares them with PNGs in tests/data/render/,
// per pixel with a tolerance, allowing a small fraction of differing pixels (anti-aliasing and
// rasteriser rounding vary a little between Mesa versions).
//
// To regenerate after an intended change of the look, run
//   S4D_UPDATE_REFERENCES=1 ./build/tests/render_tests --gtest_filter='ReferenceImage.*'
// then LOOK at the new PNGs before committing them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include "io/image.hpp"
#include "render/renderer.hpp"
#include "render/test_shapes.hpp"

namespace s4d {
namespace {

constexpr int kW = 160, kH = 120;
constexpr int kChannelTolerance = 24;     // counts out of 255
constexpr double kAllowedFraction = 0.02;  // of the pixels

std::filesystem::path reference_path(const std::string& name) {
  return std::filesystem::path(S4D_TEST_DATA) / "render" / (name + ".png");
}

void compare_with_reference(const std::string& name, const Scene& scene) {
  const Image got = render_offscreen(scene, kW, kH);
  const auto path = reference_path(name);
  const char* update = std::getenv("S4D_UPDATE_REFERENCES");
  if (update && std::string(update) == "1") {
    std::filesystem::create_directories(path.parent_path());
    write_png(got, path);
    std::cout << "wrote " << path << "\n";
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(path))
      << path << " is missing; run with S4D_UPDATE_REFERENCES=1 to create it";
  const Image want = read_png(path);
  ASSERT_EQ(want.width, got.width);
  ASSERT_EQ(want.height, got.height);
  const double diff = test::differing_fraction(want, got, kChannelTolerance);
  if (diff > kAllowedFraction) {
    const auto out = std::filesystem::temp_directory_path() / ("s4d_" + name + "_actual.png");
    write_png(got, out);
    ADD_FAILURE() << name << ": " << 100 * diff << "% of pixels differ by more than "
                  << kChannelTolerance << " counts (allowed " << 100 * kAllowedFraction
                  << "%); actual image written to " << out;
  }
}

Scene clifford_scene() {
  Scene sc = test::scene_of(test::clifford_torus(48));
  sc.frame.rotate(Plane{0, 3}, 0.5);
  sc.frame.rotate(Plane{1, 2}, 0.6);
  return sc;
}

TEST(ReferenceImage, CliffordTorusLit) { compare_with_reference("clifford_torus_lit", clifford_scene()); }

TEST(ReferenceImage, CliffordTorusWireframe) {
  Scene sc = clifford_scene();
  sc.view.wireframe = true;
  compare_with_reference("clifford_torus_wireframe", sc);
}

TEST(ReferenceImage, TrefoilTube) {
  Scene sc = test::scene_of(test::trefoil(200));
  sc.view.tube_radius = 0.08;
  sc.view.trackball = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Vec3(1, 0, 0)));
  compare_with_reference("trefoil_tube", sc);
}

TEST(ReferenceImage, TiltedSquareShadow) {
  Scene sc = test::scene_of(test::tilted_square(0.5));
  sc.view.shadow = true;
  compare_with_reference("tilted_square_shadow", sc);
}

// The comparison must be able to fail: a changed view is caught.
TEST(ReferenceImage, ComparisonDetectsAChange) {
  const auto path = reference_path("clifford_torus_lit");
  ASSERT_TRUE(std::filesystem::exists(path));
  Scene sc = clifford_scene();
  sc.frame.rotate(Plane{0, 3}, 0.4);
  const Image got = render_offscreen(sc, kW, kH);
  EXPECT_GT(test::differing_fraction(read_png(path), got, kChannelTolerance), kAllowedFraction);
}

}  // namespace
}  // namespace s4d
