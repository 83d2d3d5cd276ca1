// The toolbar's edits: a mirrored knot is its mirror image in place, a reversed component turns
// the sign of its linking numbers, a deleted component leaves the rest, and bad components are
// refused.
#include "knots/curve_edits.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "knots/knot_identify.hpp"
#include "knots/knot_table.hpp"

namespace s4d {
namespace {

TEST(CurveEdits, MirrorGivesTheMirrorImageInPlace) {
  const Curve<3> k = make_table_knot("5_2");
  const Curve<3> m = mirrored_curve(k);
  EXPECT_EQ(identify_knot(m).name, "5_2 mirror (DT 5a_1)");
  EXPECT_EQ(identify_knot(mirrored_curve(m)).name, "5_2 (DT 5a_1)");
  EXPECT_EQ(m.point_count(), k.point_count());
  auto box = [](const Curve<3>& c) {
    Vec3 lo = c.components[0].points[0], hi = lo;
    for (const Vec3& p : c.components[0].points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    return std::pair{lo, hi};
  };
  EXPECT_LT((box(k).first - box(m).first).norm(), 1e-9) << "it stays where it was";
  EXPECT_LT((box(k).second - box(m).second).norm(), 1e-9);
}

TEST(CurveEdits, ReversingAComponentTurnsItsLinkingNumbers) {
  const Curve<3> hopf = make_table_knot("Hopf link");
  const int lk = identify_knot(hopf).invariants.linking[0][1];
  ASSERT_NE(lk, 0);
  EXPECT_EQ(identify_knot(with_component_reversed(hopf, 1)).invariants.linking[0][1], -lk);
  EXPECT_EQ(identify_knot(with_component_reversed(with_component_reversed(hopf, 1), 1)).invariants.linking[0][1], lk);
  // L7n1 is a trefoil and an unknot: reversing either keeps the link's name (every orientation
  // of a table link is that link).
  const Curve<3> l = make_table_knot("L7n1");
  EXPECT_EQ(identify_knot(with_component_reversed(l, 0)).name.rfind("L7n1", 0), 0u);
}

TEST(CurveEdits, DeletingAComponentLeavesTheRest) {
  const Curve<3> l = make_table_knot("L7n1");  // components: 3_1 and an unknot
  const auto a = identify_knot(with_component_deleted(l, 0)), b = identify_knot(with_component_deleted(l, 1));
  std::vector<std::string> names{a.name, b.name};
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names[0].rfind("3_1", 0), 0u) << names[0];
  EXPECT_EQ(names[1], "unknot");
  EXPECT_EQ(with_component_deleted(l, 0).components.size(), 1u);
}

TEST(CurveEdits, MissingComponentsAndTheLastOneAreRefused) {
  const Curve<3> k = make_table_knot("3_1");
  EXPECT_THROW(with_component_reversed(k, 1), Error);
  EXPECT_THROW(with_component_reversed(k, -1), Error);
  EXPECT_THROW(with_component_deleted(k, 0), Error);
  EXPECT_THROW(with_component_deleted(make_table_knot("Hopf link"), 2), Error);
}

}  // namespace
}  // namespace s4d
