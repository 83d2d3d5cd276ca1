// RGBA8 images and PNG files (stb_image_write / stb_image).
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

namespace s4d {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width × height × 4, top row first
  std::uint8_t* pixel(int x, int y) { return &rgba[4 * (static_cast<std::size_t>(y) * width + x)]; }
  const std::uint8_t* pixel(int x, int y) const {
    return &rgba[4 * (static_cast<std::size_t>(y) * width + x)];
  }
};

// Throws s4d::Error if the file cannot be written.
void write_png(const Image& image, const std::filesystem::path& path);
// Throws s4d::Error if the file is missing or not a PNG.
Image read_png(const std::filesystem::path& path);

}  // namespace s4d
