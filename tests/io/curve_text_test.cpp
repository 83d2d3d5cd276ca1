// Plain-text curves: components, "#! open", comments, dimension detection, round trips.
#include "io/curve_text.hpp"

#include <gtest/gtest.h>

#include "io_test_util.hpp"

namespace s4d {
namespace {

using test::data_dir;

TEST(CurveText, ReadsComponentsAndOpenDirective) {
  const Shape shape = read_curve_text(data_dir() / "two_components.txt");
  ASSERT_TRUE(std::holds_alternative<Curve<3>>(shape));
  const auto& c = std::get<Curve<3>>(shape);
  ASSERT_EQ(c.components.size(), 2u);
  EXPECT_TRUE(c.components[0].closed);
  EXPECT_FALSE(c.components[1].closed);
  EXPECT_EQ(c.components[0].points.size(), 3u);
  ASSERT_EQ(c.components[1].points.size(), 3u);
  EXPECT_EQ(c.components[1].points[2], Vec3(4, 2, 2));
}

TEST(CurveText, FourCoordinatesMakeACurveInR4) {
  const Shape shape = parse_curve_text("0 0 0 0\n1 0 0 0.5\r\n0 1 0 -0.5\n", "mem");
  const auto& c = std::get<Curve<4>>(shape);
  ASSERT_EQ(c.components.size(), 1u);
  EXPECT_TRUE(c.components[0].closed);
  EXPECT_EQ(c.components[0].points[1], Vec4(1, 0, 0, 0.5));
}

TEST(CurveText, SeveralBlankLinesAreOneSeparator) {
  const Shape shape = parse_curve_text("\n\n0 0 0\n1 0 0\n\n\n   \n2 0 0\n3 0 0\n\n", "mem");
  EXPECT_EQ(std::get<Curve<3>>(shape).components.size(), 2u);
}

TEST(CurveText, OpenDirectiveAlsoEndsTheCurrentComponent) {
  const Shape shape =
      parse_curve_text("0 0 0\n1 0 0\n#! open\n2 0 0\n3 0 0\n#! closed\n4 0 0\n5 0 0\n", "mem");
  const auto& c = std::get<Curve<3>>(shape);
  ASSERT_EQ(c.components.size(), 3u);
  EXPECT_TRUE(c.components[0].closed);
  EXPECT_FALSE(c.components[1].closed);
  EXPECT_TRUE(c.components[2].closed);
}

template <int D>
Curve<D> sample(int components) {
  Curve<D> c;
  for (int k = 0; k < components; ++k) {
    Polyline<D> p;
    p.closed = k % 2 == 0;
    for (int i = 0; i < 4 + k; ++i) {
      Vec<D> v;
      for (int d = 0; d < D; ++d) v[d] = std::cos(1.1 * i - d) * (k + 1) / 7.0;
      p.points.push_back(v);
    }
    c.components.push_back(p);
  }
  return c;
}

template <int D>
void round_trip(const test::TempDir& dir) {
  const Curve<D> c = sample<D>(4);
  const auto file = dir / ("c" + std::to_string(D) + ".curve");
  write_curve_text(c, file);
  const Shape back = read_curve_text(file);
  const auto& r = std::get<Curve<D>>(back);
  ASSERT_EQ(r.components.size(), c.components.size());
  for (std::size_t k = 0; k < c.components.size(); ++k) {
    EXPECT_EQ(r.components[k].closed, c.components[k].closed);
    EXPECT_EQ(r.components[k].points, c.components[k].points);
  }
}

TEST(CurveText, RoundTripIsBitExact) {
  test::TempDir dir;
  round_trip<3>(dir);
  round_trip<4>(dir);
}

TEST(CurveText, WriterRefusesEmptyAndDegenerateCurves) {
  EXPECT_THROW(format_curve_text(Curve<3>{}), Error);
  Curve<4> c;
  c.components.push_back({{Vec4::Zero()}, true});
  EXPECT_THROW(format_curve_text(c), Error);
}

TEST(CurveText, ErrorLinesPointAtTheCulprit) {
  test::expect_parse_error([] { parse_curve_text("0 0 0\n1 0 0\n\n# c\n5 5 5\n", "mem"); }, 5, "at least 2");
  test::expect_parse_error([] { parse_curve_text("0 0 0\n1 0 0\n2 0 zz\n", "mem"); }, 3, "'zz'");
}

}  // namespace
}  // namespace s4d
