// The knotted trefoil arc, the trefoil ribbon and ribbon loops: shape, topology, embedding.
#include "shape/ribbons.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "shape/mesh_checks.hpp"
#include "shape/knotted_arc.hpp"
#include "shape/polyline_ops.hpp"
#include "shape/shape.hpp"
#include "shape/topology.hpp"

namespace s4d {
namespace {

Curve<3> as_curve(const std::vector<Vec3>& pts, bool closed) {
  Curve<3> c;
  c.components.push_back({pts, closed});
  return c;
}

TEST(TrefoilArc, EndsOnTheFloorAndStaysAboveIt) {
  for (int n : {64, 160, 500}) {
    const auto arc = trefoil_arc(n, false);
    ASSERT_EQ(arc.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(arc.front().z(), 0.0);
    EXPECT_EQ(arc.back().z(), 0.0);
    for (int i = 1; i + 1 < n; ++i) EXPECT_GT(arc[i].z(), 0.0) << "point " << i;
    // Meets the floor at right angles: the first step goes straight up.
    const Vec3 d = (arc[1] - arc[0]).normalized();
    EXPECT_NEAR(d.z(), 1.0, 1e-9);
  }
}

TEST(TrefoilArc, EmbeddedWithClearanceAndKnotted) {
  const auto arc = trefoil_arc(400, false);
  const double clearance = test::curve_clearance(as_curve(arc, false), 12);
  EXPECT_GT(clearance, 0.25);
  // Close it through z < 0: straight down from both ends, across far below. Seen from above,
  // that closing path only retraces the short floor gap, so the diagram is the trefoil's.
  std::vector<Vec3> closed = arc;
  closed.push_back(arc.back() + Vec3(0, 0, -10));
  closed.push_back(arc.front() + Vec3(0, 0, -10));
  const auto x = test::diagram_crossings(as_curve(closed, true));
  int w = 0;
  for (const auto& c : x) w += c.sign;
  EXPECT_EQ(x.size(), 3u);
  EXPECT_EQ(std::abs(w), 3);  // three crossings of one sign: an alternating trefoil diagram
}

TEST(TrefoilArc, TailsLieOnTheFloorAlongX) {
  const auto arc = trefoil_arc(600, true);
  EXPECT_NEAR(arc.front().x(), 2.5, 1e-12);
  EXPECT_NEAR(arc.back().x(), -2.5, 1e-12);
  EXPECT_EQ(arc.front().z(), 0.0);
  EXPECT_EQ(arc.back().z(), 0.0);
  EXPECT_GT(test::curve_clearance(as_curve(arc, false), 12), 0.25);
}

TEST(TrefoilRibbon, OpenStripIsADiskWithoutSelfIntersection) {
  for (auto [n, m, width] : {std::tuple{300, 4, 0.15}, std::tuple{120, 2, 0.4},
                             std::tuple{600, 6, 0.3}}) {
    const Surface<3> s = trefoil_ribbon(n, m, width);
    ASSERT_TRUE(s.grid.has_value());
    EXPECT_EQ(*s.grid, (Grid{n, m, false, false}));
    EXPECT_EQ(s.vertex_count(), static_cast<std::size_t>(n) * m);
    const auto t = summarize_topology(s);
    EXPECT_EQ(t.euler_characteristic, 1);
    EXPECT_TRUE(t.manifold && t.oriented && !t.closed);
    EXPECT_EQ(t.boundary_edges, 2 * (n - 1) + 2 * (m - 1));
    const auto rep = test::self_intersections(s);
    EXPECT_EQ(rep.intersecting_pairs, 0) << "n=" << n << " m=" << m << " width=" << width;
  }
}

TEST(TrefoilRibbon, WidthAcrossIsExactAndFlatOnTheTails) {
  const double width = 0.2;
  const Surface<3> s = trefoil_ribbon(300, 5, width);
  const Grid g = *s.grid;
  for (int i = 0; i < g.rows; ++i)
    EXPECT_NEAR((s.vertices[g.index(i, 4)] - s.vertices[g.index(i, 0)]).norm(), width, 1e-9);
  // On the first tail the width runs along y (the strip lies flat on z = 0).
  const Vec3 across = s.vertices[g.index(0, 4)] - s.vertices[g.index(0, 0)];
  EXPECT_NEAR(std::abs(across.y()), width, 1e-9);
}

TEST(TrefoilRibbon, TooWideAWidthIsRejectedAndReallyWouldIntersect) {
  EXPECT_THROW(trefoil_ribbon(300, 4, 1.0), Error);
  // The limit is not arbitrary: a far wider strip on the same core does intersect itself.
  const auto core = trefoil_arc(300, true);
  const auto normals = rotation_minimising_normals(core, false, Vec3(0, 1, 0));
  const Surface<3> wide = ribbon_along(core, false, normals, 2.0, 4);
  EXPECT_GT(test::self_intersections(wide).intersecting_pairs, 0);
}

TEST(TrefoilRibbon, LiftedTo4DAtWZero) {
  const Surface<4> s = lift_to_4d(trefoil_ribbon(100, 3, 0.1));
  for (const Vec4& v : s.vertices) EXPECT_EQ(v.w(), 0.0);
}

TEST(RibbonLoop, AnnulusWithTwoBoundaryCircles) {
  const Surface<4> s = ribbon_loop(40, 4, 1.0, 0.3);
  const auto t = summarize_topology(s);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.boundary_edges, 2 * 40);
  EXPECT_TRUE(t.manifold && t.oriented && !t.closed);
  EXPECT_EQ(t.components, 1);
  for (const Vec4& v : s.vertices) {
    EXPECT_NEAR(v.head<2>().norm(), 1.0, 1e-12);
    EXPECT_LE(std::abs(v.z()), 0.15 + 1e-12);
    EXPECT_EQ(v.w(), 0.0);
  }
  EXPECT_EQ(test::self_intersections(s).intersecting_pairs, 0);
  EXPECT_THROW(ribbon_loop(40, 4, 0.1, 0.3), Error);
  EXPECT_THROW(ribbon_loop(2, 4, 1.0, 0.3), Error);
}

}  // namespace
}  // namespace s4d
