// The vertex pass of a substep: symplectic Euler, pins, the next substep's forces, the checks and
// the motion clamp, against the formulas; and its AVX path against the portable one, bit for bit.
#include "physics/vertex_pass.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace s4d {
namespace {

struct State {
  std::vector<Vec4> x, v, force, x0, target, f_ext;
  std::vector<std::uint8_t> pinned;
  std::vector<double> mass, inv_mass;
  VertexArrays<4> arrays() {
    return {x, v, force, x0, target, f_ext, pinned, mass, inv_mass};
  }
};

State random_state(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  auto vec = [&](double s) { return Vec4(s * u(rng), s * u(rng), s * u(rng), s * u(rng)); };
  State s;
  for (int i = 0; i < n; ++i) {
    s.x0.push_back(vec(1));
    s.x.push_back(s.x0.back() + vec(1e-3));
    s.v.push_back(vec(0.5));
    s.force.push_back(vec(2));
    s.target.push_back(s.x0.back() + vec(1e-3));
    s.f_ext.push_back(i % 5 == 0 ? vec(1) : Vec4::Zero());
    s.pinned.push_back(i % 7 == 3);
    s.mass.push_back(1e-3 * (1.5 + u(rng)));
    s.inv_mass.push_back(1 / s.mass.back());
  }
  return s;
}

VertexPassParams<4> params(bool last) {
  VertexPassParams<4> p;
  p.h = 5e-4;
  p.dt = 1e-3;
  p.along = last ? 1.0 : 0.5;
  p.last = last;
  p.limit = 2e-3;
  p.gravity = Vec4(0, -9.81, 0, 0.5);
  p.damping = 0.02;
  return p;
}

bool bit_equal(const std::vector<Vec4>& a, const std::vector<Vec4>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec4)) == 0;
}

TEST(VertexPass, MiddleSubstepIsSymplecticEulerThenTheNextForces) {
  State s = random_state(50, 1);
  const State before = s;
  const VertexPassParams<4> p = params(false);
  VertexPassResult<4> r;
  vertex_pass<4>(s.arrays(), p, r);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    Vec4 v, x;
    if (before.pinned[i]) {
      x = before.x0[i] + 0.5 * (before.target[i] - before.x0[i]);
      v = (before.target[i] - before.x0[i]) / p.dt;
    } else {
      v = before.v[i] + p.h * before.force[i] / before.mass[i];
      x = before.x[i] + p.h * v;
    }
    EXPECT_LT((s.v[i] - v).norm(), 1e-12 * (1 + v.norm())) << i;
    EXPECT_LT((s.x[i] - x).norm(), 1e-15) << i;
    const Vec4 f = before.mass[i] * p.gravity + before.f_ext[i] - p.damping * v;
    EXPECT_LT((s.force[i] - f).norm(), 1e-12) << i;
  }
  EXPECT_EQ(r.clamps, 0);  // the middle substep neither clamps nor checks
}

TEST(VertexPass, StartStepSavesThePositionsAndStartsTheForces) {
  State s = random_state(50, 4);
  const State before = s;
  const VertexPassParams<4> p = params(false);
  start_step<4>(s.arrays(), s.x0, p.gravity, p.damping);
  EXPECT_TRUE(bit_equal(s.x0, before.x));
  EXPECT_TRUE(bit_equal(s.x, before.x));
  EXPECT_TRUE(bit_equal(s.v, before.v));
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const Vec4 f = before.mass[i] * p.gravity + before.f_ext[i] - p.damping * before.v[i];
    EXPECT_LT((s.force[i] - f).norm(), 1e-12) << i;
  }
}

TEST(VertexPass, LastSubstepClampsReportsTheFastestAndFlagsNonFiniteValues) {
  State s = random_state(40, 2);
  s.force[4] = Vec4(1e3, 0, 0, 0);  // a vertex pushed far past the limit
  s.pinned[4] = 0;
  const VertexPassParams<4> p = params(true);
  VertexPassResult<4> r;
  vertex_pass<4>(s.arrays(), p, r);
  EXPECT_GE(r.clamps, 1);
  double fastest2 = 0;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    EXPECT_LE((s.x[i] - s.x0[i]).norm(), p.limit * (1 + 1e-12)) << i;
    if (!s.pinned[i]) fastest2 = std::max(fastest2, s.v[i].squaredNorm());
  }
  EXPECT_TRUE((r.nonfinite.array() == 0.0).all());
  // The clamp scales the clamped vertex's velocity too; the fastest was measured before it.
  EXPECT_GE(r.fastest2, fastest2);

  State bad = random_state(40, 3);
  bad.v[7][1] = std::numeric_limits<double>::infinity();
  VertexPassResult<4> rb;
  vertex_pass<4>(bad.arrays(), p, rb);
  EXPECT_FALSE((rb.nonfinite.array() == 0.0).all());
}

TEST(VertexPass, AvxPathEqualsPortableBitForBit) {
  {
    State probe = random_state(1, 0);
    VertexPassResult<4> r;
    if (!vertex_detail::pass_avx(probe.arrays(), params(false), r)) GTEST_SKIP() << "no AVX here";
  }
  for (unsigned seed = 0; seed < 20; ++seed)
    for (bool last : {false, true}) {
      State a = random_state(61, seed);
      a.force[seed % 61] *= 1e3;  // one clamped vertex
      if (seed % 3 == 0) a.v[5][2] = std::numeric_limits<double>::quiet_NaN();
      State b = a;
      VertexPassResult<4> ra, rb;
      ra.fastest2 = rb.fastest2 = 0.125;
      vertex_detail::pass_portable(a.arrays(), params(last), ra);
      ASSERT_TRUE(vertex_detail::pass_avx(b.arrays(), params(last), rb));
      EXPECT_TRUE(bit_equal(a.x, b.x)) << seed;
      EXPECT_TRUE(bit_equal(a.v, b.v)) << seed;
      EXPECT_TRUE(bit_equal(a.force, b.force)) << seed;
      EXPECT_EQ(std::memcmp(&ra.fastest2, &rb.fastest2, sizeof(double)), 0) << seed;
      EXPECT_EQ(ra.clamps, rb.clamps) << seed;
      EXPECT_EQ((ra.nonfinite.array() == 0.0).all(), (rb.nonfinite.array() == 0.0).all()) << seed;
    }
}

}  // namespace
}  // namespace s4d
