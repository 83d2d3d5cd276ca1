// PNG encode/decode through stb, and the 2D helpers (blit, text, contact sheets). The stb
// implementations are compiled here and only here.
#include "io/image.hpp"

#include <algorithm>
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
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_easy_font.h>
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

namespace {

void check_image(const Image& image, const char* what) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    throw Error(std::string(what) + ": malformed image (" + std::to_string(image.width) + "×" +
                std::to_string(image.height) + " with " + std::to_string(image.rgba.size()) +
                " bytes of pixels)");
}

// stb_easy_font reads its tables at [c - 32] and [c - 31]: only ' '..'~' and '\n' are safe.
std::string printable(std::string_view text) {
  std::string s(text);
  for (char& c : s)
    if (c != '\n' && (c < 32 || c > 126)) c = '?';
  return s;
}

void fill_rect(Image& image, int x0, int y0, int x1, int y1, const Rgba& colour) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width);
  y1 = std::min(y1, image.height);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) std::memcpy(image.pixel(x, y), colour.data(), 4);
}

}  // namespace

Image filled_image(int width, int height, Rgba colour) {
  if (width <= 0 || height <= 0 || static_cast<long long>(width) * height > kMaxPixels)
    throw Error("cannot make a " + std::to_string(width) + "×" + std::to_string(height) +
                " image: each side must be positive and the whole at most " + std::to_string(kMaxPixels) +
                " pixels");
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) std::memcpy(&image.rgba[i], colour.data(), 4);
  return image;
}

void blit(Image& dst, const Image& src, int x, int y) {
  check_image(dst, "blit destination");
  check_image(src, "blit source");
  const int x0 = std::max(x, 0), x1 = std::min<long long>(static_cast<long long>(x) + src.width, dst.width);
  const int y0 = std::max(y, 0), y1 = std::min<long long>(static_cast<long long>(y) + src.height, dst.height);
  if (x1 <= x0) return;
  for (int row = y0; row < y1; ++row)
    std::memcpy(dst.pixel(x0, row), src.pixel(x0 - x, row - y), static_cast<std::size_t>(x1 - x0) * 4);
}

int text_width(std::string_view text, int scale) {
  std::string s = printable(text);
  return s.empty() ? 0 : scale * stb_easy_font_width(s.data());
}

int text_height(std::string_view text, int scale) {
  if (text.empty()) return 0;
  return scale * 12 * static_cast<int>(1 + std::count(text.begin(), text.end(), '\n'));
}

void draw_text(Image& image, int x, int y, std::string_view text, Rgba colour, int scale) {
  check_image(image, "draw_text");
  if (scale < 1) throw Error("draw_text: scale must be at least 1, got " + std::to_string(scale));
  std::string s = printable(text);
  if (s.empty()) return;
  // 64 bytes a quad (4 vertices of x, y, z, colour); no glyph has more than 16 segments.
  std::vector<float> quads(16 * 16 * (s.size() + 1));
  const int bytes = static_cast<int>(quads.size() * sizeof(float));
  const int n = stb_easy_font_print(0, 0, s.data(), nullptr, quads.data(), bytes);
  for (int q = 0; q < n; ++q) {
    const float* v = &quads[16 * static_cast<std::size_t>(q)];  // corners 0 and 2 are opposite
    const int qx0 = static_cast<int>(std::min(v[0], v[8])), qx1 = static_cast<int>(std::max(v[0], v[8]));
    const int qy0 = static_cast<int>(std::min(v[1], v[9])), qy1 = static_cast<int>(std::max(v[1], v[9]));
    fill_rect(image, x + scale * qx0, y + scale * qy0, x + scale * qx1, y + scale * qy1, colour);
  }
}

Image contact_sheet(const std::vector<Image>& frames, const std::vector<std::string>& labels,
                    std::string_view title, const SheetLayout& layout) {
  if (frames.empty()) throw Error("contact sheet: no frames");
  if (!labels.empty() && labels.size() != frames.size())
    throw Error("contact sheet: " + std::to_string(labels.size()) + " labels for " +
                std::to_string(frames.size()) + " frames (give one per frame, or none)");
  if (layout.columns < 1 || layout.gap < 0 || layout.text_scale < 1)
    throw Error("contact sheet: columns and text scale must be at least 1 and the gap at least 0");
  const int w = frames[0].width, h = frames[0].height;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    check_image(frames[i], "contact sheet frame");
    if (frames[i].width != w || frames[i].height != h)
      throw Error("contact sheet: frame " + std::to_string(i) + " is " + std::to_string(frames[i].width) +
                  "×" + std::to_string(frames[i].height) + ", frame 0 is " + std::to_string(w) + "×" +
                  std::to_string(h) + " (all must be of one size)");
  }
  const int n = static_cast<int>(frames.size());
  const int cols = std::min(layout.columns, n), rows = (n + cols - 1) / cols;
  const int gap = layout.gap, scale = layout.text_scale;
  const int title_band = title.empty() ? 0 : text_height(title, scale) + gap;
  int label_band = 0;
  for (const std::string& l : labels) label_band = std::max(label_band, text_height(l, scale));
  if (label_band > 0) label_band += gap / 2;
  const long long sheet_w = static_cast<long long>(cols) * w + static_cast<long long>(cols + 1) * gap;
  const long long sheet_h =
      title_band + static_cast<long long>(rows) * (h + label_band) + static_cast<long long>(rows + 1) * gap;
  if (sheet_w > kMaxPixels || sheet_h > kMaxPixels || sheet_w * sheet_h > kMaxPixels)
    throw Error("contact sheet: " + std::to_string(sheet_w) + "×" + std::to_string(sheet_h) +
                " is too large");
  Image sheet = filled_image(static_cast<int>(sheet_w), static_cast<int>(sheet_h), layout.background);
  if (!title.empty()) draw_text(sheet, gap, gap, title, layout.text, scale);
  for (int i = 0; i < n; ++i) {
    const int x = gap + (i % cols) * (w + gap);
    const int y = title_band + gap + (i / cols) * (h + label_band + gap);
    blit(sheet, frames[static_cast<std::size_t>(i)], x, y);
    if (label_band > 0 && !labels[static_cast<std::size_t>(i)].empty()) {
      // Drawn into a band of the cell's width, so a long label is cut at its cell's edge.
      Image band = filled_image(w, label_band, layout.background);
      draw_text(band, 0, gap / 2, labels[static_cast<std::size_t>(i)], layout.text, scale);
      blit(sheet, band, x, y + h);
    }
  }
  return sheet;
}

}  // namespace s4d
