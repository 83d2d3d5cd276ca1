// The spring kernels: the portable one against the paper's Eq. 1 written out, and the four-wide
// AVX one bit for bit against the portable one (coincident and non-finite ends, shared vertices,
// a tail that is not a multiple of four).
#include "physics/spring_forces.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>

#include "physics/model.hpp"
#include "physics/test_worlds.hpp"

namespace s4d {
namespace {

struct SpringSet {
  std::vector<Spring> springs;
  std::vector<Vec4> x, v;
};

// Random springs on few vertices, so that springs of one group of four share vertices.
SpringSet random_springs(int count, int vertices, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> pick(0, vertices - 1);
  SpringSet s;
  for (int i = 0; i < vertices; ++i) {
    s.x.emplace_back(u(rng), u(rng), u(rng), u(rng));
    s.v.emplace_back(u(rng), u(rng), u(rng), u(rng));
  }
  for (int i = 0; i < count; ++i) {
    Spring sp;
    sp.a = pick(rng);
    do sp.b = pick(rng);
    while (sp.b == sp.a);
    sp.rest = 0.5 + 0.5 * u(rng);
    sp.k = 100 * (1.5 + u(rng));
    s.springs.push_back(sp);
  }
  return s;
}

bool bit_equal(const std::vector<Vec4>& a, const std::vector<Vec4>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec4)) == 0;
}

TEST(SpringForces, PortableKernelIsHookeWithDampingAlongTheSpring) {
  const SpringSet s = random_springs(37, 9, 1);
  const double kd = 0.3;
  std::vector<Vec4> f(s.x.size(), Vec4::Zero()), ref(s.x.size(), Vec4::Zero());
  spring_detail::linear_springs_portable(s.springs, kd, s.x, s.v, f);
  for (const Spring& sp : s.springs) {
    const Vec4 d = s.x[sp.b] - s.x[sp.a];
    const Vec4 n = d / d.norm();
    const double mag = sp.k * (d.norm() - sp.rest) + kd * (s.v[sp.b] - s.v[sp.a]).dot(n);
    ref[sp.a] += mag * n;
    ref[sp.b] -= mag * n;
  }
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_LT((f[i] - ref[i]).norm(), 1e-10 * (1 + ref[i].norm()));
}

TEST(SpringForces, AvxKernelEqualsPortableBitForBit) {
  std::vector<Vec4> probe(1, Vec4::Zero());
  if (!spring_detail::linear_springs_avx({}, {}, 0, probe, probe, probe)) GTEST_SKIP() << "no AVX here";
  for (unsigned seed = 0; seed < 20; ++seed) {
    SpringSet s = random_springs(4 * 25 + static_cast<int>(seed % 4), 11, seed);
    // Coincident ends in one group, a non-finite position in another.
    s.x[s.springs[5].b] = s.x[s.springs[5].a];
    if (seed % 2) s.x[s.springs[13].a][2] = std::numeric_limits<double>::quiet_NaN();
    std::vector<Vec4> portable(s.x.size(), Vec4::Constant(0.25)), wide = portable;
    spring_detail::linear_springs_portable(s.springs, 0.02, s.x, s.v, portable);
    const std::vector<SpringGroup4> groups = pack_spring_groups(s.springs);
    ASSERT_TRUE(spring_detail::linear_springs_avx(s.springs, groups, 0.02, s.x, s.v, wide));
    EXPECT_TRUE(bit_equal(portable, wide)) << "seed " << seed;
  }
}

// A grid cloth's springs, one direction at a time: most groups are strided (read from their
// first ends alone), and they give the portable kernel's bits too.
TEST(SpringForces, AvxKernelEqualsPortableBitForBitOnAGridsStridedGroups) {
  std::vector<Vec4> probe(1, Vec4::Zero());
  if (!spring_detail::linear_springs_avx({}, {}, 0, probe, probe, probe)) GTEST_SKIP() << "no AVX here";
  ModelBuilder<4> b{PhysicsParams<4>{}};
  b.add_body(test::flat_cloth<4>(13, 0.5));
  const Model<4> m = b.build();
  int strided = 0;
  for (const SpringGroup4& g : m.spring_groups) strided += g.strided;
  ASSERT_EQ(m.spring_groups.size(), m.springs.size() / 4);
  EXPECT_GT(strided, static_cast<int>(0.8 * static_cast<double>(m.spring_groups.size())));
  EXPECT_LT(strided, static_cast<int>(m.spring_groups.size()));  // runs end mid-group too
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec4> x = m.initial, v(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] += 0.01 * Vec4(u(rng), u(rng), u(rng), u(rng));
    v[i] = Vec4(u(rng), u(rng), u(rng), u(rng));
  }
  std::vector<Vec4> portable(x.size(), Vec4::Constant(0.25)), wide = portable;
  spring_detail::linear_springs_portable(m.springs, 0.02, x, v, portable);
  ASSERT_TRUE(spring_detail::linear_springs_avx(m.springs, m.spring_groups, 0.02, x, v, wide));
  EXPECT_TRUE(bit_equal(portable, wide));
  // Against the formula as well: the bits above are no use if both are wrong the same way.
  std::vector<Vec4> reference(x.size(), Vec4::Constant(0.25));
  for (const Spring& sp : m.springs) {
    const Vec4 d = x[sp.b] - x[sp.a];
    const double len = d.norm();
    const Vec4 f = (sp.k * (len - sp.rest) + 0.02 * (v[sp.b] - v[sp.a]).dot(d / len)) * d / len;
    reference[sp.a] += f;
    reference[sp.b] -= f;
  }
  for (std::size_t i = 0; i < x.size(); ++i)
    EXPECT_LT((wide[i] - reference[i]).norm(), 1e-9 * (1 + reference[i].norm())) << i;
}

}  // namespace
}  // namespace s4d
