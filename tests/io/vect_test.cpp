// VECT / 4VECT: known files, open/closed polylines, bit-exact round trips.
#include "io/vect.hpp"

#include <gtest/gtest.h>

#include "io_test_util.hpp"

namespace s4d {
namespace {

using test::data_dir;

TEST(Vect, ReadsClosedAndOpenPolylines) {
  const Shape shape = read_vect(data_dir() / "trefoil.vect");
  ASSERT_TRUE(std::holds_alternative<Curve<3>>(shape));
  const auto& c = std::get<Curve<3>>(shape);
  ASSERT_EQ(c.components.size(), 2u);
  EXPECT_TRUE(c.components[0].closed);
  EXPECT_FALSE(c.components[1].closed);
  ASSERT_EQ(c.components[0].points.size(), 3u);
  ASSERT_EQ(c.components[1].points.size(), 2u);
  EXPECT_EQ(c.components[0].points[1], Vec3(1, 0, 0));
  EXPECT_EQ(c.components[1].points[1], Vec3(1, 1, 1));
  // closed triangle (1 + 1 + sqrt 2) and an open segment (0,0,1)-(1,1,1) of length sqrt 2
  EXPECT_NEAR(c.length(), 2 + 2 * std::sqrt(2.0), 1e-14);
}

TEST(Vect, FourVectIsFourDimensional) {
  const Shape shape = read_vect(data_dir() / "link_4d.4vect");
  ASSERT_TRUE(std::holds_alternative<Curve<4>>(shape));
  const auto& c = std::get<Curve<4>>(shape);
  ASSERT_EQ(c.components.size(), 1u);
  EXPECT_TRUE(c.components[0].closed);
  EXPECT_EQ(c.components[0].points[2], Vec4(0, 1, 0, -1));
}

TEST(Vect, NVectAndHomogeneous) {
  const Shape a = parse_vect("nVECT 4\n1 2 0\n2\n0\n1 2 3 4\n5 6 7 8\n", "mem");
  EXPECT_EQ(std::get<Curve<4>>(a).components[0].points[1], Vec4(5, 6, 7, 8));
  const Shape b = parse_vect("4nVECT 3\n1 2 0\n-2\n0\n2 4 6 2\n1 1 1 0.5\n", "mem");
  const auto& cb = std::get<Curve<3>>(b);
  EXPECT_EQ(cb.components[0].points[0], Vec3(1, 2, 3));
  EXPECT_EQ(cb.components[0].points[1], Vec3(2, 2, 2));
  EXPECT_TRUE(cb.components[0].closed);
}

template <int D>
Curve<D> sample_curve() {
  Curve<D> c;
  for (int k = 0; k < 3; ++k) {
    Polyline<D> p;
    p.closed = k != 1;
    for (int i = 0; i < 5 + k; ++i) {
      Vec<D> v;
      for (int d = 0; d < D; ++d) v[d] = std::sin(0.37 * i + d + k) / 3.0;
      p.points.push_back(v);
    }
    c.components.push_back(p);
  }
  return c;
}

template <int D>
void expect_same(const Curve<D>& a, const Curve<D>& b) {
  ASSERT_EQ(a.components.size(), b.components.size());
  for (std::size_t k = 0; k < a.components.size(); ++k) {
    EXPECT_EQ(a.components[k].closed, b.components[k].closed) << k;
    EXPECT_EQ(a.components[k].points, b.components[k].points) << k;
  }
}

TEST(Vect, RoundTripIsBitExact) {
  test::TempDir dir;
  const Curve<3> c3 = sample_curve<3>();
  write_vect(c3, dir / "c.vect");
  expect_same(std::get<Curve<3>>(read_vect(dir / "c.vect")), c3);
  const Curve<4> c4 = sample_curve<4>();
  write_vect(c4, dir / "c.4vect");
  expect_same(std::get<Curve<4>>(read_vect(dir / "c.4vect")), c4);
}

TEST(Vect, WriterRefusesComponentsWithFewerThanTwoPoints) {
  Curve<3> c;
  c.components.push_back({{Vec3(0, 0, 0)}, true});
  EXPECT_THROW(format_vect(c), Error);
}

TEST(Vect, NegativeZeroCountIsRejected) {
  test::expect_parse_error([] { parse_vect("VECT\n1 0 0\n0\n0\n", "mem"); }, 3, "at least 2");
}

}  // namespace
}  // namespace s4d
