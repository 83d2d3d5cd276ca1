// Each force law of force_models.hpp against its formula, at D = 2, 3 and 4.
#include "haptics/force_models.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace s4d {
namespace {

template <int D>
Vec<D> ramp(double a, double step) {
  Vec<D> v;
  for (int i = 0; i < D; ++i) v[i] = a + step * i;
  return v;
}

template <typename T>
class ForceModels : public ::testing::Test {};
template <int D>
struct Dim {
  static constexpr int value = D;
};
using Dims = ::testing::Types<Dim<2>, Dim<3>, Dim<4>>;
TYPED_TEST_SUITE(ForceModels, Dims);

TYPED_TEST(ForceModels, StickyForceIsEquationOne) {
  constexpr int D = TypeParam::value;
  const Vec<D> c = ramp<D>(0.01, 0.003), cp = ramp<D>(-0.02, 0.01);
  for (double beta : {0.0, 0.5, 1.0}) {
    const double h = 700;
    const Vec<D> n = cp - c;
    const Vec<D> expected = h * std::pow(n.norm(), 1 + beta) * n.normalized();
    const Vec<D> f = sticky_force<D>(c, cp, h, beta);
    EXPECT_LT((f - expected).norm(), 1e-12 * expected.norm()) << "beta " << beta;
    EXPECT_GT(f.dot(n), 0) << "the force points from C to C'";
  }
  // beta = 0 is Hooke's law; at the projection there is no force.
  EXPECT_LT((sticky_force<D>(c, cp, 300, 0) - 300 * (cp - c)).norm(), 1e-12);
  EXPECT_EQ(sticky_force<D>(c, c, 300, 0), Vec<D>::Zero());
}

TYPED_TEST(ForceModels, StickyForceIsFreeAlongTheTangent) {
  constexpr int D = TypeParam::value;
  // Shadow "plane": the hyperplane x_{D-1} = 0. Sliding the proxy along it leaves the force unchanged.
  Vec<D> normal = Vec<D>::Zero();
  normal[D - 1] = 1;
  Vec<D> c = ramp<D>(0.02, 0.01);
  c[D - 1] = 0.004;
  const Vec<D> f0 = sticky_force<D>(c, project_on_plane<D>(c, Vec<D>::Zero(), normal), 500, 0.3);
  Vec<D> slide = ramp<D>(0.05, -0.02);
  slide[D - 1] = 0;
  const Vec<D> c1 = c + slide;
  const Vec<D> f1 = sticky_force<D>(c1, project_on_plane<D>(c1, Vec<D>::Zero(), normal), 500, 0.3);
  EXPECT_LT((f1 - f0).norm(), 1e-12);
  EXPECT_NEAR(std::abs(f0.dot(slide)), 0, 1e-15) << "no tangential component";
}

TYPED_TEST(ForceModels, DampingIsEquationTwo) {
  constexpr int D = TypeParam::value;
  const Vec<D> v = ramp<D>(-0.3, 0.2);
  EXPECT_EQ(damping_force<D>(v, 2.5), Vec<D>(-2.5 * v));
  Vec<D> u = Vec<D>::Zero();
  u[0] = 1;
  const Vec<D> r = radial_velocity<D>(v, u);
  EXPECT_DOUBLE_EQ(r[0], v[0]);
  for (int i = 1; i < D; ++i) EXPECT_EQ(r[i], 0);
}

TYPED_TEST(ForceModels, RepulsionIsEquationThreeAndBounded) {
  constexpr int D = TypeParam::value;
  Vec<D> u = ramp<D>(1, 0.5).normalized();
  const Vec<D> v = 0.2 * u + 0.05 * ramp<D>(0, 1);  // approaching
  RepulsionParams p;
  p.h = 2e-5;
  p.beta = 0.5;
  p.s_min = 1e-3;
  p.max_force = 100;
  p.range = 0.05;
  const double s = 0.01;
  const Vec<D> expected = -p.h * std::pow(s, -1 - p.beta) * u;
  EXPECT_LT((repulsion_force<D>(s, u, v, p) - expected).norm(), 1e-12 * expected.norm());
  // Moving away or out of range: nothing.
  EXPECT_EQ(repulsion_force<D>(s, u, Vec<D>(-v), p), Vec<D>::Zero());
  EXPECT_EQ(repulsion_force<D>(0.06, u, v, p), Vec<D>::Zero());
  // S -> 0: finite, held at the s_min value, never above max_force.
  const double at_floor = p.h * std::pow(p.s_min, -1 - p.beta);
  for (double tiny : {1e-4, 1e-9, 0.0, -1e-3}) {
    const Vec<D> f = repulsion_force<D>(tiny, u, v, p);
    ASSERT_TRUE(f.allFinite());
    EXPECT_NEAR(f.norm(), std::min(at_floor, p.max_force), 1e-9);
  }
  p.max_force = 0.5;
  EXPECT_NEAR(repulsion_force<D>(1e-6, u, v, p).norm(), 0.5, 1e-12);
  // Monotone: closer means stronger.
  p.max_force = 1e9;
  EXPECT_GT(repulsion_force<D>(0.004, u, v, p).norm(), repulsion_force<D>(0.008, u, v, p).norm());
}

TYPED_TEST(ForceModels, NavigationSpringsTowardThePredictedProjection) {
  constexpr int D = TypeParam::value;
  // Curve image: a straight polyline along axis 0 through the origin.
  std::vector<Vec<D>> line;
  for (int i = -5; i <= 5; ++i) {
    Vec<D> p = Vec<D>::Zero();
    p[0] = 0.01 * i;
    line.push_back(p);
  }
  auto project = [&](const Vec<D>& p) { return project_on_polyline<D>(p, line, false); };
  Vec<D> c = Vec<D>::Zero();
  c[0] = 0.003;
  c[1] = 0.002;  // 2 mm off the line
  Vec<D> v = Vec<D>::Zero();
  v[0] = 0.1;
  v[1] = 0.05;
  const double rate = 1000;
  const DampedSpring spring{400, 2};
  // C_p = C + V/R = (0.0031, 0.00205); its projection (0.0031, 0); spring from C.
  Vec<D> cp = Vec<D>::Zero();
  cp[0] = 0.0031;
  const Vec<D> d = cp - c;
  const Vec<D> expected = spring.k * d - spring.b * v.dot(d.normalized()) * d.normalized();
  const Vec<D> f = navigation_force<D>(c, v, rate, project, spring);
  EXPECT_LT((f - expected).norm(), 1e-12);
  EXPECT_LT(f[1], 0) << "pulled back onto the image";
  // On the image and moving along it, the spring to the point predicted ahead pushes forward (K/R) V
  // and the damper resists B V: with B = K/R the glide along the image is exactly force-free.
  Vec<D> on = Vec<D>::Zero();
  on[0] = 0.002;
  Vec<D> along = Vec<D>::Zero();
  along[0] = 0.1;
  EXPECT_LT(
      (navigation_force<D>(on, along, rate, project, spring) - (spring.k / rate - spring.b) * along).norm(),
      1e-12);
  EXPECT_LT(navigation_force<D>(on, along, rate, project, DampedSpring{400, 0.4}).norm(), 1e-12);
}

TYPED_TEST(ForceModels, RubberBandAndCouplingAreActionReaction) {
  constexpr int D = TypeParam::value;
  const Vec<D> p = ramp<D>(0.01, 0.01), x = ramp<D>(-0.02, 0.005);
  const Vec<D> vp = ramp<D>(0.1, -0.05), vx = ramp<D>(-0.2, 0.03);
  const DampedSpring s{150, 0.7};
  const auto band = rubber_band_force<D>(p, vp, x, vx, s);
  const Vec<D> expected = s.k * (x - p) + s.b * (vx - vp);
  EXPECT_LT((band.on_a - expected).norm(), 1e-12);
  EXPECT_EQ(band.on_b, Vec<D>(-band.on_a));
  const auto vc = virtual_coupling_force<D>(p, vp, x, vx, s);
  EXPECT_EQ(vc.on_a, band.on_a);
  // Dissipative: for zero spring, the damper's power on the pair is -b |dv|^2 <= 0.
  const auto damper = rubber_band_force<D>(p, vp, x, vx, {0, s.b});
  EXPECT_NEAR(damper.on_a.dot(vp) + damper.on_b.dot(vx), -s.b * (vx - vp).squaredNorm(), 1e-12);
}

TYPED_TEST(ForceModels, PolylineProjectionMatchesBruteForce) {
  constexpr int D = TypeParam::value;
  std::vector<Vec<D>> pts;
  for (int i = 0; i < 7; ++i) pts.push_back(ramp<D>(std::cos(i * 0.9), std::sin(i * 1.3) * 0.5));
  const Vec<D> q = ramp<D>(0.3, -0.1);
  for (bool closed : {false, true}) {
    const Vec<D> got = project_on_polyline<D>(q, pts, closed);
    double best = 1e300;
    const int segs = closed ? 7 : 6;
    for (int i = 0; i < segs; ++i)
      for (int k = 0; k <= 20000; ++k) {
        const double t = k / 20000.0;
        best = std::min(best, (q - (pts[i] + t * (pts[(i + 1) % 7] - pts[i]))).norm());
      }
    EXPECT_NEAR((q - got).norm(), best, 1e-6);
  }
}

}  // namespace
}  // namespace s4d
