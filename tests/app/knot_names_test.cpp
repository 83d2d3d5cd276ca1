// The Scene panel's knot names: worked out on request, kept while the curve stays, dropped when
// it moves, and a sentence instead of a name for what is no knot.
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

TEST(KnotNames, NamesACurveAndKeepsTheNameWhileItStays) {
  KnotNames names;
  SceneObject k = object("trefoil", torus_knot(2, 3, 120));
  ASSERT_TRUE(KnotNames::nameable(k));
  EXPECT_EQ(names.find(k), nullptr) << "not named until asked";
  EXPECT_EQ(names.name(k), "knot: 3_1 (DT 3a_1)");
  ASSERT_NE(names.find(k), nullptr);
  EXPECT_EQ(*names.find(k), "knot: 3_1 (DT 3a_1)");
  // Another object of another name is not this one.
  EXPECT_EQ(names.find(object("other", torus_knot(2, 3, 120))), nullptr);
  // Moved by a hair, it is another curve: the name goes until asked again.
  std::get<Curve<3>>(k.shape).components[0].points[5].x() += 1e-9;
  EXPECT_EQ(names.find(k), nullptr);
  EXPECT_EQ(names.name(k), "knot: 3_1 (DT 3a_1)");
  EXPECT_NE(names.find(k), nullptr);
  // Another knot under the same name.
  EXPECT_EQ(names.name(object("trefoil", torus_knot(2, 5, 150))), "knot: 5_1 (DT 5a_2)");
  EXPECT_EQ(names.find(k), nullptr);
}

TEST(KnotNames, WhatIsNoKnotGetsASentence) {
  KnotNames names;
  EXPECT_FALSE(KnotNames::nameable(object("sphere", uv_sphere<4>(8, 1.0, Vec4::Zero()))));
  Curve<4> lifted;
  Polyline<4> p;
  const Curve<3> k = torus_knot(2, 3, 60);
  for (const Vec3& q : k.components[0].points) p.points.push_back(Vec4(q.x(), q.y(), q.z(), 0.1));
  p.closed = true;
  lifted.components.push_back(p);
  const SceneObject off = object("lifted", lifted);
  ASSERT_TRUE(KnotNames::nameable(off));
  EXPECT_EQ(names.name(off), "'lifted': a curve of R^4 off the w = 0 space is not a knot of R^3");
  Curve<3> open = torus_knot(2, 3, 60);
  open.components[0].closed = false;
  EXPECT_NE(names.name(object("open", open)).find("closed"), std::string::npos) << names.name(object("open", open));
}

}  // namespace
}  // namespace s4d
