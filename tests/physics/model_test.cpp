// Model building: the paper's spring kinds on grids, edge + bending springs on meshes, thickness
// checks against the initial state, and parameter validation.
#include "physics/model.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.hpp"
#include "physics/test_worlds.hpp"
#include "proximity/closest_points.hpp"
#include "shape/generators.hpp"
#include "shape/surfaces_4d.hpp"
#include "shape/topology.hpp"

namespace s4d {
namespace {

int count(const std::vector<Spring>& s, SpringKind k) {
  return static_cast<int>(std::count_if(s.begin(), s.end(), [&](const Spring& x) { return x.kind == k; }));
}

TEST(MakeSprings, OpenGridHasThePapersThreeKinds) {
  const int n = 6;
  const auto springs = make_springs<4>(cloth(n, 1.0), 10, 0.5, 0.1);
  EXPECT_EQ(count(springs, SpringKind::kStructural), 2 * n * (n - 1));
  EXPECT_EQ(count(springs, SpringKind::kShear), 2 * (n - 1) * (n - 1));
  EXPECT_EQ(count(springs, SpringKind::kBending), 2 * n * (n - 2));
  const double h = 1.0 / (n - 1);
  for (const Spring& s : springs) {
    const double expect = s.kind == SpringKind::kStructural ? h
                          : s.kind == SpringKind::kShear    ? h * std::sqrt(2.0)
                                                            : 2 * h;
    EXPECT_NEAR(s.rest, expect, 1e-12);
    EXPECT_DOUBLE_EQ(s.k, s.kind == SpringKind::kStructural ? 10 : s.kind == SpringKind::kShear ? 5 : 1);
  }
}

TEST(MakeSprings, WrappedGridWrapsEveryKind) {
  const int n = 7, m = 9;
  const auto springs = make_springs<4>(clifford_torus(n, m), 1, 1, 1);
  EXPECT_EQ(count(springs, SpringKind::kStructural), 2 * n * m);
  EXPECT_EQ(count(springs, SpringKind::kShear), 2 * n * m);
  EXPECT_EQ(count(springs, SpringKind::kBending), 2 * n * m);
}

TEST(MakeSprings, MeshWithoutGridUsesEdgesAndBendingAcrossEdges) {
  const Surface<4> sphere = uv_sphere<4>(12, 1.0, Vec4::Zero());
  ASSERT_FALSE(sphere.grid);
  const auto springs = make_springs<4>(sphere, 1, 0.5, 0.1);
  const auto edges = mesh_edges(sphere.triangles);
  EXPECT_EQ(count(springs, SpringKind::kStructural), static_cast<int>(edges.size()));
  EXPECT_EQ(count(springs, SpringKind::kShear), 0);
  // A closed triangulated sphere: every edge has two triangles, so one bending spring per edge
  // unless the two opposite vertices are already joined (never, for this sphere: n >= 4).
  EXPECT_EQ(count(springs, SpringKind::kBending), static_cast<int>(edges.size()));
  for (const Spring& s : springs) EXPECT_NE(s.a, s.b);
}

template <int D>
void builds_in_dimension() {
  ModelBuilder<D> b(test::quiet_params<D>());
  b.add_body(test::flat_cloth<D>(5, 1.0));
  const Model<D> m = b.build();
  EXPECT_EQ(m.nv, 25);
  EXPECT_EQ(m.triangles.size(), 32u);
  EXPECT_GT(m.contact_thickness, 0);
  EXPECT_LT(m.hard_thickness, m.contact_thickness);
  EXPECT_TRUE(m.mesh_adjacent(0, 1));
  EXPECT_FALSE(m.mesh_adjacent(0, 2));
}
TEST(ModelBuilder, BuildsInD2) { builds_in_dimension<2>(); }
TEST(ModelBuilder, BuildsInD3) { builds_in_dimension<3>(); }
TEST(ModelBuilder, BuildsInD4) { builds_in_dimension<4>(); }

TEST(ModelBuilder, ThicknessStaysBelowRestGaps) {
  // Grid spacing 0.1: the default δ = 0.02 fits as it is; δ = 0.5 must shrink to 0.9 × the
  // smallest rest gap between triangles that no mesh edge joins (brute force reference).
  PhysicsParams<4> p = test::quiet_params<4>();
  ModelBuilder<4> fits(p);
  fits.add_body(test::flat_cloth<4>(11, 1.0));
  EXPECT_DOUBLE_EQ(fits.build().contact_thickness, 0.02);
  p.thickness = 0.5;
  ModelBuilder<4> b(p);
  b.add_body(test::flat_cloth<4>(11, 1.0));
  const Model<4> m = b.build();
  double far = 1e300, all = 1e300;
  for (const Triangle& a : m.triangles)
    for (const Triangle& c : m.triangles) {
      bool shared = false;
      for (int u : a)
        for (int v : c) shared = shared || u == v;
      if (shared) continue;
      const double d = triangle_triangle<4>({m.initial[a[0]], m.initial[a[1]], m.initial[a[2]]},
                                            {m.initial[c[0]], m.initial[c[1]], m.initial[c[2]]})
                           .distance;
      all = std::min(all, d);
      if (!m.near_adjacent(a, c)) far = std::min(far, d);
    }
  EXPECT_NEAR(m.contact_thickness, 0.9 * far, 1e-12);
  EXPECT_DOUBLE_EQ(m.hard_thickness, std::min(0.25 * m.contact_thickness, 0.5 * all));
  EXPECT_GT(far, 0.09);  // nothing closer than a grid step is left unguarded by springs
}

TEST(ModelBuilder, RejectsAnIntersectingStart) {
  ModelBuilder<4> b(test::quiet_params<4>());
  b.add_body(test::flat_cloth<4>(4, 1.0));
  b.add_body(test::flat_cloth<4>(4, 1.0, Vec4(0.01, 0.02, 0, 0)));  // coplanar overlap
  EXPECT_THROW(b.build(), Error);
}

TEST(ModelBuilder, RejectsBadInput) {
  PhysicsParams<3> p;
  p.mass = -1;
  ModelBuilder<3> b(p);
  b.add_body(test::lone_triangle<3>(1.0));
  EXPECT_THROW(b.build(), Error);
  ModelBuilder<3> empty(PhysicsParams<3>{});
  EXPECT_THROW(empty.build(), Error);
  Surface<3> bad = test::lone_triangle<3>(1.0);
  bad.triangles[0][2] = 7;
  ModelBuilder<3> c(PhysicsParams<3>{});
  EXPECT_THROW(c.add_body(bad), Error);
  EXPECT_THROW(parse_integrator("runge-kutta"), Error);
  EXPECT_EQ(parse_integrator("paper-euler"), Integrator::kPaperEuler);
}

TEST(Model, SubstepsFollowStiffness) {
  PhysicsParams<4> p = test::quiet_params<4>();
  p.stiffness = 2e4;  // N/m with 1 g masses: ω far above 1 kHz
  ModelBuilder<4> b(p);
  b.add_body(test::flat_cloth<4>(5, 1.0));
  const Model<4> m = b.build();
  EXPECT_GE(m.substeps(1e-3), static_cast<int>(std::ceil(1e-3 * m.omega_max)));
  EXPECT_GT(m.substeps(1e-3), 5);
  PhysicsParams<4> q = p;
  q.integrator = Integrator::kPaperEuler;
  ModelBuilder<4> c(q);
  c.add_body(test::flat_cloth<4>(5, 1.0));
  EXPECT_EQ(c.build().substeps(1e-3), 1);
}

}  // namespace
}  // namespace s4d
