// The finders: self-intersections of a surface in R^4, and the intersection curves of its 3D
// shadow classified by 4D depth, on surfaces whose answers are known by construction.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "proximity/self_intersections.hpp"
#include "proximity/shadow_intersections.hpp"

namespace s4d {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A flat n × n grid patch o + s·u + t·v, s, t in [-1, 1], appended to `m`.
void add_patch(Surface<4>& m, const Vec4& o, const Vec4& u, const Vec4& v, int n) {
  const int base = static_cast<int>(m.vertices.size());
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      m.vertices.push_back(o + (2.0 * i / n - 1) * u + (2.0 * j / n - 1) * v);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = base + i * (n + 1) + j, b = a + 1, c = a + (n + 1), d = c + 1;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
}

// The Clifford torus (cos u, sin u, cos v, sin v)/sqrt 2: embedded in R^4.
Surface<4> clifford_torus(int n) {
  Surface<4> s;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / n;
      s.vertices.push_back(Vec4(std::cos(u), std::sin(u), std::cos(v), std::sin(v)) / std::sqrt(2));
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * n + j, b = i * n + (j + 1) % n, c = ((i + 1) % n) * n + j,
                d = ((i + 1) % n) * n + (j + 1) % n;
      s.triangles.push_back({a, b, d});
      s.triangles.push_back({a, d, c});
    }
  return s;
}

Frame<4> generic_frame() {
  Frame<4> f;
  f.rotate({0, 3}, 0.5);
  f.rotate({1, 2}, 0.3);
  f.rotate({1, 3}, 0.7);
  f.rotate({0, 2}, 0.2);
  return f;
}

// Two patches in complementary planes (xy and zw) crossing at the single point `at`.
Surface<4> crossing_patches(const Vec4& at) {
  Surface<4> s;
  add_patch(s, Vec4(at.x(), at.y(), 0, 0) + Vec4(0.013, -0.021, 0, 0), Vec4(1, 0, 0, 0),
            Vec4(0, 1, 0, 0), 8);
  add_patch(s, Vec4(0, 0, at.z(), at.w()) + Vec4(0, 0, 0.017, 0.011), Vec4(0, 0, 1, 0),
            Vec4(0, 0, 0, 1), 8);
  return s;
}

TEST(SelfIntersections, EmbeddedCliffordTorusHasNone) {
  const auto r = self_intersections(clifford_torus(32));
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_TRUE(r.points.empty());
}

TEST(SelfIntersections, ComplementaryPlanesMeetInExactlyOnePoint) {
  const Surface<4> s = crossing_patches(Vec4::Zero());
  const auto r = self_intersections(s);
  ASSERT_EQ(r.points.size(), 1u);
  EXPECT_GE(r.pairs.size(), 1u);
  // The planes z = w = 0 and x = y = 0 meet at the origin (the patches' offsets lie in their
  // own planes and only keep the crossing away from vertices and edges).
  EXPECT_NEAR(r.points[0].norm(), 0.0, 1e-12);
  // The two planes span R^4, so shifting one patch (its first 81 vertices) by a small vector
  // keeps exactly one crossing; a shift in z and w moves it by that much.
  Surface<4> moved = s;
  for (int i = 0; i < 81; ++i) moved.vertices[i] += Vec4(0, 0, 0.1, -0.2);
  const auto r2 = self_intersections(moved);
  ASSERT_EQ(r2.points.size(), 1u);
  EXPECT_NEAR((r2.points[0] - Vec4(0, 0, 0.1, -0.2)).norm(), 0.0, 1e-12);
}

TEST(SelfIntersections, BetweenTwoSurfaces) {
  Surface<4> a, b;
  add_patch(a, Vec4(0.01, 0.02, 0, 0), Vec4(1, 0, 0, 0), Vec4(0, 1, 0, 0), 6);
  add_patch(b, Vec4(0, 0, 0.03, 0.04), Vec4(0, 0, 1, 0), Vec4(0, 0, 0, 1), 6);
  const auto r = surface_intersections(a, b);
  ASSERT_EQ(r.points.size(), 1u);
  EXPECT_NEAR(r.points[0].norm(), 0.0, 1e-12);
  for (auto& v : b.vertices) v += Vec4(3, 0, 0, 0);  // now far apart
  EXPECT_TRUE(surface_intersections(a, b).points.empty());
}

TEST(SelfIntersections, AmongGivenPairsIsTheWholeSearchRestrictedToThem) {
  // A crumpled ribbon in R^3 (a strip along a curve that crosses itself and folds back): its
  // meeting pairs by the whole search, against the restricted one over every pair, over the pairs
  // of one half, and over a list with repeats, reversed pairs, a triangle with itself and pairs
  // sharing a vertex (skipped).
  Surface<3> s;
  const int n = 120;
  for (int i = 0; i < n; ++i) {
    const double t = 4 * kPi * i / n;
    const Vec3 c(std::cos(t) + 0.4 * std::cos(3 * t), std::sin(t), 0.05 * std::sin(5 * t));
    s.vertices.push_back(c + Vec3(0, 0, 0.08));
    s.vertices.push_back(c - Vec3(0, 0, 0.08));
  }
  for (int i = 0; i + 1 < n; ++i) {
    s.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
    s.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
  }
  const auto whole = self_intersections(s);
  ASSERT_GT(whole.pairs.size(), 4u);
  const int nt = static_cast<int>(s.triangles.size());
  std::vector<std::array<int, 2>> every, half, messy;
  for (int a = 0; a < nt; ++a)
    for (int b = a + 1; b < nt; ++b) {
      every.push_back({b, a});
      if (a < nt / 2) half.push_back({a, b});
    }
  std::vector<std::pair<int, int>> expected_half;
  for (const auto& p : whole.pairs) {
    if (p.a < nt / 2) expected_half.push_back({p.a, p.b});
    messy.push_back({p.b, p.a});
    messy.push_back({p.a, p.b});
    messy.push_back({p.a, p.a});
    messy.push_back({p.a, p.a + 1});  // a neighbour: skipped if it shares a vertex
  }
  auto ids = [](const IntersectionReport<3>& r) {
    std::vector<std::pair<int, int>> out;
    for (const auto& p : r.pairs) out.push_back({p.a, p.b});
    return out;
  };
  const auto all = self_intersections_among(s, every);
  EXPECT_EQ(ids(all), ids(whole));
  EXPECT_EQ(all.points.size(), whole.points.size());
  EXPECT_EQ(all.tolerance, whole.tolerance);
  EXPECT_EQ(ids(self_intersections_among(s, half)), expected_half);
  EXPECT_EQ(ids(self_intersections_among(s, messy)), ids(whole));
  EXPECT_TRUE(self_intersections_among(s, std::span<const std::array<int, 2>>()).pairs.empty());
  const std::vector<std::array<int, 2>> bad{{0, nt}};
  EXPECT_THROW(self_intersections_among(s, bad), Error);
}

// Every segment is in exactly one stroke, and a stroke's points are its segments' ends in
// walking order: segment i runs from point i to point i + 1 (either way round).
void expect_strokes_walk_the_segments(const ShadowIntersections& r, double tol) {
  std::vector<int> seen(r.segments.size(), 0);
  for (const ShadowStroke& k : r.strokes) {
    ASSERT_FALSE(k.segments.empty());
    ASSERT_EQ(k.points.size(), k.segments.size() + 1);
    for (std::size_t i = 0; i < k.segments.size(); ++i) {
      const ShadowSegment& s = r.segments[k.segments[i]];
      ++seen[k.segments[i]];
      const double ahead = std::max((s.p0 - k.points[i]).norm(), (s.p1 - k.points[i + 1]).norm());
      const double back = std::max((s.p1 - k.points[i]).norm(), (s.p0 - k.points[i + 1]).norm());
      EXPECT_LE(std::min(ahead, back), tol) << "segment " << i << " of a stroke";
    }
    if (k.closed) {
      EXPECT_EQ(k.points.front(), k.points.back());
    }
  }
  for (int n : seen) EXPECT_EQ(n, 1);
}

TEST(ShadowIntersections, TrueCrossingIsFoundWhereTheDepthsAgree) {
  const Surface<4> s = crossing_patches(Vec4::Zero());
  const Frame<4> f = generic_frame();
  const ShadowIntersections r = shadow_intersections(s, f);
  // Two planar pieces in general position in the shadow meet along one straight curve.
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_FALSE(r.curves[0].closed);
  EXPECT_EQ(r.true_curves, 1);
  EXPECT_EQ(r.shadow_only_curves, 0);
  EXPECT_GT(r.total_length, 0.5);
  // Exactly one segment changes depth order, at the shadow of the 4D crossing point (or two,
  // if that point falls on a shared end).
  int meets = 0;
  for (const auto& seg : r.segments)
    if (seg.true_intersection) {
      ++meets;
      EXPECT_NEAR((seg.meet - f.shadow(Vec4::Zero())).norm(), 0.0, 1e-9);
    }
  EXPECT_GE(meets, 1);
  EXPECT_LE(meets, 2);
  // The one-line report adds them up: twice the same result, twice everything.
  ShadowCurveCounts counts;
  counts.add(r);
  counts.add(r);
  EXPECT_EQ(counts.curves, 2);
  EXPECT_EQ(counts.true_curves, 2);
  EXPECT_EQ(counts.true_points, 2 * meets);
  EXPECT_NEAR(counts.length, 2 * r.total_length, 1e-12);
  EXPECT_EQ(counts_text(counts).rfind("2 curve(s), total length ", 0), 0u) << counts_text(counts);
  EXPECT_NE(counts_text(counts).find(": 0 shadow-only, 2 true (" + std::to_string(2 * meets) +
                                     " true point(s))"),
            std::string::npos);
  EXPECT_EQ(counts_text(counts).find("not generic"), std::string::npos);
  // The segments are straight pieces of one line: their lengths add up to its end-to-end length.
  Vec3 lo = r.segments[0].p0, hi = lo;
  const Vec3 dir = (r.segments[0].p1 - r.segments[0].p0).normalized();
  double tmin = 0, tmax = 0;
  for (const auto& seg : r.segments)
    for (const Vec3& p : {seg.p0, seg.p1}) {
      EXPECT_NEAR((p - lo - (p - lo).dot(dir) * dir).norm(), 0.0, 1e-9);
      tmin = std::min(tmin, (p - lo).dot(dir));
      tmax = std::max(tmax, (p - lo).dot(dir));
    }
  (void)hi;
  EXPECT_NEAR(r.total_length, tmax - tmin, 1e-9);
  // Drawn as one open stroke from one end of the line to the other.
  ASSERT_EQ(r.strokes.size(), 1u);
  EXPECT_FALSE(r.strokes[0].closed);
  EXPECT_NEAR((r.strokes[0].points.back() - r.strokes[0].points.front()).norm(), tmax - tmin, 1e-9);
  expect_strokes_walk_the_segments(r, 1e-9);
}

TEST(ShadowIntersections, SameShadowApartInDepthIsShadowOnly) {
  const Frame<4> f = generic_frame();
  Surface<4> s = crossing_patches(Vec4::Zero());
  const ShadowIntersections before = shadow_intersections(s, f);
  // Push the second patch far along the viewing (depth) axis: the same shadow, and the depth
  // difference (which varies by less than 5 across the patches) never vanishes: no 4D meeting.
  for (std::size_t i = 81; i < s.vertices.size(); ++i) s.vertices[i] += 5.0 * f.axis(3);
  const ShadowIntersections after = shadow_intersections(s, f);
  EXPECT_EQ(after.curves.size(), before.curves.size());
  EXPECT_NEAR(after.total_length, before.total_length, 1e-9);
  EXPECT_EQ(after.true_curves, 0);
  EXPECT_EQ(after.shadow_only_curves, 1);
  EXPECT_TRUE(self_intersections(s).points.empty());
  for (const auto& seg : after.segments) {  // sheet b is behind sheet a all along
    EXPECT_GT(seg.depth_b0 - seg.depth_a0, 0.5);
    EXPECT_GT(seg.depth_b1 - seg.depth_a1, 0.5);
  }
}

TEST(ShadowIntersections, CliffordTorusShadowCrossesItselfOnlyInTheShadow) {
  const Surface<4> t = clifford_torus(40);
  const ShadowIntersections r = shadow_intersections(t, generic_frame());
  EXPECT_GT(r.segments.size(), 0u);
  EXPECT_GT(r.total_length, 0.1);
  EXPECT_EQ(r.true_curves, 0);
  EXPECT_EQ(r.shadow_only_curves, static_cast<int>(r.curves.size()));
  double sum = 0;
  for (const auto& c : r.curves) sum += c.length;
  EXPECT_NEAR(sum, r.total_length, 1e-12);
  // Each closed curve (a loop with no branch or end) is walked as one closed stroke.
  expect_strokes_walk_the_segments(r, 1e-9);
  int closed_curves = 0;
  for (const auto& c : r.curves) closed_curves += c.closed;
  int closed_strokes = 0;
  for (const auto& k : r.strokes) closed_strokes += k.closed;
  EXPECT_EQ(closed_strokes, closed_curves);
  // In this view the shadow has two double curves, each ending at two branch points (Whitney
  // umbrellas), with no triple point: one open stroke each.
  EXPECT_EQ(r.curves.size(), 2u);
  EXPECT_EQ(r.strokes.size(), 2u);
  EXPECT_EQ(closed_curves, 0);
}

// A round sphere of radius r about c in the 3-space w = c.w (latitude-longitude mesh).
void add_sphere(Surface<4>& m, const Vec4& c, double r, int n) {
  const int base = static_cast<int>(m.vertices.size());
  m.vertices.push_back(c + Vec4(0, 0, r, 0));
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double th = kPi * i / n, ph = kPi * j / n;
      m.vertices.push_back(c + r * Vec4(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                                        std::cos(th), 0));
    }
  m.vertices.push_back(c + Vec4(0, 0, -r, 0));
  const int south = static_cast<int>(m.vertices.size()) - 1;
  auto ring = [&](int i, int j) { return base + 1 + (i - 1) * 2 * n + (j % (2 * n)); };
  for (int j = 0; j < 2 * n; ++j) {
    m.triangles.push_back({base, ring(1, j), ring(1, j + 1)});
    m.triangles.push_back({south, ring(n - 1, j + 1), ring(n - 1, j)});
    for (int i = 1; i + 1 < n; ++i) {
      m.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  }
}

TEST(ShadowIntersections, OverlappingSpheresApartInDepthCrossInOneClosedStroke) {
  // Two unit spheres 1 apart in x and 2 apart in w: their shadows (seen along w) meet in one circle
  // of radius sqrt(3)/2, only in the shadow.
  Surface<4> a, b;
  add_sphere(a, Vec4(0, 0, 0, 0), 1.0, 24);
  add_sphere(b, Vec4(1, 0.01, 0.02, 2), 1.0, 24);
  const ShadowIntersections r = shadow_intersections(a, b, Frame<4>());
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  EXPECT_EQ(r.shadow_only_curves, 1);
  EXPECT_NEAR(r.total_length, 2 * kPi * std::sqrt(3.0) / 2, 0.05);
  ASSERT_EQ(r.strokes.size(), 1u);
  EXPECT_TRUE(r.strokes[0].closed);
  EXPECT_EQ(r.strokes[0].segments.size(), r.segments.size());
  expect_strokes_walk_the_segments(r, 1e-9);
}

TEST(ShadowIntersections, StrokesWalkTheCurvesOfThreeCrossingPatchesInManyViews) {
  // Crossing patches at several places and turns: curves that end on the patches' borders and
  // meet each other, so strokes start at ends and at branch points.
  Surface<4> s;
  add_patch(s, Vec4(0, 0, 0, 0), Vec4(1, 0, 0.1, 0), Vec4(0, 1, 0, 0.2), 6);
  add_patch(s, Vec4(0.1, 0.05, 0, 0.3), Vec4(0, 0, 1, 0), Vec4(0.2, 0, 0, 1), 6);
  add_patch(s, Vec4(-0.2, 0.1, 0.05, -0.4), Vec4(0, 0.9, 0.4, 0), Vec4(0.3, 0, 0, 0.8), 5);
  for (int turn = 0; turn < 6; ++turn) {
    Frame<4> f = generic_frame();
    f.rotate({0, 1}, 0.4 * turn);
    f.rotate({2, 3}, 0.25 * turn);
    const ShadowIntersections r = shadow_intersections(s, f);
    ASSERT_GT(r.segments.size(), 10u);
    expect_strokes_walk_the_segments(r, 1e-9);
    double stroke_length = 0;
    for (const auto& k : r.strokes)
      for (std::size_t i = 0; i + 1 < k.points.size(); ++i)
        stroke_length += (k.points[i + 1] - k.points[i]).norm();
    EXPECT_NEAR(stroke_length, r.total_length, 1e-7);
  }
}

}  // namespace
}  // namespace s4d
