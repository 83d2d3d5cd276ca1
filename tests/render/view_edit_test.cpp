// Changing a crossing through the view: only that crossing changes, on the screen everything stays,
// and the trefoil with one crossing changed is the unknot.
#include "interact/tools/view_edit.hpp"
#include "render/scene_geometry.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "knots/knot_identify.hpp"
#include "render/test_shapes.hpp"

namespace s4d {
namespace {

Vec2 ndc(const Camera& c, const Vec3& p) {
  const Eigen::Vector4d clip = c.projection() * c.view() * p.homogeneous();
  return clip.head<2>() / clip.w();
}

// Every crossing of `before` is at the same place in `after`, with the same over strand, except
// the one at `changed`, whose over strand is now the other.
void expect_only_changed(const Camera& cam, const std::vector<ScreenCrossing>& before,
                         const std::vector<ScreenCrossing>& after, const ScreenCrossing& changed) {
  ASSERT_EQ(after.size(), before.size());
  for (const ScreenCrossing& b : before) {
    const ScreenCrossing* a = nullptr;
    for (const ScreenCrossing& x : after)
      if ((ndc(cam, x.over) - ndc(cam, b.over)).norm() < 1e-7) a = &x;
    ASSERT_NE(a, nullptr);
    if ((ndc(cam, b.over) - ndc(cam, changed.over)).norm() < 1e-7) {
      EXPECT_EQ(a->over_at, b.under_at);
      EXPECT_EQ(a->under_at, b.over_at);
    } else {
      EXPECT_EQ(a->over_at, b.over_at);
    }
  }
}

TEST(ViewEdit, ChangingACrossingOfTheTrefoilGivesTheUnknotAndBack) {
  Scene sc = test::scene_of(test::trefoil());
  sc.view.trackball = Eigen::AngleAxisd(0.3, Vec3(1, 1, 0).normalized()) * Eigen::Quaterniond::Identity();
  const Camera cam = build_scene_geometry(sc, 1.3).camera;
  const auto before = screen_crossings(sc, cam).crossings;
  ASSERT_EQ(before.size(), 3u);
  ASSERT_GE(before[1].under_at.component, 0);
  Scene edited = sc;
  edited.objects[0].shape = change_crossing_in_view(sc, cam, before[1], 0.05);
  const auto after = screen_crossings(edited, cam).crossings;
  expect_only_changed(cam, before, after, before[1]);
  EXPECT_EQ(identify_knot(std::get<Curve<3>>(edited.objects[0].shape)).kind, KnotKind::kUnknot);
  // The same crossing changed back: a trefoil again.
  const ScreenCrossing* again = nullptr;
  for (const ScreenCrossing& a : after)
    if ((ndc(cam, a.over) - ndc(cam, before[1].over)).norm() < 1e-7) again = &a;
  ASSERT_NE(again, nullptr);
  Scene back = edited;
  back.objects[0].shape = change_crossing_in_view(edited, cam, *again, 0.05);
  EXPECT_EQ(identify_knot(std::get<Curve<3>>(back.objects[0].shape)).name, "3_1 (DT 3a_1)");
}

TEST(ViewEdit, ACurveInFourDimensionsKeepsItsDepthInW) {
  const Curve<3> k = test::trefoil();
  Curve<4> lifted;
  Polyline<4> p;
  p.closed = true;
  for (const Vec3& q : k.components[0].points) p.points.push_back(Vec4(q.x(), q.y(), q.z(), 0.3 * q.x()));
  lifted.components.push_back(p);
  Scene sc = test::scene_of(lifted);
  sc.frame.rotate(Plane{1, 2}, 0.2);
  const Camera cam = build_scene_geometry(sc, 1.0).camera;
  const auto before = screen_crossings(sc, cam).crossings;
  ASSERT_EQ(before.size(), 3u);
  Scene edited = sc;
  edited.objects[0].shape = change_crossing_in_view(sc, cam, before[0], 0.05);
  expect_only_changed(cam, before, screen_crossings(edited, cam).crossings, before[0]);
  const auto& out = std::get<Curve<4>>(edited.objects[0].shape).components[0].points;
  ASSERT_EQ(out.size(), p.points.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    EXPECT_NEAR(sc.frame.to_view(out[i])[3], sc.frame.to_view(p.points[i])[3], 1e-12) << "w of the view kept";
}

TEST(ViewEdit, WhatCannotBeChangedSaysWhy) {
  Scene sc = test::scene_of(test::trefoil());
  const Camera cam = build_scene_geometry(sc, 1.0).camera;
  const auto found = screen_crossings(sc, cam).crossings;
  ASSERT_FALSE(found.empty());
  ScreenCrossing hidden = found[0];
  hidden.under_at = {-1, -1};
  EXPECT_THROW(change_crossing_in_view(sc, cam, hidden, 0.05), Error) << "part behind the eye";
  Scene surf = test::scene_of(test::clifford_torus(12));
  ScreenCrossing on_surface = found[0];
  EXPECT_THROW(change_crossing_in_view(surf, cam, on_surface, 0.05), Error);
}

}  // namespace
}  // namespace s4d
