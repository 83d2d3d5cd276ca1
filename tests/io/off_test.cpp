// OFF / 4OFF / nOFF: known files, fan triangulation, bit-exact round trips, typed readers.
#include "io/off.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "io_test_util.hpp"
#include "shape/topology.hpp"

namespace s4d {
namespace {

using test::data_dir;

TEST(Off, ReadsTetrahedronIgnoringFaceColours) {
  const Shape shape = read_off(data_dir() / "tetra.off");
  ASSERT_TRUE(std::holds_alternative<Surface<3>>(shape));
  const auto& s = std::get<Surface<3>>(shape);
  ASSERT_EQ(s.vertex_count(), 4u);
  ASSERT_EQ(s.triangle_count(), 4u);
  EXPECT_EQ(s.vertices[1], Vec3(1, -1, -1));
  EXPECT_EQ(s.vertices[3], Vec3(-1, -1, 1));
  EXPECT_EQ(s.triangles[1], (Triangle{0, 3, 1}));
  EXPECT_EQ(s.triangles[3], (Triangle{1, 3, 2}));
  const TopologySummary t = summarize_topology(s);
  EXPECT_TRUE(t.closed);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_FALSE(s.grid.has_value());
}

TEST(Off, FourOffIsFourDimensionalAndPolygonsAreFanned) {
  const Surface<4> s = read_off4(data_dir() / "square_4d.4off");
  ASSERT_EQ(s.vertex_count(), 5u);
  EXPECT_EQ(s.vertices[2], Vec4(0, 0, 1, 1));
  EXPECT_EQ(s.vertices[4], Vec4(0, 0, -0.5, 0.5));
  // quad 0 1 2 3 -> (0,1,2) (0,2,3); pentagon 0..4 -> (0,1,2) (0,2,3) (0,3,4)
  const std::vector<Triangle> expected{{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
  EXPECT_EQ(s.triangles, expected);
}

TEST(Off, NOffWithNormalsAndColoursSkipsThem) {
  const Surface<4> s = read_off4(data_dir() / "cube_noff.off");
  ASSERT_EQ(s.vertex_count(), 3u);
  EXPECT_EQ(s.vertices[0], Vec4(1, 0, 0, 0));
  EXPECT_EQ(s.vertices[2], Vec4(0, 0, 1, 0));
  EXPECT_EQ(s.triangles, (std::vector<Triangle>{{0, 1, 2}}));
}

TEST(Off, HomogeneousNOffDividesByTheLastCoordinate) {
  const Surface<3> s = read_off3(data_dir() / "homogeneous.off");
  ASSERT_EQ(s.vertex_count(), 3u);
  EXPECT_EQ(s.vertices[0], Vec3(1, 0, 0));
  EXPECT_EQ(s.vertices[1], Vec3(0, 2, 0));
  EXPECT_EQ(s.vertices[2], Vec3(0, 0, 3));
}

TEST(Off, TypedReadersRejectTheOtherDimension) {
  test::expect_parse_error([] { read_off3(data_dir() / "square_4d.4off"); }, 0, "R^4");
  test::expect_parse_error([] { read_off4(data_dir() / "tetra.off"); }, 0, "R^3");
}

TEST(Off, DegenerateFanTrianglesAreDropped) {
  const Shape shape = parse_off("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n5 0 1 1 2 3\n", "mem");
  const auto& s = std::get<Surface<3>>(shape);
  // fan: (0,1,1) dropped, (0,1,2), (0,2,3)
  EXPECT_EQ(s.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(Off, AcceptsHeaderAndCountsOnOneLineAndLeadingPlus) {
  const Shape shape = parse_off("OFF 3 1 0  0 0 0  +1 0 0  0 1.5e0 0  3 0 1 2", "mem");
  const auto& s = std::get<Surface<3>>(shape);
  EXPECT_EQ(s.vertices[1], Vec3(1, 0, 0));
  EXPECT_EQ(s.vertices[2], Vec3(0, 1.5, 0));
}

template <int D>
Surface<D> random_surface(int nv, int nt, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-10, 10);
  Surface<D> s;
  for (int i = 0; i < nv; ++i) {
    Vec<D> v;
    for (int c = 0; c < D; ++c) v[c] = u(rng);
    s.vertices.push_back(v);
  }
  // Values that a naive printf("%g") would not reproduce exactly.
  s.vertices[0][0] = 0.1;
  s.vertices[0][1] = -0.0;
  s.vertices[1][0] = 1e-300;
  s.vertices[1][1] = std::numeric_limits<double>::denorm_min();
  s.vertices[2][0] = std::numeric_limits<double>::max();
  std::uniform_int_distribution<int> idx(0, nv - 1);
  while (static_cast<int>(s.triangles.size()) < nt) {
    const Triangle t{idx(rng), idx(rng), idx(rng)};
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
      s.triangles.push_back(t);  // the reader drops degenerate ones
  }
  return s;
}

TEST(Off, RoundTripIsBitExactInR3AndR4) {
  test::TempDir dir;
  const Surface<3> s3 = random_surface<3>(50, 80, 1);
  write_off(s3, dir / "a.off");
  const Surface<3> r3 = read_off3(dir / "a.off");
  EXPECT_EQ(r3.vertices, s3.vertices);
  EXPECT_EQ(r3.triangles, s3.triangles);
  EXPECT_TRUE(std::signbit(r3.vertices[0][1]));

  const Surface<4> s4 = random_surface<4>(40, 70, 2);
  write_off(s4, dir / "b.4off");
  const Surface<4> r4 = read_off4(dir / "b.4off");
  EXPECT_EQ(r4.vertices, s4.vertices);
  EXPECT_EQ(r4.triangles, s4.triangles);
}

TEST(Off, RoundTripKeepsTheGrid) {
  Surface<4> s;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) s.vertices.push_back(Vec4(i, j, i * j, 0.5 * i));
  s.triangles = {{0, 1, 4}, {1, 5, 4}};
  s.grid = Grid{3, 4, false, true};
  const Shape back = parse_off(format_off(s), "mem");
  const auto& r = std::get<Surface<4>>(back);
  ASSERT_TRUE(r.grid.has_value());
  EXPECT_EQ(*r.grid, (Grid{3, 4, false, true}));
  EXPECT_EQ(r.vertices, s.vertices);
}

TEST(Off, GridThatNoLongerMatchesTheVerticesIsDropped) {
  const Shape shape = parse_off("OFF\n#! grid 2 3 0 0\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "mem");
  EXPECT_FALSE(std::get<Surface<3>>(shape).grid.has_value());
}

TEST(Off, WriterRefusesNonFiniteVertices) {
  Surface<3> s;
  s.vertices = {Vec3(0, 0, 0), Vec3(1, std::nan(""), 0), Vec3(0, 1, 0)};
  s.triangles = {{0, 1, 2}};
  EXPECT_THROW(format_off(s), Error);
}

TEST(Off, EmptyMeshRoundTrips) {
  const Surface<3> s;
  const Shape back = parse_off(format_off(s), "mem");
  EXPECT_EQ(std::get<Surface<3>>(back).vertex_count(), 0u);
}

TEST(Off, LoadsAMillionVerticesInLinearTime) {
  // A 1000 × 1000 grid: 10^6 vertices, ~2·10^6 triangles. Quadratic work would never finish.
  const int n = 1000;
  Surface<4> s;
  s.vertices.reserve(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) s.vertices.push_back(Vec4(i * 0.001, j * 0.001, 0.25, -0.5));
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      s.triangles.push_back({i * n + j, i * n + j + 1, (i + 1) * n + j});
      s.triangles.push_back({i * n + j + 1, (i + 1) * n + j + 1, (i + 1) * n + j});
    }
  s.grid = Grid{n, n, false, false};
  const std::string text = format_off(s);
  const Shape back = parse_off(text, "big");
  const auto& r = std::get<Surface<4>>(back);
  EXPECT_EQ(r.vertices.size(), s.vertices.size());
  EXPECT_EQ(r.triangles.size(), s.triangles.size());
  EXPECT_EQ(r.vertices.back(), s.vertices.back());
  EXPECT_EQ(r.triangles.back(), s.triangles.back());
}

}  // namespace
}  // namespace s4d
