// PNG write/read through stb: exact round trip of RGBA8, and clear errors for bad input.
#include "io/image.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace s4d
