// A scene's slice (view/scene_slice.hpp): every surface of R^4 cut at the level together, each
// piece knowing its object; the critical levels of all of them; the slice back on the level.
#include "view/scene_slice.hpp"

#include <gtest/gtest.h>

#include "shape/surfaces_4d.hpp"

namespace s4d {
namespace {

Scene torus_and_sphere() {
  Scene sc;
  SceneObject torus;
  torus.name = "torus";
  torus.shape = clifford_torus(32, 32);  // w in [-1, 1]
  SceneObject sphere;
  sphere.name = "sphere";
  sphere.shape = uv_sphere<4>(16, 0.5, Vec4(3, 0, 0, 0.25));  // in the hyperplane w = 0.25
  SceneObject knot;
  knot.name = "knot";
  knot.shape = Curve<3>{{{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, true}}};  // not cut
  sc.objects = {torus, sphere, knot};
  return sc;
}

TEST(SceneSlice, EverySurfaceIsCutAndEachPieceKnowsItsObject) {
  Scene sc = torus_and_sphere();
  EXPECT_TRUE(has_4d_surfaces(sc));
  const auto [lo, hi] = scene_depth_range(sc);
  EXPECT_NEAR(lo, -1, 1e-9);
  EXPECT_NEAR(hi, 1, 1e-9);
  const SceneSlice at = scene_slice(sc, 0.5);
  ASSERT_EQ(at.curve.components.size(), 2u);  // the torus's two circles; the flat sphere lies below
  EXPECT_EQ(at.object_of, (std::vector<int>{0, 0}));
  // Just below the sphere's hyperplane the whole sphere counts as above: cut nowhere; at its level
  // every vertex is above (the symbolic perturbation), so still nothing of it.
  EXPECT_EQ(scene_slice(sc, 0.25).object_of, (std::vector<int>{0, 0}));
  const SceneObject lifted = slice_object(at, sc.frame, "slice");
  for (const Polyline<4>& line : std::get<Curve<4>>(lifted.shape).components)
    for (const Vec4& p : line.points) EXPECT_NEAR(p.w(), 0.5, 1e-12);
  sc.objects.resize(2);
  sc.objects.erase(sc.objects.begin());
  sc.frame.rotate(Plane{0, 3}, 0.5);  // the sphere turned out of its hyperplane: cut in a circle
  const auto [slo, shi] = scene_depth_range(sc);
  const SceneSlice sphere = scene_slice(sc, 0.5 * (slo + shi));
  ASSERT_EQ(sphere.curve.components.size(), 1u);
  EXPECT_EQ(sphere.object_of, (std::vector<int>{0}));
}

TEST(SceneSlice, CriticalLevelsOfAllSurfacesSumToTheirEulerCharacteristics) {
  Scene sc = torus_and_sphere();
  sc.frame.rotate(Plane{1, 3}, 0.3);
  const std::vector<SceneCriticalPoint> points = scene_critical_points(sc);
  std::vector<CriticalPoint> all;
  int per_object[2] = {0, 0};
  for (const SceneCriticalPoint& p : points) {
    all.push_back(p.point);
    ASSERT_TRUE(p.object == 0 || p.object == 1);
    per_object[p.object] += p.point.kind == CriticalKind::kSaddle ? -p.point.multiplicity : p.point.multiplicity;
  }
  EXPECT_EQ(per_object[0], 0);  // the torus
  EXPECT_EQ(per_object[1], 2);  // the sphere
  EXPECT_EQ(count_critical(all).euler_characteristic(), 2);
  for (std::size_t i = 1; i < points.size(); ++i) EXPECT_LE(points[i - 1].point.level, points[i].point.level);
  EXPECT_FALSE(has_4d_surfaces(Scene{}));
  EXPECT_TRUE(scene_critical_points(Scene{}).empty());
}

}  // namespace
}  // namespace s4d
