#include "core/colour_map.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace s4d {
namespace {

TEST(ColourMap, FarIsBlueNearIsRed) {
  for (auto m : {ColourMap::kCoolWarm, ColourMap::kRainbow}) {
    Vec3f far = map_colour(m, 0.0), near = map_colour(m, 1.0);
    EXPECT_GT(far.z(), far.x()) << colour_map_name(m);
    EXPECT_GT(near.x(), near.z()) << colour_map_name(m);
  }
}

TEST(ColourMap, RedGrowsMonotonicallyWithNearness) {
  float prev = -1;
  for (int i = 0; i <= 100; ++i) {
    const Vec3f c = map_colour(ColourMap::kCoolWarm, i / 100.0);
    const float redness = c.x() - c.z();
    EXPECT_GE(redness, prev - 1e-6f);
    prev = redness;
  }
}

TEST(ColourMap, ClampsAndHandlesNaN) {
  EXPECT_EQ(map_colour(ColourMap::kCoolWarm, -5), map_colour(ColourMap::kCoolWarm, 0));
  EXPECT_EQ(map_colour(ColourMap::kCoolWarm, 5), map_colour(ColourMap::kCoolWarm, 1));
  Vec3f c = map_colour(ColourMap::kRainbow, std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(c.allFinite());
}

TEST(ColourMap, NamesRoundTrip) {
  for (auto m : {ColourMap::kCoolWarm, ColourMap::kRainbow, ColourMap::kGrey})
    EXPECT_EQ(parse_colour_map(colour_map_name(m)), m);
  EXPECT_FALSE(parse_colour_map("viridis-ish"));
  EXPECT_DOUBLE_EQ(normalise_depth(1, 1, 1), 0.5);
  EXPECT_DOUBLE_EQ(normalise_depth(2, 0, 4), 0.5);
}

}  // namespace
}  // namespace s4d
