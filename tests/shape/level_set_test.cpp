// Level sets of a view's depth on meshes (slices) against a brute-force reference, and the
// critical levels' count against the Euler characteristic of every closed generated surface.
// Sections: [SECTION] level sets, [SECTION] critical levels.
#include "shape/level_set.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "shape/critical_levels.hpp"
#include "shape/generators.hpp"
#include "shape/grid_mesh.hpp"
#include "shape/spun_knot.hpp"
#include "shape/surfaces_4d.hpp"
#include "shape/topology.hpp"

namespace s4d {
namespace {

template <int D>
Frame<D> random_frame(std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  Frame<D> f;
  for (int a = 0; a < D; ++a)
    for (int b = a + 1; b < D; ++b) f.rotate(Plane{a, b}, angle(rng));
  return f;
}

// [SECTION] level sets

// The level set triangle by triangle, written independently of level_set: the points where the
// depth crosses the level on the triangle's edges (a vertex at the level counts as above it).
template <int D>
std::vector<std::array<Vec<D - 1>, 2>> reference_segments(const Surface<D>& mesh, const Frame<D>& frame, double c) {
  std::vector<std::array<Vec<D - 1>, 2>> out;
  for (const Triangle& t : mesh.triangles) {
    std::vector<Vec<D - 1>> hits;
    for (int k = 0; k < 3; ++k) {
      const Vec<D> qa = frame.to_view(mesh.vertices[t[k]]), qb = frame.to_view(mesh.vertices[t[(k + 1) % 3]]);
      const double fa = qa[D - 1] - c, fb = qb[D - 1] - c;
      if ((fa >= 0) == (fb >= 0)) continue;
      hits.push_back(((fb * qa - fa * qb) / (fb - fa)).template head<D - 1>());
    }
    if (hits.size() == 2) out.push_back({hits[0], hits[1]});
  }
  return out;
}

// Every segment of the level set is one of the reference's and the other way round.
template <int D>
void expect_matches_reference(const Surface<D>& mesh, const Frame<D>& frame, double c) {
  const LevelSet<D> set = level_set(mesh, frame, c);
  auto ref = reference_segments(mesh, frame, c);
  std::vector<char> taken(ref.size(), 0);
  std::size_t segments = 0;
  for (const Polyline<D - 1>& line : set.curve.components)
    for (std::size_t k = 0; k < line.segment_count(); ++k) {
      ++segments;
      const Vec<D - 1>&a = line.seg_a(k), &b = line.seg_b(k);
      bool found = false;
      for (std::size_t r = 0; r < ref.size() && !found; ++r) {
        if (taken[r]) continue;
        const double d = std::min((a - ref[r][0]).norm() + (b - ref[r][1]).norm(),
                                  (a - ref[r][1]).norm() + (b - ref[r][0]).norm());
        if (d < 1e-9) {
          found = true;
          taken[r] = 1;
        }
      }
      EXPECT_TRUE(found) << "a segment of the level set at " << c << " is in no triangle";
    }
  EXPECT_EQ(segments, ref.size()) << "at level " << c;
}

TEST(LevelSet, MatchesTheTriangleByTriangleReferenceInR4) {
  std::mt19937 rng(37);
  const std::vector<Surface<4>> meshes{uv_sphere<4>(24, 1.0, Vec4(0.1, 0.2, 0.3, 0.4)), clifford_torus(20, 16),
                                       spun_trefoil(40, 12)};
  for (const Surface<4>& mesh : meshes)
    for (int trial = 0; trial < 6; ++trial) {
      const Frame<4> frame = random_frame<4>(rng);
      const auto [lo, hi] = depth_range(mesh, frame);
      for (double c : movie_levels(lo, hi, 5)) expect_matches_reference(mesh, frame, c);
    }
}

TEST(LevelSet, MatchesTheReferenceInR3AndR2) {
  std::mt19937 rng(3);
  const Surface<3> sphere = uv_sphere<3>(20, 1.0, Vec3::Zero());
  Surface<2> disk;  // a wobbly grid in the plane
  const Grid g{9, 11, false, false};
  for (int i = 0; i < g.rows; ++i)
    for (int j = 0; j < g.cols; ++j) disk.vertices.emplace_back(j + 0.3 * std::sin(i), i + 0.2 * std::cos(j));
  disk.triangles = grid_triangles(g);
  for (int trial = 0; trial < 5; ++trial) {
    const Frame<3> f3 = random_frame<3>(rng);
    const Frame<2> f2 = random_frame<2>(rng);
    const auto [lo3, hi3] = depth_range(sphere, f3);
    const auto [lo2, hi2] = depth_range(disk, f2);
    for (double c : movie_levels(lo3, hi3, 4)) {
      expect_matches_reference(sphere, f3, c);
      const LevelSet<3> s = level_set(sphere, f3, c);
      ASSERT_EQ(s.curve.components.size(), 1u);  // a round sphere's slice is one circle
      EXPECT_TRUE(s.curve.components[0].closed);
    }
    for (double c : movie_levels(lo2, hi2, 4)) {
      expect_matches_reference(disk, f2, c);
      const LevelSet<2> s = level_set(disk, f2, c);
      EXPECT_EQ(s.open_components, static_cast<int>(s.curve.components.size()));  // arcs across a disk
      EXPECT_GE(s.open_components, 1);
    }
  }
}

// Signed area of a closed curve of the plane.
double signed_area(const Polyline<2>& line) {
  double a = 0;
  for (std::size_t k = 0; k < line.segment_count(); ++k) {
    const Vec2 &p = line.seg_a(k), &q = line.seg_b(k);
    a += 0.5 * (p.x() * q.y() - p.y() * q.x());
  }
  return a;
}

TEST(LevelSet, ClosedCurvesAreOrientedAsTheBoundaryOfWhatLiesBelow) {
  const Surface<3> sphere = uv_sphere<3>(32, 1.0, Vec3::Zero());
  ASSERT_TRUE(summarize_topology(sphere).oriented);
  std::mt19937 rng(5);
  const Frame<3> frame = random_frame<3>(rng);
  const auto [lo, hi] = depth_range(sphere, frame);
  const std::vector<double> levels = movie_levels(lo, hi, 7);
  const double first = signed_area(level_set(sphere, frame, levels.front()).curve.components.at(0));
  for (double c : levels) {
    const double a = signed_area(level_set(sphere, frame, c).curve.components.at(0));
    EXPECT_GT(a * first, 0) << "the circle at " << c << " turns the other way";
    EXPECT_NEAR(std::abs(a), M_PI * (1 - c * c), 0.05);  // the disk of radius sqrt(1 - c²)
  }
}

TEST(LevelSet, CliffordTorusSlicesAreTwoCircles) {
  const Surface<4> torus = clifford_torus(48, 40);
  for (double c : {-0.9, -0.5, -0.1, 0.3, 0.8}) {
    const LevelSet<4> s = level_set(torus, Frame<4>{}, c);
    ASSERT_EQ(s.curve.components.size(), 2u) << "at w = " << c;
    for (const Polyline<3>& line : s.curve.components) {
      EXPECT_TRUE(line.closed);
      const double z = line.points[0].z();  // cos v with sin v = c: the circle at height ±sqrt(1 - c²)
      EXPECT_NEAR(std::abs(z), std::sqrt(1 - c * c), 0.02);
      for (const Vec3& p : line.points) EXPECT_NEAR(p.z(), z, 1e-12);
    }
  }
}

TEST(LevelSet, VerticesOnTheLevelAreCornersNotKinks) {
  // The spun trefoil's ring of angle 0 and its poles lie exactly on w = 0.
  const Surface<4> s = spun_trefoil(48, 12);
  const LevelSet<4> set = level_set(s, Frame<4>{}, 0.0);
  EXPECT_GE(set.vertices_at_level, 48);
  ASSERT_EQ(set.curve.components.size(), 1u);
  const Polyline<3>& line = set.curve.components[0];
  EXPECT_TRUE(line.closed);
  for (std::size_t k = 0; k < line.segment_count(); ++k) EXPECT_GT((line.seg_b(k) - line.seg_a(k)).norm(), 1e-9);
  // The arc and its mirror z -> -z: every vertex of the ring at angle 0 is a point of the slice.
  for (int i = 1; i + 1 < 48; ++i) {
    const Vec4& v = s.vertices[1 + (i - 1) * 12];
    bool on = false;
    for (const Vec3& p : line.points) on = on || (p - v.head<3>()).norm() < 1e-12;
    EXPECT_TRUE(on) << "ring " << i;
  }
}

TEST(LevelSet, LiftedSlicesLieOnTheLevel) {
  std::mt19937 rng(11);
  const Frame<4> frame = random_frame<4>(rng);
  const Surface<4> s = spun_trefoil(32, 10);
  const LevelSet<4> set = level_set(s, frame, 0.05);
  const Curve<4> lifted = lift_slice(set.curve, frame, 0.05);
  ASSERT_FALSE(lifted.components.empty());
  for (const Polyline<4>& line : lifted.components)
    for (const Vec4& p : line.points) EXPECT_NEAR(frame.depth(p), 0.05, 1e-12);
}

TEST(LevelSet, RefusesBadInput) {
  Surface<4> s = clifford_torus(8, 8);
  EXPECT_THROW(level_set(s, Frame<4>{}, std::nan("")), Error);
  s.vertices[3].x() = std::nan("");
  EXPECT_THROW(level_set(s, Frame<4>{}, 0.0), Error);
  s = clifford_torus(8, 8);
  s.triangles[0][1] = 1000;
  EXPECT_THROW(level_set(s, Frame<4>{}, 0.0), Error);
  EXPECT_TRUE(level_set(Surface<4>{}, Frame<4>{}, 0.0).curve.components.empty());
}

TEST(LevelSet, MovieLevelsLieInsideTheRangeWithTheMiddleExact) {
  const std::vector<double> l = movie_levels(-1.0, 0.6, 41);
  ASSERT_EQ(l.size(), 41u);
  EXPECT_EQ(l[20], -0.2);
  EXPECT_GT(l.front(), -1.0);
  EXPECT_LT(l.back(), 0.6);
  for (std::size_t i = 1; i < l.size(); ++i) EXPECT_GT(l[i], l[i - 1]);
  EXPECT_TRUE(movie_levels(0, 1, 0).empty());
}

// [SECTION] critical levels

TEST(CriticalLevels, BirthsMinusSaddlesPlusDeathsIsTheEulerCharacteristicOfEveryClosedSurface) {
  std::mt19937 rng(41);
  int closed_surfaces = 0;
  for (const GeneratorInfo& g : generator_catalogue()) {
    if (!g.surface || g.dim != 4) continue;
    const Shape shape = generate(g.name);
    const auto* mesh = std::get_if<Surface<4>>(&shape);
    ASSERT_NE(mesh, nullptr) << g.name;
    const TopologySummary t = summarize_topology(*mesh);
    if (!t.closed) continue;
    ++closed_surfaces;
    for (int trial = 0; trial < 4; ++trial) {
      const Frame<4> frame = trial == 0 ? Frame<4>{} : random_frame<4>(rng);
      const std::vector<CriticalPoint> points = critical_points(*mesh, frame);
      EXPECT_EQ(count_critical(points).euler_characteristic(), t.euler_characteristic) << g.name;
      for (std::size_t i = 1; i < points.size(); ++i) EXPECT_LE(points[i - 1].level, points[i].level);
    }
  }
  EXPECT_GE(closed_surfaces, 3);  // the sphere, the Clifford torus, the spun trefoil at least
}

TEST(CriticalLevels, KnownCounts) {
  // A round sphere seen generically: one birth, one death, nothing between.
  std::mt19937 rng(2);
  const CriticalCount sphere = count_critical(critical_points(uv_sphere<3>(32, 1.0, Vec3::Zero()), random_frame<3>(rng)));
  EXPECT_EQ(sphere.births, 1);
  EXPECT_EQ(sphere.deaths, 1);
  EXPECT_EQ(sphere.saddles, 0);
  // The Clifford torus by w = sin v: its slices are two circles between the circle of minima
  // (v = -π/2) and of maxima; a tie-broken circle of minima is a birth and a saddle.
  const std::vector<CriticalPoint> torus = critical_points(clifford_torus(16, 16), Frame<4>{});
  const CriticalCount t = count_critical(torus);
  EXPECT_EQ(t.euler_characteristic(), 0);
  for (const CriticalPoint& p : torus) EXPECT_NEAR(std::abs(p.level), 1.0, 1e-12);
  // A flat disk has a boundary: χ = 1.
  const Surface<4> cloth_mesh = cloth(9, 1.0);
  Frame<4> tilted;
  tilted.rotate(Plane{1, 3}, 0.4);
  tilted.rotate(Plane{0, 3}, 0.3);
  EXPECT_EQ(count_critical(critical_points(cloth_mesh, tilted)).euler_characteristic(), 1);
  EXPECT_STREQ(critical_kind_name(CriticalKind::kSaddle), "saddle");
}

TEST(CriticalLevels, SpunTrefoilSlicesChangeOnlyAtCriticalLevels) {
  // Between two consecutive critical levels the slice has the same number of curves.
  const Surface<4> s = spun_trefoil(48, 12);
  Frame<4> frame;
  frame.rotate(Plane{2, 3}, 0.3);
  const std::vector<CriticalPoint> points = critical_points(s, frame);
  ASSERT_GE(points.size(), 2u);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double a = points[i].level, b = points[i + 1].level;
    if (b - a < 1e-9) continue;
    const auto n1 = level_set(s, frame, a + 0.25 * (b - a)).curve.components.size();
    const auto n2 = level_set(s, frame, a + 0.75 * (b - a)).curve.components.size();
    EXPECT_EQ(n1, n2) << "between " << a << " and " << b;
  }
  const CriticalCount c = count_critical(points);
  EXPECT_EQ(c.euler_characteristic(), 2);
  EXPECT_GE(c.saddles, 1);  // a knotted sphere needs saddles
}

}  // namespace
}  // namespace s4d
