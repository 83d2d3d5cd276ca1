// Slices of surfaces of R^4 named by the one naming decision: the spun trefoil's slice through
// its spinning plane is the square knot, the Clifford torus's slices are 2-component unlinks.
#include "knots/slice_naming.hpp"

#include <gtest/gtest.h>

#include "shape/level_set.hpp"
#include "shape/spun_knot.hpp"
#include "shape/surfaces_4d.hpp"

namespace s4d {
namespace {

TEST(SliceNaming, SpunTrefoilThroughItsSpinningPlaneIsTheSquareKnot) {
  // The scenario's resolution; w = 0 holds the spinning plane z = w = 0, so the slice is the
  // arc and its mirror image z -> -z: the trefoil beside its mirror.
  const Surface<4> s = spun_trefoil(64, 12);
  const LevelSet<4> set = level_set(s, Frame<4>{}, 0.0);
  const SliceNaming n = name_slice(set.curve, 0.0);
  EXPECT_EQ(n.name, "3_1 # 3_1 mirror") << n.headline();
  EXPECT_TRUE(n.proven) << n.headline();
  EXPECT_EQ(n.components, 1);
  EXPECT_EQ(n.open_components, 0);
  EXPECT_TRUE(n.error.empty());
}

TEST(SliceNaming, SpunTrefoilNearTheTopIsUnknotted) {
  const Surface<4> s = spun_trefoil(64, 12);
  const auto [lo, hi] = depth_range(s, Frame<4>{});
  const double c = lo + 0.97 * (hi - lo);
  const SliceNaming n = name_slice(level_set(s, Frame<4>{}, c).curve, c);
  ASSERT_GE(n.components, 1);
  if (n.components == 1) {
    EXPECT_EQ(n.name, "unknot") << n.headline();
  }
}

TEST(SliceNaming, CliffordTorusSlicesAreTwoComponentUnlinks) {
  const Surface<4> torus = clifford_torus(48, 40);
  // Its critical levels are w = ±1 (the circles v = ±π/2); every level between is regular.
  for (double c : {-0.8, -0.3, 0.05, 0.5, 0.9}) {
    const SliceNaming n = name_slice(level_set(torus, Frame<4>{}, c).curve, c);
    EXPECT_EQ(n.components, 2) << c;
    EXPECT_EQ(n.name.rfind("unlink of 2 components", 0), 0u) << n.headline();
    EXPECT_TRUE(n.proven) << n.headline();
    ASSERT_EQ(n.linking.size(), 2u);
    EXPECT_EQ(n.linking[0][1], 0);
  }
}

TEST(SliceNaming, EmptyAndOpenSlicesAreSaidSo) {
  const SliceNaming empty = name_slice(Curve<3>{}, 5.0);
  EXPECT_EQ(empty.name, "empty");
  EXPECT_EQ(empty.components, 0);
  Curve<3> arc;
  arc.components.push_back({{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}, false});
  const SliceNaming open = name_slice(arc, 0.0);
  EXPECT_EQ(open.open_components, 1);
  EXPECT_EQ(open.name, "open arcs only");
}

}  // namespace
}  // namespace s4d
