// PNG encode/decode through stb. The stb implementations are compiled here and only here.
#include "io/image.hpp"

#include <cstring>

#include "core/error.hpp"
#include "io/text_scanner.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace s4d {

namespace {
// Larger images are refused rather than risking an allocation the machine cannot make.
constexpr long long kMaxPixels = 1LL << 28;  // 16384 × 16384

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}
}  // namespace

void write_png(const Image& image, const std::filesystem::path& path) {
  if (image.width <= 0 || image.height <= 0)
    throw Error("cannot write " + path.string() + ": image is empty (" + std::to_string(image.width) + "×" +
                std::to_string(image.height) + ")");
  if (static_cast<long long>(image.width) * image.height > kMaxPixels)
    throw Error("cannot write " + path.string() + ": image is too large");
  const std::size_t expected = static_cast<std::size_t>(image.width) * image.height * 4;
  if (image.rgba.size() != expected)
    throw Error("cannot write " + path.string() + ": pixel buffer holds " +
                std::to_string(image.rgba.size()) +
                " bytes, expected width × height × 4 = " + std::to_string(expected));
  std::string png;
  if (!stbi_write_png_to_func(append_bytes, &png, image.width, image.height, 4, image.rgba.data(),
                              image.width * 4))
    throw Error("cannot write " + path.string() + ": PNG encoding failed");
  write_text_file(path, png);
}

Image read_png(const std::filesystem::path& path) {
  const std::string bytes = read_text_file(path);
  static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0)
    throw Error(path.string() + ": not a PNG file");
  if (bytes.size() > static_cast<std::size_t>(INT32_MAX)) throw Error(path.string() + ": file too large");
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(data, static_cast<int>(bytes.size()), &w, &h, &channels))
    throw Error(path.string() + ": corrupt PNG (" + stbi_failure_reason() + ")");
  if (w <= 0 || h <= 0 || static_cast<long long>(w) * h > kMaxPixels)
    throw Error(path.string() + ": PNG size " + std::to_string(w) + "×" + std::to_string(h) +
                " is not supported");
  stbi_uc* pixels = stbi_load_from_memory(data, static_cast<int>(bytes.size()), &w, &h, &channels, 4);
  if (!pixels) throw Error(path.string() + ": corrupt PNG (" + stbi_failure_reason() + ")");
  Image image;
  image.width = w;
  image.height = h;
  image.rgba.assign(pixels, pixels + static_cast<std::size_t>(w) * h * 4);
  stbi_image_free(pixels);
  return image;
}

}  // namespace s4d
