// The Scene panel's knot names: small curves named live and kept while they stay, renamed when
// they move; large ones named on request; a sentence instead of a name for what is no knot.
#include "app/knot_names.hpp"

#include <gtest/gtest.h>

#include "shape/knot_curves.hpp"
#include "shape/surfaces_4d.hpp"

namespace s4d {
namespace {

SceneObject object(std::string name, Shape shape) {
  SceneObject o;
  o.name = std::move(name);
  o.shape = std::move(shape);
  return o;
}

TEST(KnotNames, SmallCurvesAreNamedLiveAndRenamedWhenTheyChange) {
  KnotNames names;
  SceneObject k = object("k", torus_knot(2, 3, 120));
  ASSERT_TRUE(KnotNames::nameable(k));
  const std::string* line = names.live(k);
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(*line, "knot: 3_1 (DT 3a_1)");
  EXPECT_EQ(names.live(k), line) << "kept while the points stay";
  // Moved by a hair it is another curve, named again: still a trefoil.
  std::get<Curve<3>>(k.shape).components[0].points[5].x() += 1e-9;
  ASSERT_NE(names.live(k), nullptr);
  EXPECT_EQ(*names.live(k), "knot: 3_1 (DT 3a_1)");
  // Another knot under the same name is named for what it is.
  k.shape = torus_knot(2, 5, 150);
  ASSERT_NE(names.live(k), nullptr);
  EXPECT_EQ(*names.live(k), "knot: 5_1 (DT 5a_2)");
  // Each object keeps its own name.
  ASSERT_NE(names.live(object("other", torus_knot(2, 3, 120))), nullptr);
  EXPECT_EQ(*names.live(k), "knot: 5_1 (DT 5a_2)");
}

TEST(KnotNames, LargeCurvesWaitForARequest) {
  KnotNames names;
  // T(2, 17) seen down its axis: 17 crossings, one more than is named live.
  const SceneObject big = object("big", torus_knot(2, KnotNames::kLiveCrossings + 1, 400));
  EXPECT_EQ(names.live(big), nullptr);
  EXPECT_EQ(names.live(big), nullptr) << "still waiting, not named behind the user's back";
  EXPECT_EQ(names.name(big),
            "knot: unknown (17 crossings after simplification; the table goes to 14)  [not proven]");
  ASSERT_NE(names.live(big), nullptr) << "named once asked, and kept";
  EXPECT_EQ(*names.live(big), names.name(big));
}

TEST(KnotNames, WhatIsNoKnotGetsASentence) {
  KnotNames names;
  EXPECT_FALSE(KnotNames::nameable(object("sphere", uv_sphere<4>(8, 1.0, Vec4::Zero()))));
  const Curve<3> k = torus_knot(2, 3, 60);
  Curve<4> lifted;
  Polyline<4> p;
  for (const Vec3& q : k.components[0].points) p.points.push_back(Vec4(q.x(), q.y(), q.z(), 0.1));
  p.closed = true;
  lifted.components.push_back(p);
  const std::string* line = names.live(object("lifted", lifted));
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(*line, "'lifted': a curve of R^4 off the w = 0 space is not a knot of R^3");
  Curve<3> open = k;
  open.components[0].closed = false;
  line = names.live(object("open", open));
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(*line, "component 0 is open; knots and links are closed curves");
}

}  // namespace
}  // namespace s4d
