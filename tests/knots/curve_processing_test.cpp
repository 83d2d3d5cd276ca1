// Curve processing keeps the knot: resampling, relaxation, depth smoothing and crossing flips;
// Dynadraw smooths strokes in any dimension.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "knots/braid_closure.hpp"
#include "knots/depth_edit.hpp"
#include "knots/dynadraw.hpp"
#include "knots/knot_identify.hpp"
#include "knots/relax.hpp"
#include "knots/resample.hpp"
#include "shape/knot_curves.hpp"

namespace s4d {
namespace {

// The unknot drawn messily: a closed braid w (s1 s2 s3) w^-1 on 4 strands.
Curve<3> scrambled_unknot(unsigned seed, int length, int samples = 5) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> g(1, 3), s(0, 1);
  std::vector<int> w;
  for (int i = 0; i < length; ++i) w.push_back(s(rng) ? g(rng) : -g(rng));
  std::vector<int> word = w;
  for (int x : {1, 2, 3}) word.push_back(x);
  for (auto it = w.rbegin(); it != w.rend(); ++it) word.push_back(-*it);
  return braid_closure(4, word, samples);
}

int fewest_crossings(const Curve<3>& c) {
  // Down each principal axis, as identify_knot chooses its view.
  return identify_knot(c).invariants.diagram_crossings;
}

// Fewest crossings over 300 view directions spread over the sphere (a Fibonacci lattice).
int fewest_crossings_any_view(const Curve<3>& c) {
  int best = fewest_crossings(c);
  const double golden = 3.0 - std::sqrt(5.0);
  for (int i = 0; i < 300 && best > 0; ++i) {
    const double z = 1 - (i + 0.5) / 150.0, r = std::sqrt(std::max(0.0, 1 - z * z));
    const Vec3 dir(r * std::cos(golden * M_PI * i), r * std::sin(golden * M_PI * i), z);
    Mat<3> m;
    m.col(2) = dir;
    m.col(0) = dir.unitOrthogonal();
    m.col(1) = dir.cross(m.col(0));
    best = std::min(best, diagram_from_curve(c, Frame<3>(m)).crossing_count());
  }
  return best;
}

TEST(Resample, EqualSegmentsAndTheSameKnot) {
  const Curve<3> k = torus_knot(3, 4, 500);
  ResampleStats st;
  const Curve<3> r = resample_curve_to_count(k, 200, &st);
  EXPECT_EQ(identify_knot(r).name, identify_knot(k).name);
  const auto& pl = r.components[0];
  double lo = INFINITY, hi = 0;
  for (std::size_t i = 0; i < pl.segment_count(); ++i) {
    const double l = (pl.seg_b(i) - pl.seg_a(i)).norm();
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  if (st.refused == 0) {
    EXPECT_EQ(pl.points.size(), 200u);
    EXPECT_LT(hi / lo, 1.3);  // chords of equal arcs of a smooth curve
  }
}

TEST(Resample, CoarseResamplingRefusesPassThroughs) {
  // Very coarse targets would cut corners through other strands; every refusal keeps the knot.
  for (unsigned seed : {1u, 2u, 3u}) {
    const Curve<3> k = scrambled_unknot(seed, 6);
    for (int n : {24, 40, 80}) {
      ResampleStats st;
      const Curve<3> r = resample_curve_to_count(k, n, &st);
      EXPECT_EQ(identify_knot(r).kind, KnotKind::kUnknot) << seed << " " << n;
    }
  }
  const Curve<3> t = braid_closure(2, {1, 1, 1}, 9);
  for (int n : {9, 12, 20}) {
    ResampleStats st;
    const Curve<3> r = resample_curve_to_count(t, n, &st);
    EXPECT_EQ(identify_knot(r).name, identify_knot(t).name) << n << " refused " << st.refused;
  }
}

TEST(Relax, ScrambledUnknotsEndWithNoCrossingsInSomeView) {
  for (unsigned seed : {11u, 12u}) {
    const Curve<3> k = resample_curve_to_count(scrambled_unknot(seed, 5), 150);
    ASSERT_GT(fewest_crossings(k), 0);
    RelaxModel m;
    RelaxData d;
    relax_setup(k, m, d);
    for (int i = 0; i < 10000 && fewest_crossings_any_view(relax_curve(m, d)) > 0; i += 500)
      for (int j = 0; j < 500; ++j) relax_step(m, d);
    const Curve<3> r = relax_curve(m, d);
    EXPECT_EQ(fewest_crossings_any_view(r), 0) << "seed " << seed;
    EXPECT_EQ(identify_knot(r).kind, KnotKind::kUnknot);
  }
}

TEST(Relax, TrefoilStaysATrefoilAndNeverTouches) {
  const Curve<3> k = resample_curve_to_count(braid_closure(2, {1, 1, 1}, 9), 120);
  const std::string name = identify_knot(k).name;
  RelaxModel m;
  RelaxData d;
  relax_setup(k, m, d);
  for (int i = 0; i < 1500; ++i) {
    relax_step(m, d);
    ASSERT_GT(d.min_gap, 0.0) << "step " << i;
  }
  EXPECT_EQ(identify_knot(relax_curve(m, d)).name, name);
  // Relaxed towards a symmetric trefoil: its diagram shows the minimal 3 crossings.
  EXPECT_EQ(fewest_crossings(relax_curve(m, d)), 3);
}

TEST(DepthEdit, FlipChangesExactlyOneCrossing) {
  const Curve<3> k = braid_closure(2, {1, 1, 1}, 9);
  const KnotDiagram before = diagram_from_curve(k, Frame<3>());
  const Curve<3> f = flip_crossing(k, Frame<3>(), 2);
  const KnotDiagram after = diagram_from_curve(f, Frame<3>());
  EXPECT_EQ(after.gauss_code(), before.with_crossing_changed(1).gauss_code());
  EXPECT_EQ(identify_knot(f).kind, KnotKind::kUnknot);
  EXPECT_THROW(flip_crossing(k, Frame<3>(), 4), Error);
}

TEST(DepthEdit, SmoothingKeepsTheDiagramAndFlattensDepth) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 0.15);
  const Curve<3> k = braid_closure(3, {1, -2, 1, -2}, 9);  // figure-eight
  auto roughness = [](const Curve<3>& c) {
    double r = 0;
    const auto& p = c.components[0].points;
    for (std::size_t i = 0; i < p.size(); ++i)
      r += std::abs(p[(i + 1) % p.size()].z() - 2 * p[i].z() + p[(i + p.size() - 1) % p.size()].z());
    return r;
  };
  Curve<3> noisy = k;
  for (auto& p : noisy.components[0].points) p.z() += noise(rng) * 0.2;
  const std::string noisy_code = diagram_from_curve(noisy, Frame<3>()).gauss_code();
  const Curve<3> s = smooth_depth(noisy, Frame<3>());
  EXPECT_EQ(diagram_from_curve(s, Frame<3>()).gauss_code(), noisy_code);
  EXPECT_LT(roughness(s), 0.5 * roughness(noisy));
  for (std::size_t i = 0; i < s.components[0].points.size(); ++i)  // shadows untouched
    EXPECT_LT((s.components[0].points[i].head<2>() - noisy.components[0].points[i].head<2>()).norm(), 1e-12);
}

template <int D>
void check_dynadraw() {
  // A jittery straight stroke: the pen's path is much smoother and still ends at the target.
  std::mt19937 rng(9);
  std::normal_distribution<double> jitter(0, 0.02);
  std::vector<Vec<D>> samples;
  for (int i = 0; i <= 200; ++i) {
    Vec<D> p = Vec<D>::Zero();
    p[0] = i / 200.0;
    for (int k = 0; k < D; ++k) p[k] += jitter(rng);
    samples.push_back(p);
  }
  const auto pen = dynadraw_stroke<D>(samples, 1.0 / 120, {}, 400);
  auto wiggle = [](const std::vector<Vec<D>>& s, std::size_t n) {
    double w = 0;
    for (std::size_t i = 1; i + 1 < n; ++i) w += (s[i + 1] - 2 * s[i] + s[i - 1]).norm();
    return w;
  };
  EXPECT_LT(wiggle(pen, samples.size()), 0.2 * wiggle(samples, samples.size()));
  EXPECT_LT((pen.back() - samples.back()).norm(), 1e-3);
  Dynadraw<D> d;
  d.reset(Vec<D>::Zero());
  Vec<D> nan = Vec<D>::Constant(std::nan(""));
  EXPECT_TRUE(d.step(nan, 0.01).allFinite());
}

TEST(Dynadraw, SmoothsStrokesIn2D3D4D) {
  check_dynadraw<2>();
  check_dynadraw<3>();
  check_dynadraw<4>();
}

}  // namespace
}  // namespace s4d
