// Broad phase (BVH) + narrow phase over meshes and curves equal the all-pairs brute force.
#include "proximity/mesh_proximity.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <set>

#include "core/cpu.hpp"
#include "core/error.hpp"
#include "proximity/reference.hpp"

namespace s4d {
namespace {

using test::random_vec;

// A random mesh: vertices in a cube, cells made of a vertex and K-1 of its near neighbours (so
// cells share vertices as in a real mesh), plus a few random long cells.
template <int D, int K>
std::pair<std::vector<Vec<D>>, std::vector<Cell<K>>> random_mesh(std::mt19937& rng, int nv,
                                                                  int nc) {
  std::vector<Vec<D>> x(nv);
  for (auto& v : x) v = random_vec<D>(rng);
  std::uniform_int_distribution<int> pick(0, nv - 1);
  std::vector<Cell<K>> cells;
  while (static_cast<int>(cells.size()) < nc) {
    Cell<K> c;
    c[0] = pick(rng);
    for (int k = 1; k < K; ++k) {
      // nearest of a few random candidates, so cells are small and neighbours share vertices
      int best = pick(rng);
      for (int tries = 0; tries < 6; ++tries) {
        const int v = pick(rng);
        if ((x[v] - x[c[0]]).norm() < (x[best] - x[c[0]]).norm()) best = v;
      }
      c[k] = best;
    }
    bool ok = true;
    for (int i = 0; i < K; ++i)
      for (int j = i + 1; j < K; ++j) ok = ok && c[i] != c[j];
    if (ok) cells.push_back(c);
  }
  return {x, cells};
}

template <int D, int K>
void check_self(unsigned seed) {
  std::mt19937 rng(seed);
  auto [x, cells] = random_mesh<D, K>(rng, 160, 260);
  SelfProximity<D, K> q(cells);
  std::vector<ProximityPair<D>> got;
  for (int round = 0; round < 3; ++round) {  // moving vertices: exercises refit (and rebuild)
    const double delta = 0.05 + 0.05 * round;
    q.pairs_within(x, delta, got);
    std::vector<std::pair<int, int>> want;
    for (int a = 0; a < static_cast<int>(cells.size()); ++a)
      for (int b = a + 1; b < static_cast<int>(cells.size()); ++b) {
        if (share_vertex<K, K>(cells[a], cells[b])) continue;
        Simplex<D, K> sa, sb;
        for (int i = 0; i < K; ++i) sa[i] = x[cells[a][i]], sb[i] = x[cells[b][i]];
        if (closest_points<D, K, K>(sa, sb).distance <= delta) want.push_back({a, b});
      }
    ASSERT_EQ(got.size(), want.size()) << "D=" << D << " K=" << K << " round " << round;
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(got[i].a, want[i].first);
      EXPECT_EQ(got[i].b, want[i].second);
    }
    EXPECT_GT(want.size(), 0u);
    for (auto& v : x) v += random_vec<D>(rng, 0.1 * (round + 1));
  }
  // Earliest impact over a step equals the minimum over all pairs.
  std::vector<Vec<D>> x1 = x;
  for (auto& v : x1) v += random_vec<D>(rng, 0.15);
  CcdOptions opt;
  opt.thickness = 0.01;
  const Impact<D> got_i = q.earliest_impact(x, x1, opt);
  double best = 2;
  for (int a = 0; a < static_cast<int>(cells.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(cells.size()); ++b) {
      if (share_vertex<K, K>(cells[a], cells[b])) continue;
      Simplex<D, K> a0, a1, b0, b1;
      for (int i = 0; i < K; ++i) {
        a0[i] = x[cells[a][i]], a1[i] = x1[cells[a][i]];
        b0[i] = x[cells[b][i]], b1[i] = x1[cells[b][i]];
      }
      const auto r = earliest_contact<D, K, K>(a0, a1, b0, b1, opt);
      if (r.hit) best = std::min(best, r.t);
    }
  ASSERT_EQ(got_i.hit, best <= 1);
  if (got_i.hit) {
    EXPECT_DOUBLE_EQ(got_i.t, best);
  }
}

// The distance between cell a of one mesh and cell b of another, straight from the narrow phase.
template <int D, int KA, int KB>
double cell_distance(const std::vector<Vec<D>>& xa, const Cell<KA>& a, const std::vector<Vec<D>>& xb,
                     const Cell<KB>& b) {
  Simplex<D, KA> sa;
  Simplex<D, KB> sb;
  for (int i = 0; i < KA; ++i) sa[i] = xa[a[i]];
  for (int i = 0; i < KB; ++i) sb[i] = xb[b[i]];
  return closest_points<D, KA, KB>(sa, sb).distance;
}

template <int D, int KA, int KB>
void check_pair(unsigned seed) {
  std::mt19937 rng(seed);
  auto [xa, ca] = random_mesh<D, KA>(rng, 120, 150);
  auto [xb, cb] = random_mesh<D, KB>(rng, 120, 150);
  PairProximity<D, KA, KB> q(ca, cb);
  std::vector<ProximityPair<D>> got;
  q.pairs_within(xa, xb, 0.06, got);
  std::vector<std::pair<int, int>> want;
  for (int a = 0; a < static_cast<int>(ca.size()); ++a)
    for (int b = 0; b < static_cast<int>(cb.size()); ++b)
      if (cell_distance<D, KA, KB>(xa, ca[a], xb, cb[b]) <= 0.06) want.push_back({a, b});
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i)
    EXPECT_EQ(std::make_pair(got[i].a, got[i].b), want[i]);
  EXPECT_GT(want.size(), 0u);
}

TEST(MeshProximity, SelfQueriesEqualBruteForceInR2) {
  check_self<2, 2>(1);
  check_self<2, 3>(2);
}
TEST(MeshProximity, SelfQueriesEqualBruteForceInR3) {
  check_self<3, 2>(3);
  check_self<3, 3>(4);
}
TEST(MeshProximity, SelfQueriesEqualBruteForceInR4) {
  check_self<4, 2>(5);
  check_self<4, 3>(6);
}
TEST(MeshProximity, PairQueriesEqualBruteForce) {
  check_pair<3, 3, 3>(7);
  check_pair<4, 3, 3>(8);
  check_pair<4, 2, 3>(9);
  check_pair<4, 3, 2>(10);
  check_pair<2, 2, 2>(11);
}

// The smallest distance against the brute force over every pair, at radii below, near and above
// the true one, and on meshes moved apart until nothing is within the radius.
template <int D, int KA, int KB>
void check_smallest_distance(unsigned seed) {
  std::mt19937 rng(seed);
  auto [xa, ca] = random_mesh<D, KA>(rng, 80, 100);
  auto [xb, cb] = random_mesh<D, KB>(rng, 80, 100);
  PairProximity<D, KA, KB> q(ca, cb);
  for (const double shift : {0.0, 0.3, 1.2, 5.0}) {
    std::vector<Vec<D>> moved = xb;
    for (Vec<D>& v : moved) v[0] += shift;
    double brute = std::numeric_limits<double>::infinity();
    for (const Cell<KA>& a : ca)
      for (const Cell<KB>& b : cb) brute = std::min(brute, cell_distance<D, KA, KB>(xa, a, moved, b));
    for (const double up_to : {0.5 * brute, brute, 1.01 * brute, 3 * brute + 0.01, 10.0}) {
      const double got = q.smallest_distance(xa, moved, up_to);
      if (brute <= up_to)
        EXPECT_DOUBLE_EQ(got, brute) << "shift " << shift << ", up to " << up_to;
      else
        EXPECT_EQ(got, std::numeric_limits<double>::infinity()) << "shift " << shift << ", up to " << up_to;
    }
  }
}

TEST(MeshProximity, SmallestDistanceEqualsBruteForceWithinTheRadiusAndIsInfiniteBeyond) {
  check_smallest_distance<4, 3, 3>(21);
  check_smallest_distance<4, 2, 3>(22);
  check_smallest_distance<3, 3, 3>(23);
  check_smallest_distance<2, 2, 2>(24);
}

TEST(MeshProximity, BvhSelfPairsEqualAllOverlappingBoxes) {
  std::mt19937 rng(12);
  for (int n : {0, 1, 3, 4, 5, 17, 300}) {
    std::vector<Box<4>> boxes(n);
    for (auto& b : boxes) {
      const Vec4 c = random_vec<4>(rng);
      b.add(c);
      b.add(c + random_vec<4>(rng, 0.2));
    }
    Bvh<4> bvh;
    bvh.build(boxes);
    std::set<std::pair<int, int>> got;
    bvh.self_pairs(0.01, [&](int i, int j) {
      EXPECT_TRUE(got.insert({std::min(i, j), std::max(i, j)}).second) << "pair reported twice";
    });
    std::set<std::pair<int, int>> want;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (boxes[i].near(boxes[j], 0.01)) want.insert({i, j});
    EXPECT_EQ(got, want) << n << " boxes";
  }
}

// Temporal coherence: one query object followed along a random motion (small drifts that reuse
// its list, jumps that force rebuilds, a NaN frame and the recovery after it, thresholds that go
// up and down) answers every query exactly as a fresh, coherence-free one does.
template <int D, int K>
void check_coherent_sequence(unsigned seed) {
  std::mt19937 rng(seed);
  auto [x, cells] = random_mesh<D, K>(rng, 150, 240);
  SelfProximity<D, K> coherent(cells);
  std::vector<ProximityPair<D>> got, want;
  std::uniform_real_distribution<double> unit(0, 1);
  int reused = 0;
  for (int step = 0; step < 60; ++step) {
    std::vector<Vec<D>> next = x;
    const double size = step % 17 == 16 ? 0.3 : 0.004;  // mostly drifts, sometimes a jump
    for (auto& v : next) v += random_vec<D>(rng, size);
    if (step == 30) next[cells[0][0]][0] = std::numeric_limits<double>::quiet_NaN();
    if (step == 31) next[cells[0][0]] = random_vec<D>(rng);  // and back
    const double delta = 0.04 + 0.03 * unit(rng);
    const long long runs = coherent.broad_phase_runs();
    coherent.pairs_within(next, delta, got);
    if (coherent.broad_phase_runs() == runs) ++reused;
    SelfProximity<D, K> fresh(cells);
    fresh.set_temporal_coherence(false);
    fresh.pairs_within(next, delta, want);
    ASSERT_EQ(got.size(), want.size()) << "step " << step;
    for (std::size_t i = 0; i < want.size(); ++i) {
      ASSERT_EQ(std::make_pair(got[i].a, got[i].b), std::make_pair(want[i].a, want[i].b));
      // Both exact; a warm-started answer may differ from the enumeration in the last bits.
      EXPECT_NEAR(got[i].closest.distance, want[i].closest.distance, 1e-9);
    }
    // A step from x to next: earliest impact, and step candidates cover every pair that hits.
    {
      CcdOptions opt;
      opt.thickness = 0.02;
      const Impact<D> gi = coherent.earliest_impact(x, next, opt);
      const Impact<D> wi = fresh.earliest_impact(x, next, opt);
      ASSERT_EQ(gi.hit, wi.hit) << "step " << step;
      if (gi.hit) {
        EXPECT_EQ(gi.t, wi.t);
        EXPECT_EQ(std::make_pair(gi.a, gi.b), std::make_pair(wi.a, wi.b));
      }
      if (step % 3 != 0 && step < 29) {  // the all-pairs reference below is slow: every third step
        x = next;
        continue;
      }
      std::set<std::pair<int, int>> offered;
      coherent.step_candidates(x, next, opt.thickness, [&](int a, int b) { offered.insert({a, b}); });
      for (int a = 0; a < static_cast<int>(cells.size()); ++a)
        for (int b = a + 1; b < static_cast<int>(cells.size()); ++b) {
          if (share_vertex<K, K>(cells[a], cells[b])) continue;
          Simplex<D, K> a0, a1, b0, b1;
          for (int i = 0; i < K; ++i) {
            a0[i] = x[cells[a][i]], a1[i] = next[cells[a][i]];
            b0[i] = x[cells[b][i]], b1[i] = next[cells[b][i]];
          }
          if (earliest_contact<D, K, K>(a0, a1, b0, b1, opt).hit) {
            EXPECT_TRUE(offered.count({a, b})) << "step " << step << " missed " << a << "," << b;
          }
        }
    }
    x = next;
  }
  EXPECT_GT(reused, 20) << "small drifts should reuse the list";
}

TEST(MeshProximity, CoherentQueriesEqualFreshOnesAlongAMotion) {
  check_coherent_sequence<2, 2>(11);
  check_coherent_sequence<3, 3>(12);
  check_coherent_sequence<4, 3>(13);
  check_coherent_sequence<4, 2>(14);
}

using test::grid_cells;

// The vertices of an n × n grid folded in R^4 at a phase of a motion: stretched in the plane by
// `stretch`, folded into z and w by `fold`, with w moving at `w_rate` × the phase.
std::vector<Vec4> folded_grid(int n, double phase, double stretch, double fold, double w_rate) {
  std::vector<Vec4> x;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = double(i) / (n - 1), v = double(j) / (n - 1);
      x.push_back(Vec4(u + stretch * std::sin(7 * v + 2 * u + phase),
                       v + stretch * std::sin(6 * u - 3 * v + phase),
                       fold * std::sin(9 * u + phase) * std::cos(8 * v),
                       fold * std::cos(7 * u - 5 * v) * std::sin(6 * v + u + w_rate * phase)));
    }
  return x;
}

// A long run on a deforming grid (the ring pairs dominate there): every query equals a fresh one,
// with and without ring pairs, through list rebuilds, fringe evictions and the settling of the
// ring odometers; a common translation costs no rebuild at all.
TEST(MeshProximity, CoherentGridRunEqualsFreshQueriesWithAndWithoutRingPairs) {
  const int n = 14;
  const std::vector<Cell<3>> cells = grid_cells(n);
  auto grid = [&](double phase) { return folded_grid(n, phase, 0.08, 0.25, 1.0); };
  const double delta = 0.8 / (n - 1);
  SelfProximity<4, 3> coherent(cells);
  int answered = 0;
  EXPECT_GT(coherent.ring_pairs(), 0u);
  std::vector<ProximityPair<4>> got, want;
  for (int step = 0; step < 400; ++step) {
    const auto x = grid(0.01 * step);
    const RingPairs ring = step % 5 == 4 ? RingPairs::kExclude : RingPairs::kInclude;
    coherent.pairs_within(x, delta, got, ring);
    SelfProximity<4, 3> fresh(cells);
    fresh.set_temporal_coherence(false);
    fresh.pairs_within(x, delta, want, ring);
    ASSERT_EQ(got.size(), want.size()) << "step " << step;
    for (std::size_t i = 0; i < want.size(); ++i)
      ASSERT_EQ(std::make_pair(got[i].a, got[i].b), std::make_pair(want[i].a, want[i].b)) << "step " << step;
    answered += !want.empty();
  }
  EXPECT_GT(answered, 300);
  // Excluding ring pairs leaves out exactly the pairs joined by a mesh edge.
  const auto x = grid(0.3);
  SelfProximity<4, 3> fresh(cells);
  fresh.set_temporal_coherence(false);
  fresh.pairs_within(x, delta, want, RingPairs::kInclude);
  fresh.pairs_within(x, delta, got, RingPairs::kExclude);
  std::size_t ring_answers = 0;
  for (const auto& p : want) {
    const auto& t = coherent.topology();
    ring_answers += std::binary_search(t.ring.begin() + t.ring_offset[p.a],
                                       t.ring.begin() + t.ring_offset[p.a + 1], p.b);
  }
  EXPECT_GT(ring_answers, 0u);
  EXPECT_EQ(got.size(), want.size() - ring_answers);
  // Moving the whole surface rigidly by far more than δ rebuilds nothing.
  coherent.pairs_within(x, delta, got);
  const long long runs = coherent.broad_phase_runs();
  for (int step = 1; step <= 20; ++step) {
    auto moved = x;
    for (auto& v : moved) v += Vec4(0.3, -0.2, 0.1, 0.25) * step;
    coherent.pairs_within(moved, delta, got);
    EXPECT_EQ(got.size(), want.size());
  }
  EXPECT_EQ(coherent.broad_phase_runs(), runs);
}

// Steps as the physics takes them: the pairs near x0, then the candidates of the step x0 → x1,
// and the next step starts at x1 or, when a fail-safe stopped some vertices, at a mix of x0 and
// x1 (the ring odometer then has to measure its way back). The candidates cover every pair, ring
// pairs included, that an all-pairs continuous test finds coming within the thickness.
TEST(MeshProximity, GridStepCandidatesCoverEveryHitThroughStoppedSteps) {
  const int n = 12;
  const std::vector<Cell<3>> cells = grid_cells(n);
  auto grid = [&](double phase) { return folded_grid(n, phase, 0.1, 0.3, 2.0); };
  const double spacing = 1.0 / (n - 1);
  CcdOptions opt;
  opt.thickness = 0.6 * spacing;  // ring pairs come this close as the grid folds
  SelfProximity<4, 3> q(cells);
  std::mt19937 rng(5);
  std::vector<ProximityPair<4>> near;
  auto x0 = grid(0);
  int hits = 0, ring_hits = 0, stopped = 0;
  for (int step = 0; step < 240; ++step) {
    const auto x1 = grid(0.015 * (step + 1));
    q.pairs_within(x0, 1.5 * opt.thickness, near, RingPairs::kExclude);
    std::set<std::pair<int, int>> offered;
    q.step_candidates(x0, x1, opt.thickness, [&](int a, int b) { offered.insert({a, b}); });
    if (step % 4 == 0) {
      for (int a = 0; a < static_cast<int>(cells.size()); ++a)
        for (int b = a + 1; b < static_cast<int>(cells.size()); ++b) {
          if (share_vertex<3, 3>(cells[a], cells[b])) continue;
          Simplex<4, 3> a0, a1, b0, b1;
          for (int i = 0; i < 3; ++i) {
            a0[i] = x0[cells[a][i]], a1[i] = x1[cells[a][i]];
            b0[i] = x0[cells[b][i]], b1[i] = x1[cells[b][i]];
          }
          if (!earliest_contact<4, 3, 3>(a0, a1, b0, b1, opt).hit) continue;
          ++hits;
          const auto& t = q.topology();
          ring_hits +=
              std::binary_search(t.ring.begin() + t.ring_offset[a], t.ring.begin() + t.ring_offset[a + 1], b);
          ASSERT_TRUE(offered.count({a, b})) << "step " << step << " missed " << a << "," << b;
        }
    }
    auto next = x1;
    if (step % 7 == 3) {  // a fail-safe stopped a patch of vertices at x0
      const int c = std::uniform_int_distribution<int>(0, n * n - 1)(rng);
      for (int v = 0; v < n * n; ++v)
        if ((v % n - c % n) * (v % n - c % n) + (v / n - c / n) * (v / n - c / n) <= 4) next[v] = x0[v];
      ++stopped;
    }
    x0 = next;
  }
  EXPECT_GT(hits, 0);
  EXPECT_GT(ring_hits, 0) << "the run should bring ring pairs within the thickness";
  EXPECT_GT(stopped, 20);
}

// The float boxes' gaps the broad phase prunes with never exceed the double boxes' gaps.
TEST(MeshProximity, FloatLeafGapsAreLowerBounds) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1, 1), scale(1e-3, 1e3);
  for (int round = 0; round < 20; ++round) {
    const double s = scale(rng);
    std::vector<Box<4>> boxes(40);
    for (auto& b : boxes) {
      const Vec4 c(s * u(rng), s * u(rng), s * u(rng), s * u(rng));
      b.add(c);
      b.add(c + 0.05 * s * Vec4(u(rng), u(rng), u(rng), u(rng)));
    }
    Bvh<4> bvh;
    bvh.build(boxes);
    for (int l = 0; l < bvh.leaf_count(); ++l)
      for (int k = 0; k < static_cast<int>(boxes.size()); ++k) {
        float g2[Bvh<4>::kLeafSize];
        bvh.leaf_gaps2(k, l, std::numeric_limits<float>::infinity(), g2);
        const Box<4>& a = boxes[bvh.id(k)];
        for (int j = 0; j < bvh.leaf_size(l); ++j) {
          const Box<4>& b = boxes[bvh.id(bvh.leaf_first(l) + j)];
          double exact = 0;
          for (int axis = 0; axis < 4; ++axis) {
            const double g = std::max({b.lo[axis] - a.hi[axis], a.lo[axis] - b.hi[axis], 0.0});
            exact += g * g;
          }
          EXPECT_LE(static_cast<double>(g2[j]), exact);
          // The leaf's box holds this one: the cell is near it at any radius the pair is within
          // (the query's radius carries the same 1e-6 of slack).
          EXPECT_TRUE(bvh.prim_near_leaf(k, l, static_cast<float>(exact * (1 + 1e-6)) * (1 + 1e-7f)));
        }
      }
  }
}

// The rows a list build tests against a leaf: a row left out has no pair the leaf gaps keep, at
// every radius and in 2, 3 and 4 dimensions, NaN boxes included; and far rows are left out.
template <int D>
void expect_leaf_rows_keep_every_near_pair(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Box<D>> boxes(45);
  for (auto& b : boxes) {
    Vec<D> c, e;
    for (int k = 0; k < D; ++k) c[k] = u(rng), e[k] = 0.1 * std::abs(u(rng));
    b.add(c);
    b.add(c + e);
  }
  boxes[7].hi[D - 1] = std::numeric_limits<double>::quiet_NaN();
  Bvh<D> bvh;
  bvh.build(boxes);
  int dropped = 0;
  for (const float r2 : {0.0f, 0.01f, 0.3f, std::numeric_limits<float>::infinity()})
    for (int la = 0; la < bvh.leaf_count(); ++la)
      for (int lb = 0; lb < bvh.leaf_count(); ++lb) {
        const unsigned rows = bvh.leaf_rows_near(la, lb, r2);
        EXPECT_EQ(rows >> bvh.leaf_size(la), 0u);
        for (int i = 0; i < bvh.leaf_size(la); ++i) {
          float g2[Bvh<D>::kLeafSize];
          const unsigned lanes = (1u << bvh.leaf_size(lb)) - 1;
          const unsigned kept = bvh.leaf_gaps2(bvh.leaf_first(la) + i, lb, r2, g2) & lanes;
          if (kept != 0) {
            EXPECT_TRUE(rows >> i & 1u) << "row " << i << " of leaf " << la;
          }
          dropped += !(rows >> i & 1u);
        }
      }
  EXPECT_GT(dropped, 0);  // the test sees rows far from a leaf
}

TEST(MeshProximity, LeafRowsNearKeepEveryRowWithANearPair) {
  std::mt19937 rng(31);
  for (int round = 0; round < 4; ++round) {
    expect_leaf_rows_keep_every_near_pair<2>(rng);
    expect_leaf_rows_keep_every_near_pair<3>(rng);
    expect_leaf_rows_keep_every_near_pair<4>(rng);
  }
}

// The AVX way of the leaf gaps gives the portable way's gaps and mask bit for bit, at every
// radius, in 2, 3 and 4 dimensions (unused axes must add nothing), NaN boxes included.
template <int D>
void expect_leaf_gaps_ways_agree(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Box<D>> boxes(37);  // a partial last leaf
  for (auto& b : boxes) {
    Vec<D> c, e;
    for (int k = 0; k < D; ++k) c[k] = u(rng), e[k] = 0.1 * std::abs(u(rng));
    b.add(c);
    b.add(c + e);
  }
  boxes[5].lo[0] = std::numeric_limits<double>::quiet_NaN();
  Bvh<D> bvh;
  bvh.build(boxes);
  for (const float r2 : {0.0f, 0.01f, 0.3f, std::numeric_limits<float>::infinity()})
    for (int l = 0; l < bvh.leaf_count(); ++l)
      for (int k = 0; k < static_cast<int>(boxes.size()); ++k) {
        float a[Bvh<D>::kLeafSize], b[Bvh<D>::kLeafSize];
        const unsigned lanes = (1u << bvh.leaf_size(l)) - 1;
        const unsigned ma = bvh.leaf_gaps2_portable(k, l, r2, a) & lanes;
        const unsigned mb = bvh.leaf_gaps2_avx(k, l, r2, b) & lanes;
        EXPECT_EQ(ma, mb);
        for (int j = 0; j < bvh.leaf_size(l); ++j)
          EXPECT_EQ(std::memcmp(&a[j], &b[j], sizeof(float)), 0) << a[j] << " vs " << b[j];
      }
}

TEST(MeshProximity, AvxLeafGapsEqualThePortableOnes) {
  if (!cpu::kHasAvx) GTEST_SKIP() << "this CPU has no AVX";
  std::mt19937 rng(8);
  for (int round = 0; round < 5; ++round) {
    expect_leaf_gaps_ways_agree<2>(rng);
    expect_leaf_gaps_ways_agree<3>(rng);
    expect_leaf_gaps_ways_agree<4>(rng);
  }
}

// The displacement field of the coherent queries: the AVX path (R^4) gives the portable bits, for
// every length (groups of four and a tail), and both report a non-finite coordinate as +inf.
TEST(MeshProximity, AvxCentredDifferenceEqualsThePortableOne) {
  if (!cpu::kHasAvx) GTEST_SKIP() << "this CPU has no AVX";
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-3, 3);
  for (const std::size_t n : {1u, 3u, 4u, 7u, 64u, 1001u}) {
    std::vector<Vec4> a(n), b(n);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 4; ++k) a[i][k] = u(rng), b[i][k] = a[i][k] + 1e-3 * u(rng);
    std::vector<Vec4> out_fast, out_ref;
    const double fast = prox_detail::centred_difference<4>(a, b, out_fast);
    const double ref = prox_detail::centred_difference_portable<4>(a, b, out_ref);
    EXPECT_EQ(std::memcmp(&fast, &ref, sizeof(double)), 0) << fast << " vs " << ref;
    ASSERT_EQ(out_fast.size(), n);
    EXPECT_EQ(std::memcmp(out_fast.data(), out_ref.data(), n * sizeof(Vec4)), 0);
    double far = 0;  // the radius holds every centred displacement
    for (const Vec4& d : out_ref) far = std::max(far, d.norm());
    EXPECT_LE(far, ref);
    if (n > 1) {  // one point is its own centre
      EXPECT_GT(ref, 0.0);
    }
    for (const double bad : {std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()}) {
      std::vector<Vec4> c = a;
      c[n / 2][3] = bad;
      EXPECT_EQ(prox_detail::centred_difference<4>(c, b, out_fast),
                std::numeric_limits<double>::infinity());
      EXPECT_EQ(prox_detail::centred_difference_portable<4>(c, b, out_ref),
                std::numeric_limits<double>::infinity());
    }
  }
}

// The relative motion of two triangles' vertices, every bound of the coherent queries rests on.
TEST(MeshProximity, AvxRelativeMotionEqualsThePortableOne) {
  if (!cpu::kHasAvx) GTEST_SKIP() << "this CPU has no AVX";
  std::mt19937 rng(10);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> pick(0, 19);
  std::vector<Vec4> field(20);
  for (int round = 0; round < 2000; ++round) {
    for (Vec4& f : field)
      for (int k = 0; k < 4; ++k) f[k] = std::ldexp(u(rng), round % 7 - 3);
    const Cell<3> a{pick(rng), pick(rng), pick(rng)}, b{pick(rng), pick(rng), pick(rng)};
    const double fast = prox_detail::max_relative<4, 3>(field, a, b);
    const double ref = prox_detail::max_relative_portable<4, 3>(field, a, b);
    ASSERT_EQ(std::memcmp(&fast, &ref, sizeof(double)), 0) << fast << " vs " << ref;
    double brute = 0;
    for (int i : a)
      for (int j : b) brute = std::max(brute, (field[i] - field[j]).norm());
    EXPECT_NEAR(ref, brute, 1e-15);
  }
}

// The gap along a pair's cached axis, the first re-proof of most pairs a query looks at again.
TEST(MeshProximity, AvxStoredAxisGapEqualsThePortableOne) {
  if (!cpu::kHasAvx) GTEST_SKIP() << "this CPU has no AVX";
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> pick(0, 11);
  std::vector<Vec4> x(12);
  int positive = 0;
  for (int round = 0; round < 3000; ++round) {
    for (Vec4& p : x)
      for (int k = 0; k < 4; ++k) p[k] = u(rng) + (k == 0 && (&p - x.data()) >= 6 ? 1.5 : 0.0);
    if (round % 50 == 7) x[3][2] = std::numeric_limits<double>::quiet_NaN();
    std::array<float, 4> axis{};
    if (round % 40 != 5)  // now and then a zero axis
      for (float& c : axis) c = static_cast<float>(u(rng));
    const Cell<3> a{pick(rng) % 6, pick(rng) % 6, pick(rng) % 6};
    const Cell<3> b{6 + pick(rng) % 6, 6 + pick(rng) % 6, 6 + pick(rng) % 6};
    const double fast = prox_detail::stored_axis_gap<4, 3>(x, a, b, axis);
    const double ref = prox_detail::stored_axis_gap_portable<4, 3>(x, a, b, axis);
    ASSERT_EQ(std::memcmp(&fast, &ref, sizeof(double)), 0) << fast << " vs " << ref;
    positive += ref > 0;
    // A lower bound of the distance: no pair of vertices is closer than a positive gap.
    double nearest = std::numeric_limits<double>::infinity();
    for (int i : a)
      for (int j : b) nearest = std::min(nearest, (x[i] - x[j]).norm());
    if (ref > 0) {
      EXPECT_LE(ref, nearest);
    }
  }
  EXPECT_GT(positive, 100);  // the test sees separating axes, not only overlaps
}

TEST(MeshProximity, BadInputIsAClearError) {
  EXPECT_THROW((SelfProximity<3, 3>({{0, 1, -2}})), Error);
  SelfProximity<3, 3> q({{0, 1, 5}});
  std::vector<Vec3> x(3, Vec3::Zero());
  std::vector<ProximityPair<3>> out;
  EXPECT_THROW(q.pairs_within(x, 0.1, out), Error);
  std::vector<Vec3> ok(6, Vec3::Zero());
  EXPECT_THROW(q.pairs_within(ok, std::numeric_limits<double>::quiet_NaN(), out), Error);
  q.pairs_within(ok, -1.0, out);  // no distance is negative
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace s4d
