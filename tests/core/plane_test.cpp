#include "core/plane.hpp"
#include "core/error.hpp"

#include <gtest/gtest.h>

namespace s4d {
namespace {

TEST(Plane, ParsesNamesInEitherOrder) {
  EXPECT_EQ(parse_plane("xw", 4), (Plane{0, 3}));
  EXPECT_EQ(parse_plane("wx", 4), (Plane{0, 3}));
  EXPECT_EQ(parse_plane("yz", 3), (Plane{1, 2}));
}

TEST(Plane, RejectsBadNames) {
  EXPECT_FALSE(parse_plane("xx", 4));
  EXPECT_FALSE(parse_plane("xq", 4));
  EXPECT_FALSE(parse_plane("xw", 3));  // no w axis in R^3
  EXPECT_FALSE(parse_plane("xyz", 4));
  EXPECT_FALSE(parse_plane("", 4));
}

TEST(Plane, AllPlanesInUiOrder) {
  auto p = all_planes(4);
  ASSERT_EQ(p.size(), 6u);
  std::vector<std::string> names;
  for (auto q : p) names.push_back(plane_name(q));
  EXPECT_EQ(names, (std::vector<std::string>{"xy", "xz", "xw", "yz", "yw", "zw"}));
  EXPECT_EQ(all_planes(3).size(), 3u);
  EXPECT_EQ(all_planes(2).size(), 1u);
}

}  // namespace
}  // namespace s4d

namespace s4d {
namespace {

TEST(RotationList, ParsesSeveralItems) {
  auto r = parse_rotation_list("xw=30,yz=-10.5", 4);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].plane, (Plane{0, 3}));
  EXPECT_DOUBLE_EQ(r[0].degrees, 30);
  EXPECT_EQ(r[1].plane, (Plane{1, 2}));
  EXPECT_DOUBLE_EQ(r[1].degrees, -10.5);
  auto s = parse_rotation_list("wx=30", 4);
  EXPECT_DOUBLE_EQ(s[0].degrees, -30);
  EXPECT_TRUE(parse_rotation_list("", 4).empty());
}

TEST(RotationList, RejectsMalformedItems) {
  EXPECT_THROW(parse_rotation_list("xw", 4), Error);
  EXPECT_THROW(parse_rotation_list("qq=3", 4), Error);
  EXPECT_THROW(parse_rotation_list("xw=abc", 4), Error);
  EXPECT_THROW(parse_rotation_list("xw=nan", 4), Error);
  EXPECT_THROW(parse_rotation_list("xw=inf", 4), Error);
  EXPECT_THROW(parse_rotation_list("xw=30", 3), Error);
}

}  // namespace
}  // namespace s4d
