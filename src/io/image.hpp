// RGBA8 images and PNG files (stb_image_write / stb_image), and the few 2D operations the
// headless commands need to assemble their pictures: copying one image into another, a line of
// text in a small built-in font, and a contact sheet of frames.
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
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

using Rgba = std::array<std::uint8_t, 4>;

// A width × height image of one colour. Throws s4d::Error unless both are positive and the
// image is of a size write_png accepts.
Image filled_image(int width, int height, Rgba colour);

// Copies `src` into `dst` with its top-left pixel at (x, y), replacing what was there (alpha
// included); what falls outside `dst` is left out. Throws s4d::Error on a malformed image.
void blit(Image& dst, const Image& src, int x, int y);

// Text in stb_easy_font's built-in font (no font file needed): each font pixel becomes a
// scale × scale block, a line is text_height(1) = 12 × scale pixels high, and '\n' starts a
// new line. Characters outside printable ASCII are drawn as '?'. Clipped to the image.
void draw_text(Image& image, int x, int y, std::string_view text, Rgba colour, int scale = 1);
int text_width(std::string_view text, int scale = 1);   // px, the longest line
int text_height(std::string_view text, int scale = 1);  // px, 12 × scale per line

// How contact_sheet lays frames out.
struct SheetLayout {
  int columns = 6;     // frames across; the last row may be shorter
  int gap = 6;         // px between cells and around the edge
  int text_scale = 2;  // font scale of the labels and the title
  Rgba background{16, 18, 22, 255};
  Rgba text{235, 235, 235, 255};
};

// A contact sheet: `title` (any number of lines, may be empty) in a band across the top, then
// the frames in rows of layout.columns, each with its label in a band beneath it (labels may be
// empty, else one per frame). With n frames of size w × h, c = min(columns, n) across and
// r = ceil(n / c) rows, the sheet is (c·w + (c+1)·gap) wide and
// (T + r·(h + L) + (r+1)·gap) high, where T = text_height(title) + gap when the title is not
// empty (else 0) and L = the tallest label's text height + gap/2 (0 without labels).
// Frame i sits at x = gap + (i mod c)·(w + gap), y = T + gap + (i div c)·(h + L + gap).
// Throws s4d::Error on no frames, frames of different sizes, a label count that is neither 0
// nor the frame count, columns < 1, gap < 0 or text_scale < 1.
Image contact_sheet(const std::vector<Image>& frames, const std::vector<std::string>& labels,
                    std::string_view title, const SheetLayout& layout = {});

}  // namespace s4d
