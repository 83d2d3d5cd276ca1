// PNG write/read through stb: exact round trip of RGBA8, and clear errors for bad input. The 2D
// helpers: blit clips, text lands where measured, contact sheets place every frame's pixels.
#include "io/image.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>

#include "core/error.hpp"
#include "io_test_util.hpp"

namespace s4d {
namespace {

Image gradient(int w, int h) {
  Image im;
  im.width = w;
  im.height = h;
  im.rgba.resize(static_cast<std::size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = im.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 255 / (w - 1));
      p[1] = static_cast<std::uint8_t>(y * 255 / (h - 1));
      p[2] = static_cast<std::uint8_t>((x * 7 + y * 13) & 0xff);
      p[3] = static_cast<std::uint8_t>(255 - (x & 0x3f));
    }
  return im;
}

TEST(Png, RoundTripIsExactAndTopRowFirst) {
  test::TempDir dir;
  const Image im = gradient(37, 23);
  write_png(im, dir / "g.png");
  const Image back = read_png(dir / "g.png");
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 23);
  EXPECT_EQ(back.rgba, im.rgba);
  EXPECT_EQ(back.pixel(0, 0)[1], 0);     // top row: y = 0
  EXPECT_EQ(back.pixel(0, 22)[1], 255);  // bottom row
}

TEST(Png, FileStartsWithThePngSignature) {
  test::TempDir dir;
  write_png(gradient(4, 4), dir / "s.png");
  std::ifstream in(dir / "s.png", std::ios::binary);
  char sig[8];
  in.read(sig, 8);
  EXPECT_EQ(std::string(sig + 1, 3), "PNG");
}

TEST(Png, WriteRejectsBadImagesAndPaths) {
  test::TempDir dir;
  Image empty;
  EXPECT_THROW(write_png(empty, dir / "e.png"), Error);
  Image wrong = gradient(4, 4);
  wrong.rgba.pop_back();
  EXPECT_THROW(write_png(wrong, dir / "w.png"), Error);
  EXPECT_THROW(write_png(gradient(4, 4), dir / "no" / "such" / "dir.png"), Error);
}

TEST(Png, ReadRejectsMissingNonPngAndCorruptFiles) {
  test::TempDir dir;
  EXPECT_THROW(read_png(dir / "missing.png"), Error);
  EXPECT_THROW(read_png(dir.write("text.png", "this is not a png")), Error);
  write_png(gradient(16, 16), dir / "full.png");
  std::ifstream in(dir / "full.png", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  EXPECT_THROW(read_png(dir.write("cut.png", bytes.substr(0, bytes.size() / 2))), Error);
  std::string flipped = bytes;
  for (std::size_t i = 40; i < flipped.size(); i += 3) flipped[i] = static_cast<char>(flipped[i] ^ 0x5a);
  EXPECT_THROW(read_png(dir.write("flip.png", flipped)), Error);
}

// A frame whose every pixel says which frame it is and where in it it lies.
Image tagged(int w, int h, int tag) {
  Image im = filled_image(w, h, {0, 0, 0, 255});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = im.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x);
      p[1] = static_cast<std::uint8_t>(y);
      p[2] = static_cast<std::uint8_t>(100 + tag);
    }
  return im;
}

bool same_pixel(const std::uint8_t* a, const std::uint8_t* b) { return std::memcmp(a, b, 4) == 0; }

TEST(Image, FilledImageHasItsColourAndRefusesBadSizes) {
  const Image im = filled_image(3, 2, {1, 2, 3, 4});
  ASSERT_EQ(im.rgba.size(), 24u);
  for (std::size_t i = 0; i < im.rgba.size(); i += 4) EXPECT_EQ(im.rgba[i + 3], 4);
  EXPECT_THROW(filled_image(0, 5, {}), Error);
  EXPECT_THROW(filled_image(5, -1, {}), Error);
  EXPECT_THROW(filled_image(1 << 15, 1 << 15, {}), Error);
}

TEST(Image, BlitCopiesAndClipsAtEveryEdge) {
  const Image src = tagged(4, 3, 1);
  Image dst = filled_image(6, 5, {9, 9, 9, 255});
  blit(dst, src, 1, 2);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 6; ++x) {
      const bool inside = x >= 1 && x < 5 && y >= 2 && y < 5;
      if (inside)
        EXPECT_TRUE(same_pixel(dst.pixel(x, y), src.pixel(x - 1, y - 2))) << x << "," << y;
      else
        EXPECT_EQ(dst.pixel(x, y)[0], 9) << x << "," << y;
    }
  Image corner = filled_image(3, 3, {9, 9, 9, 255});
  blit(corner, src, -2, -1);  // src (2, 1) lands on (0, 0)
  EXPECT_TRUE(same_pixel(corner.pixel(0, 0), src.pixel(2, 1)));
  EXPECT_TRUE(same_pixel(corner.pixel(1, 1), src.pixel(3, 2)));
  EXPECT_EQ(corner.pixel(2, 0)[0], 9);
  blit(corner, src, 50, 50);  // wholly outside: nothing changes
  blit(corner, src, -50, 0);
  EXPECT_EQ(corner.pixel(2, 2)[0], 9);
  Image broken = src;
  broken.rgba.pop_back();
  EXPECT_THROW(blit(corner, broken, 0, 0), Error);
  EXPECT_THROW(blit(broken, src, 0, 0), Error);
}

TEST(Image, TextIsDrawnWithinItsMeasuredBoxAndScales) {
  EXPECT_EQ(text_width(""), 0);
  EXPECT_EQ(text_height(""), 0);
  EXPECT_EQ(text_height("t = 0.4 s"), 12);
  EXPECT_EQ(text_height("a\nb", 3), 72);
  EXPECT_EQ(text_width("0123", 2), 2 * text_width("0123"));
  EXPECT_GT(text_width("0123"), text_width("01"));
  EXPECT_EQ(text_width("ab\nabcd"), text_width("abcd"));
  for (int scale : {1, 3}) {
    Image im = filled_image(200, 60, {0, 0, 0, 255});
    const std::string s = "t = 1.25 s";
    draw_text(im, 10, 5, s, {255, 255, 255, 255}, scale);
    int lit = 0, x_max = -1, y_max = -1, x_min = 1000, y_min = 1000;
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x)
        if (im.pixel(x, y)[0] == 255) {
          ++lit;
          x_min = std::min(x_min, x), x_max = std::max(x_max, x);
          y_min = std::min(y_min, y), y_max = std::max(y_max, y);
        }
    EXPECT_GT(lit, 20 * scale * scale);
    EXPECT_GE(x_min, 10);
    EXPECT_GE(y_min, 5);
    EXPECT_LT(x_max, 10 + text_width(s, scale));
    EXPECT_LT(y_max, 5 + text_height(s, scale));
  }
  // Off the image and outside ASCII: clipped and replaced, never out of bounds.
  Image small = filled_image(8, 8, {0, 0, 0, 255});
  draw_text(small, -5, -3, "\x01\xff\xc3\xa9 W~", {255, 0, 0, 255}, 2);
  EXPECT_EQ(text_width("\xc3\xa9"), text_width("??"));
  EXPECT_THROW(draw_text(small, 0, 0, "x", {}, 0), Error);
}

TEST(ContactSheet, SizeFollowsTheDocumentedLayout) {
  const std::vector<Image> frames(7, tagged(20, 10, 0));
  SheetLayout layout;
  layout.columns = 3;
  layout.gap = 4;
  layout.text_scale = 1;
  const Image bare = contact_sheet(frames, {}, "", layout);
  EXPECT_EQ(bare.width, 3 * 20 + 4 * 4);
  EXPECT_EQ(bare.height, 3 * 10 + 4 * 4);  // rows = ceil(7 / 3) = 3
  const std::vector<std::string> labels(7, "t = 0 s");
  const Image full = contact_sheet(frames, labels, "title\nsecond line", layout);
  const int title_band = 24 + 4, label_band = 12 + 2;
  EXPECT_EQ(full.width, bare.width);
  EXPECT_EQ(full.height, title_band + 3 * (10 + label_band) + 4 * 4);
  layout.columns = 10;  // more columns than frames: one row as wide as the frames
  EXPECT_EQ(contact_sheet(frames, {}, "", layout).width, 7 * 20 + 8 * 4);
}

TEST(ContactSheet, EachFrameLandsInItsCellWithItsLabelBeneath) {
  std::vector<Image> frames;
  for (int i = 0; i < 5; ++i) frames.push_back(tagged(16, 12, i));
  SheetLayout layout;
  layout.columns = 2;
  layout.gap = 6;
  layout.text_scale = 1;
  layout.background = {7, 7, 7, 255};
  layout.text = {250, 0, 250, 255};
  const std::vector<std::string> labels{"a", "b", "c", "d", "e"};
  const Image sheet = contact_sheet(frames, labels, "T", layout);
  const int title_band = 12 + 6, label_band = 12 + 3;
  for (int i = 0; i < 5; ++i) {
    const int x0 = 6 + (i % 2) * (16 + 6), y0 = title_band + 6 + (i / 2) * (12 + label_band + 6);
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 16; ++x)
        ASSERT_TRUE(same_pixel(sheet.pixel(x0 + x, y0 + y), frames[i].pixel(x, y))) << "frame " << i;
    EXPECT_EQ(sheet.pixel(x0 - 1, y0)[0], 7);  // gap on the left
    EXPECT_EQ(sheet.pixel(x0, y0 - 1)[0], 7);  // gap above
    // The label is in the band under the frame, within the cell's width.
    bool label_drawn = false;
    for (int y = y0 + 12; y < y0 + 12 + label_band; ++y)
      for (int x = x0; x < x0 + 16; ++x) label_drawn |= sheet.pixel(x, y)[0] == 250;
    EXPECT_TRUE(label_drawn) << "label " << i;
  }
  bool title_drawn = false;
  for (int y = 0; y < title_band; ++y)
    for (int x = 0; x < sheet.width; ++x) title_drawn |= sheet.pixel(x, y)[0] == 250;
  EXPECT_TRUE(title_drawn);
  // The empty sixth cell is background.
  EXPECT_EQ(sheet.pixel(6 + 22 + 8, title_band + 6 + 2 * (12 + label_band + 6) + 6)[0], 7);
}

TEST(ContactSheet, LongLabelsStopAtTheirCell) {
  const std::vector<Image> frames(2, filled_image(10, 10, {0, 0, 0, 255}));
  SheetLayout layout;
  layout.gap = 4;
  layout.text_scale = 1;
  layout.background = {7, 7, 7, 255};
  layout.text = {250, 250, 250, 255};
  const Image sheet = contact_sheet(frames, {"WWWWWWWWWWWWWWWWWWWW", ""}, "", layout);
  for (int y = 14; y < sheet.height; ++y)
    for (int x = 14; x < sheet.width; ++x) EXPECT_NE(sheet.pixel(x, y)[0], 250) << x << "," << y;
}

TEST(ContactSheet, RefusesBadInput) {
  const Image a = tagged(8, 8, 0);
  EXPECT_THROW(contact_sheet({}, {}, ""), Error);
  EXPECT_THROW(contact_sheet({a, tagged(8, 9, 1)}, {}, ""), Error);
  EXPECT_THROW(contact_sheet({a, a}, {"only one"}, ""), Error);
  Image broken = a;
  broken.rgba.resize(10);
  EXPECT_THROW(contact_sheet({a, broken}, {}, ""), Error);
  SheetLayout bad;
  bad.columns = 0;
  EXPECT_THROW(contact_sheet({a}, {}, "", bad), Error);
  bad = {};
  bad.gap = -1;
  EXPECT_THROW(contact_sheet({a}, {}, "", bad), Error);
  bad = {};
  bad.text_scale = 0;
  EXPECT_THROW(contact_sheet({a}, {}, "", bad), Error);
}

}  // namespace
}  // namespace s4d
