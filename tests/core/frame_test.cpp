// Frame<D>: rotations stay in SO(D), projection/depth agree with R^T p, planes compose as expected.
#include "core/frame.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

namespace s4d {
namespace {

template <typename T>
class FrameTest : public ::testing::Test {};
template <int D>
struct Dim {
  static constexpr int value = D;
};
using Dims = ::testing::Types<Dim<2>, Dim<3>, Dim<4>>;
TYPED_TEST_SUITE(FrameTest, Dims);

TYPED_TEST(FrameTest, IdentityProjectsToLeadingCoordinates) {
  constexpr int D = TypeParam::value;
  Frame<D> f;
  Vec<D> p = Vec<D>::LinSpaced(1.0, static_cast<double>(D));
  EXPECT_TRUE(f.shadow(p).isApprox(p.template head<D - 1>()));
  EXPECT_DOUBLE_EQ(f.depth(p), static_cast<double>(D));
}

TYPED_TEST(FrameTest, MillionIncrementalRotationsStayOrthonormal) {
  constexpr int D = TypeParam::value;
  Frame<D> f;
  std::mt19937 rng(42);
  const auto planes = all_planes(D);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(planes.size()) - 1);
  std::uniform_real_distribution<double> angle(-0.05, 0.05);
  for (int i = 0; i < 1'000'000; ++i) f.rotate(planes[pick(rng)], angle(rng));
  EXPECT_LT(f.orthonormality_error(), 1e-9);
  EXPECT_NEAR(f.matrix().determinant(), 1.0, 1e-9);
}

TYPED_TEST(FrameTest, RotationPreservesDistancesAndSplitsShadowAndDepth) {
  constexpr int D = TypeParam::value;
  Frame<D> f;
  f.rotate({0, D - 1}, 0.7);
  f.rotate({0, 1}, -1.3);
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  for (int k = 0; k < 100; ++k) {
    Vec<D> p, q;
    for (int i = 0; i < D; ++i) p[i] = g(rng), q[i] = g(rng);
    EXPECT_NEAR((f.to_view(p) - f.to_view(q)).norm(), (p - q).norm(), 1e-12);
    const double s2 = (f.shadow(p)).squaredNorm();
    EXPECT_NEAR(s2 + f.depth(p) * f.depth(p), p.squaredNorm(), 1e-12);
    EXPECT_TRUE(f.to_world(f.to_view(p)).isApprox(p, 1e-12));
  }
}

TYPED_TEST(FrameTest, QuarterTurnMovesFirstAxisIntoDepth) {
  constexpr int D = TypeParam::value;
  Frame<D> f;
  // Turning the view a quarter turn in the (0, D-1) plane: the world's first axis becomes depth.
  f.rotate({0, D - 1}, std::numbers::pi / 2);
  Vec<D> e0 = Vec<D>::Unit(0);
  EXPECT_NEAR(std::abs(f.depth(e0)), 1.0, 1e-12);
  EXPECT_NEAR(f.shadow(e0).norm(), 0.0, 1e-12);
}

TYPED_TEST(FrameTest, FullTurnIsIdentity) {
  constexpr int D = TypeParam::value;
  Frame<D> f;
  for (int i = 0; i < 360; ++i) f.rotate({0, 1}, std::numbers::pi / 180);
  EXPECT_LT((f.matrix() - Mat<D>::Identity()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Frame, DegenerateMatrixFallsBackToIdentity) {
  Mat<4> zero = Mat<4>::Zero();
  Frame<4> f(zero);
  EXPECT_TRUE(f.matrix().isIdentity());
  Mat<4> nan = Mat<4>::Constant(std::numeric_limits<double>::quiet_NaN());
  Frame<4> g(nan);
  EXPECT_TRUE(g.matrix().isIdentity());
}

TEST(Frame, ReflectionIsTurnedIntoRotation) {
  Mat<3> m = Mat<3>::Identity();
  m(2, 2) = -1;
  Frame<3> f(m);
  EXPECT_NEAR(f.matrix().determinant(), 1.0, 1e-12);
}

}  // namespace
}  // namespace s4d
