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

// Perspective: the shadow from an eye at w = d, lifted back exactly; far away it is the orthographic one.
TYPED_TEST(FrameTest, PerspectiveLiftUndoesTheShadowAtEveryDepth) {
  constexpr int D = TypeParam::value;
  Frame<D> f;
  f.rotate({0, D - 1}, 0.4);
  f.rotate({0, 1}, 0.9);
  f.set_perspective(3.0);
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0, 2);
  for (int k = 0; k < 200; ++k) {
    Vec<D> p;
    for (int i = 0; i < D; ++i) p[i] = g(rng);
    const Vec<D> q = f.to_view(p);
    const Vec<D - 1> s = f.shadow(p);
    ASSERT_TRUE(s.allFinite());
    if (q[D - 1] < 3.0 * (1 - Frame<D>::kNearestEye)) {  // in front of the eye: the exact central projection
      EXPECT_TRUE(s.isApprox(q.template head<D - 1>() * 3.0 / (3.0 - q[D - 1]), 1e-12));
    }
    // The point at that depth under that shadow is the point itself (clamped ones too).
    EXPECT_TRUE(f.to_world(f.lift(s, q[D - 1])).isApprox(p, 1e-12)) << p.transpose();
  }
  // The hyperplane w = 0 keeps its size; nearer is larger, farther smaller.
  const Vec<D - 1> s = Vec<D - 1>::Ones();
  EXPECT_TRUE(Frame<D>().lift(s, 0).template head<D - 1>().isApprox(s));
  EXPECT_DOUBLE_EQ(f.magnification(0), 1.0);
  EXPECT_DOUBLE_EQ(f.magnification(1.5), 2.0);
  EXPECT_DOUBLE_EQ(f.magnification(-3.0), 0.5);
}

TYPED_TEST(FrameTest, PerspectiveAtAndBehindTheEyeIsClampedNeverInfinite) {
  constexpr int D = TypeParam::value;
  Frame<D> f;
  f.set_perspective(2.0);
  for (double w : {2.0, 2.0 - 1e-300, 5.0, 1e300, HUGE_VAL, std::nan("")}) {
    Vec<D> q = Vec<D>::Ones();
    q[D - 1] = w;
    const Vec<D - 1> s = f.project(q);
    EXPECT_TRUE(s.allFinite()) << w;
    EXPECT_DOUBLE_EQ(s[0], 1.0 / Frame<D>::kNearestEye) << w;
  }
  EXPECT_TRUE(std::isfinite(f.depth_at(std::array<double, 2>{0.5, 0.5}, std::array<double, 2>{5.0, 9.0})));
}

TYPED_TEST(FrameTest, PerspectiveTendsToTheOrthographicShadow) {
  constexpr int D = TypeParam::value;
  Frame<D> ortho;
  ortho.rotate({0, D - 1}, 0.3);
  Vec<D> p = Vec<D>::LinSpaced(-1.0, 1.5);
  double last = HUGE_VAL;
  for (double d : {10.0, 1e2, 1e3, 1e4, 1e5, 1e6}) {
    Frame<D> f = ortho;
    f.set_perspective(d);
    const double gap = (f.shadow(p) - ortho.shadow(p)).norm();
    EXPECT_LT(gap, last);  // monotonely closer
    EXPECT_LT(gap, 10.0 / d);  // |q| |w| / (d - w), about 1/d
    last = gap;
  }
  EXPECT_LT(last, 1e-5);
  // Orthographic is the default and exactly the leading view coordinates.
  EXPECT_FALSE(ortho.is_perspective());
  EXPECT_EQ(ortho.shadow(p), Vec<D - 1>(ortho.to_view(p).template head<D - 1>()));
}

TYPED_TEST(FrameTest, PerspectiveDepthIsInterpolatedCorrectlyAlongAShadowSegment) {
  constexpr int D = TypeParam::value;
  Frame<D> f;
  f.rotate({0, D - 1}, 0.8);
  f.set_perspective(4.0);
  Vec<D> a = Vec<D>::Constant(0.3), b = Vec<D>::LinSpaced(-1.0, 1.2);
  for (double u : {0.0, 0.25, 0.5, 0.9, 1.0}) {
    const Vec<D> p = (1 - u) * a + u * b;  // a point of the 4D segment
    // Where its shadow lies along the shadow segment, and the depth read from there.
    const Vec<D - 1> sa = f.shadow(a), sb = f.shadow(b), sp = f.shadow(p);
    const double t = (sp - sa).dot(sb - sa) / (sb - sa).squaredNorm();
    EXPECT_NEAR((sa + t * (sb - sa) - sp).norm(), 0, 1e-12);  // the shadow of a segment is a segment
    EXPECT_NEAR(f.depth_at(std::array<double, 2>{1 - t, t}, std::array<double, 2>{f.depth(a), f.depth(b)}),
                f.depth(p), 1e-12);
  }
}

TEST(FramePerspective, BadDistancesAreRefusedWithASentence) {
  Frame<4> f;
  for (double d : {0.0, -1.0, std::nan(""), HUGE_VAL, 1e7, 1e308}) {
    try {
      f.set_perspective(d);
      ADD_FAILURE() << d << " was taken";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("perspective distance"), std::string::npos) << e.what();
      EXPECT_LT(std::string(e.what()).size(), 160u) << "a sentence, not 300 digits: " << e.what();
    }
    EXPECT_FALSE(f.is_perspective());
  }
  f.set_perspective(5);
  EXPECT_DOUBLE_EQ(f.perspective(), 5);
  f.rotate({0, 3}, 0.2);  // a turn keeps the eye
  EXPECT_DOUBLE_EQ(f.perspective(), 5);
  f.set_orthographic();
  EXPECT_FALSE(f.is_perspective());
}

}  // namespace
}  // namespace s4d
