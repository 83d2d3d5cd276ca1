// The surface explorer: a probe dragged across the shadow's intersection curves stays on its own
// sheet (where a probe choosing the nearest or the visible sheet would jump), reports each pass once
// and in order with above/below from the sheets' known w, its cues land in a WAV at their times, it
// holds the device point's projection through the real haptic loop, and nothing bad in makes NaN out.
#include "interact/live/surface_explorer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "audio/audio_measure.hpp"
#include "audio/cue_synth.hpp"
#include "audio/wav_file.hpp"
#include "core/error.hpp"
#include "haptics/haptic_loop.hpp"
#include "haptics/simulated_arm.hpp"
#include "interact/live/surface_explorer_path.hpp"
#include "interact/live/surface_explorer_scene.hpp"
#include "interact/live/surface_explorer_sound.hpp"
#include "proximity/closest_points.hpp"
#include "proximity/shadow_intersections.hpp"
#include "shape/surfaces_4d.hpp"

namespace s4d {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const DampedSpring kSpring{200, 1};

// An n × n grid over [-1, 1]² in (x, y), placed in R^4 by `place(x, y)`.
template <typename Place>
void add_sheet(Surface<4>& s, int n, Place place) {
  const int base = static_cast<int>(s.vertices.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) s.vertices.push_back(place(-1 + 2.0 * i / (n - 1), -1 + 2.0 * j / (n - 1)));
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int v00 = base + i * n + j, v10 = v00 + n, v01 = v00 + 1, v11 = v10 + 1;
      s.triangles.push_back({v00, v10, v11});
      s.triangles.push_back({v00, v11, v01});
    }
}

// Two sheets whose shadows (identity frame: shadow x, y, z; depth w) cross along y = 0.03, z = 0:
// A is the plane z = 0 at w = -0.5 + 0.1 x (below), B the plane z = (y - 0.03) / 2 at w = 0.5.
constexpr double kLineY = 0.03;
constexpr int kSheetN = 12;
constexpr int kSheetTriangles = 2 * (kSheetN - 1) * (kSheetN - 1);
double w_a(double x) { return -0.5 + 0.1 * x; }
double z_b(double y) { return 0.5 * (y - kLineY); }
Surface<4> two_sheets() {
  Surface<4> s;
  add_sheet(s, kSheetN, [](double x, double y) { return Vec4(x, y, 0, w_a(x)); });
  add_sheet(s, kSheetN, [](double x, double y) { return Vec4(x, y, z_b(y), 0.5); });
  return s;
}
bool on_sheet_a(int t) { return t >= 0 && t < kSheetTriangles; }

std::vector<ExplorerEvent> drain(SurfaceExplorer& e) {
  std::vector<ExplorerEvent> out;
  while (auto ev = e.pop_event()) out.push_back(*ev);
  return out;
}

// The brute-force naive probe: the triangle whose shadow is nearest to p.
int nearest_triangle(const Surface<4>& s, const Frame<4>& f, const Vec3& p) {
  int best = -1;
  double d = std::numeric_limits<double>::infinity();
  for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
    const auto& tr = s.triangles[t];
    const double dt =
        point_triangle<3>(p, f.shadow(s.vertices[tr[0]]), f.shadow(s.vertices[tr[1]]), f.shadow(s.vertices[tr[2]]))
            .distance;
    if (dt < d) {
      d = dt;
      best = t;
    }
  }
  return best;
}

// The visible sheet at shadow point p: of the triangles whose shadow holds p, the one nearest the
// viewer (largest w there). -1 if none.
int visible_triangle(const Surface<4>& s, const Frame<4>& f, const Vec3& p, double tol) {
  int best = -1;
  double best_w = -std::numeric_limits<double>::infinity();
  for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
    const auto& tr = s.triangles[t];
    const ClosestPoints<3> c =
        point_triangle<3>(p, f.shadow(s.vertices[tr[0]]), f.shadow(s.vertices[tr[1]]), f.shadow(s.vertices[tr[2]]));
    if (!(c.distance < tol)) continue;
    const double w = c.wb[0] * f.depth(s.vertices[tr[0]]) + c.wb[1] * f.depth(s.vertices[tr[1]]) +
                     c.wb[2] * f.depth(s.vertices[tr[2]]);
    if (w > best_w) {
      best_w = w;
      best = t;
    }
  }
  return best;
}

// Drags the explorer's device point straight from a to b in `steps` updates at 1 kHz.
struct Drag {
  std::vector<ExplorerStep> steps;
  std::vector<Vec3> device;
  std::vector<double> times;
  std::vector<double> w;  // the probe's depth after each step
};
Drag drag(SurfaceExplorer& e, const Surface<4>& s, const Frame<4>& f, const Vec3& a, const Vec3& b, int steps,
          double& time) {
  Drag d;
  const double dt = 1e-3;
  const Vec3 v = (b - a) / (steps * dt);
  for (int i = 1; i <= steps; ++i) {
    time += dt;
    const Vec3 c = a + (b - a) * (double(i) / steps);
    d.device.push_back(c);
    d.times.push_back(time);
    d.steps.push_back(e.update(s.vertices, f, c, v, 1000, time, kSpring));
    d.w.push_back(e.probe_depth(s.vertices, f));
  }
  return d;
}

TEST(SurfaceExplorer, TopologyAndCrossingTable) {
  const Surface<4> s = two_sheets();
  SurfaceExplorer e(s.triangles, static_cast<int>(s.vertices.size()));
  EXPECT_EQ(e.component_count(), 2);
  EXPECT_EQ(e.component(0), e.component(kSheetTriangles - 1));
  EXPECT_NE(e.component(0), e.component(kSheetTriangles));
  // Interior triangles have three neighbours, and neighbourhood is symmetric.
  for (int t = 0; t < e.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int nb = e.neighbour(t, k);
      if (nb < 0) continue;
      int back = 0;
      for (int j = 0; j < 3; ++j) back += e.neighbour(nb, j) == t;
      EXPECT_EQ(back, 1) << t << " -> " << nb;
    }
  const Frame<4> f;
  e.refresh_crossings(s.vertices, f);
  const CrossingTable& table = e.crossings();
  const ShadowIntersections ref = shadow_intersections(s, f);
  ASSERT_GT(ref.segments.size(), 0u);
  EXPECT_EQ(table.segments, static_cast<int>(ref.segments.size()));
  EXPECT_EQ(table.entries.size(), 2 * ref.segments.size());
  // Every entry's ends, in its triangle's barycentric coordinates, are on the line y = 0.03, z = 0,
  // and the same point in the other triangle's.
  for (int t = 0; t < e.triangle_count(); ++t)
    for (const CrossingTable::Entry& en : table.of(t)) {
      ASSERT_NE(on_sheet_a(t), on_sheet_a(en.other)) << "only the two sheets cross";
      for (int k = 0; k < 2; ++k) {
        const auto at = [&](int tri, const std::array<double, 2>& b) {
          const auto& tr = s.triangles[tri];
          return Vec3((1 - b[0] - b[1]) * f.shadow(s.vertices[tr[0]]) + b[0] * f.shadow(s.vertices[tr[1]]) +
                      b[1] * f.shadow(s.vertices[tr[2]]));
        };
        const Vec3 p = at(t, en.q[k]), q = at(en.other, en.o[k]);
        EXPECT_NEAR(p.y(), kLineY, 1e-12);
        EXPECT_NEAR(p.z(), 0, 1e-12);
        EXPECT_LT((p - q).norm(), 1e-12);
      }
    }
  EXPECT_THROW(SurfaceExplorer(s.triangles, 10), Error);
  const std::vector<Triangle> repeated = {{0, 1, 1}};
  EXPECT_THROW(SurfaceExplorer(repeated, 3), Error);
}

TEST(SurfaceExplorer, StaysOnItsSheetWhereANaiveProbeWouldJump) {
  const Surface<4> s = two_sheets();
  const Frame<4> f;
  SurfaceExplorer e(s.triangles, static_cast<int>(s.vertices.size()));
  e.refresh_crossings(s.vertices, f);
  // From a point of A to a point nearer B than A: the hand drifts towards the other sheet.
  const Vec3 a(0.1, -0.8, 0), b(0.1, 0.8, 0.3);
  ASSERT_TRUE(e.place(s.vertices, f, a));
  ASSERT_TRUE(on_sheet_a(e.probe().triangle));
  double time = 0;
  const Drag d = drag(e, s, f, a, b, 400, time);
  bool naive_jumped = false;
  for (std::size_t i = 0; i < d.steps.size(); ++i) {
    const ExplorerStep& st = d.steps[i];
    ASSERT_TRUE(st.ok) << i;
    ASSERT_TRUE(st.force.allFinite());
    ASSERT_NEAR(st.probe.z(), 0, 1e-12) << "on sheet A's plane at step " << i;
    if (!on_sheet_a(nearest_triangle(s, f, d.device[i]))) naive_jumped = true;
  }
  EXPECT_TRUE(on_sheet_a(e.probe().triangle)) << "ends on its sheet";
  EXPECT_EQ(e.component(e.probe().triangle), e.component(0));
  EXPECT_TRUE(naive_jumped) << "the nearest sheet became B: a nearest-triangle probe would have jumped";
  // The probe is the projection of the predicted point C + V/R on A, where A extends.
  const Vec3 v = (b - a) / 0.4;
  const Vec3 predicted = b + v / 1000;
  EXPECT_LT((d.steps.back().probe - Vec3(predicted.x(), predicted.y(), 0)).norm(), 1e-9);
  EXPECT_GT(e.counters().edges_walked, 5u);

  const std::vector<ExplorerEvent> ev = drain(e);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_FALSE(ev[0].above);
  EXPECT_NEAR(ev[0].point[1], kLineY, 1e-9);
  EXPECT_NEAR(ev[0].point[2], 0, 1e-12);
  EXPECT_NEAR(ev[0].w_self, w_a(0.1), 1e-9);
  EXPECT_NEAR(ev[0].w_other, 0.5, 1e-9);
  EXPECT_TRUE(on_sheet_a(ev[0].triangle));
  EXPECT_FALSE(on_sheet_a(ev[0].other));
  // There B is in front: the visible sheet, which a probe following the picture would take.
  EXPECT_FALSE(on_sheet_a(visible_triangle(s, f, ev[0].point_vec(), 1e-9)));
  // The device crossed y = 0.03 at t = 0.4 * (0.83 / 1.6) s; the event is at that tick (+1 for V/R).
  EXPECT_NEAR(ev[0].time, 0.4 * 0.83 / 1.6, 1.5e-3);
}

TEST(SurfaceExplorer, PassesAboveFromTheNearerSheet) {
  const Surface<4> s = two_sheets();
  const Frame<4> f;
  SurfaceExplorer e(s.triangles, static_cast<int>(s.vertices.size()));
  e.refresh_crossings(s.vertices, f);
  const Vec3 a(-0.3, -0.7, z_b(-0.7)), b(-0.3, 0.7, 0.0);  // from B, drifting towards A
  ASSERT_TRUE(e.place(s.vertices, f, a));
  ASSERT_FALSE(on_sheet_a(e.probe().triangle));
  double time = 0;
  const Drag d = drag(e, s, f, a, b, 300, time);
  for (const ExplorerStep& st : d.steps) {
    ASSERT_TRUE(st.ok);
    ASSERT_NEAR(st.probe.z(), z_b(st.probe.y()), 1e-12) << "on B's plane";
  }
  const std::vector<ExplorerEvent> ev = drain(e);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_TRUE(ev[0].above);
  EXPECT_NEAR(ev[0].w_self, 0.5, 1e-9);
  EXPECT_NEAR(ev[0].w_other, w_a(-0.3), 1e-9);
  EXPECT_EQ(explore_cue(ev[0]), CueKind::curve_above);
}

TEST(SurfaceExplorer, OneEventPerCrossingInOrderEvenAlongMeshEdges) {
  const Surface<4> s = two_sheets();
  const Frame<4> f;
  // x = 1/11 is a grid line of both sheets: the probe runs along mesh edges, and the curve crosses
  // those edges exactly where the probe passes it.
  for (double x : {0.37, 1.0 / 11.0}) {
    SurfaceExplorer e(s.triangles, static_cast<int>(s.vertices.size()));
    e.refresh_crossings(s.vertices, f);
    const std::vector<Vec3> stops = {{x, -0.5, 0}, {x, 0.5, 0}, {x, -0.2, 0}, {x, 0.6, 0}};
    ASSERT_TRUE(e.place(s.vertices, f, stops[0]));
    double time = 0;
    std::vector<Vec3> probes;
    std::vector<double> times;
    for (std::size_t k = 1; k < stops.size(); ++k) {
      const Drag d = drag(e, s, f, stops[k - 1], stops[k], 250, time);
      for (std::size_t i = 0; i < d.steps.size(); ++i) {
        ASSERT_TRUE(d.steps[i].ok);
        probes.push_back(d.steps[i].probe);
        times.push_back(d.times[i]);
      }
    }
    // Reference: the probe's y crossing 0.03 (a point on the line counts as beyond it).
    std::vector<double> expected;
    for (std::size_t i = 1; i < probes.size(); ++i)
      if ((probes[i - 1].y() >= kLineY) != (probes[i].y() >= kLineY)) expected.push_back(times[i]);
    const std::vector<ExplorerEvent> ev = drain(e);
    ASSERT_EQ(expected.size(), 3u) << "out, back, and out again";
    ASSERT_EQ(ev.size(), expected.size()) << "x = " << x;
    for (std::size_t i = 0; i < ev.size(); ++i) {
      EXPECT_DOUBLE_EQ(ev[i].time, expected[i]) << i;
      EXPECT_FALSE(ev[i].above);
      EXPECT_NEAR(ev[i].point[0], x, 1e-9);
      if (i > 0) {
        EXPECT_GT(ev[i].time, ev[i - 1].time);
      }
    }
    EXPECT_EQ(e.counters().events, 3u);
    EXPECT_EQ(e.counters().events_dropped, 0u);
    // Stopping exactly on the line and going on is one pass, whichever side rounding puts the stop
    // on; touching the line and going back is at most one.
    e.move_to(s.vertices, f, {x, kLineY, 0}, 10.0);
    e.move_to(s.vertices, f, {x, -0.6, 0}, 10.1);
    e.move_to(s.vertices, f, {x, kLineY, 0}, 10.2);
    e.move_to(s.vertices, f, {x, 0.6, 0}, 10.3);
    EXPECT_EQ(drain(e).size(), 2u) << "x = " << x;
    e.move_to(s.vertices, f, {x, kLineY, 0}, 10.4);
    e.move_to(s.vertices, f, {x, 0.5, 0}, 10.5);
    EXPECT_LE(drain(e).size(), 1u) << "x = " << x;
  }
}

TEST(SurfaceExplorer, ATremblingPassIsOneEvent) {
  const Surface<4> s = two_sheets();
  const Frame<4> f;
  SurfaceExplorer e(s.triangles, static_cast<int>(s.vertices.size()));
  e.refresh_crossings(s.vertices, f);
  ASSERT_TRUE(e.place(s.vertices, f, {0.3, -0.2, 0}));
  // Across the line, then back and forth over it by 1e-3 (less than the 0.006 rearm distance) ten
  // times, then away: one pass. Then back across from afar: a second.
  double t = 0;
  e.move_to(s.vertices, f, {0.3, kLineY + 0.0005, 0}, t += 0.001);
  for (int i = 0; i < 10; ++i) e.move_to(s.vertices, f, {0.3, kLineY + (i % 2 ? 0.0005 : -0.0005), 0}, t += 0.001);
  e.move_to(s.vertices, f, {0.3, 0.4, 0}, t += 0.001);
  EXPECT_EQ(drain(e).size(), 1u);
  EXPECT_EQ(e.counters().events_merged, 10u);
  e.move_to(s.vertices, f, {0.3, -0.4, 0}, t += 0.001);
  EXPECT_EQ(drain(e).size(), 1u);
  // With no rearm distance every jitter is a pass.
  e.settings().rearm_distance = 0;
  for (int i = 0; i < 10; ++i) e.move_to(s.vertices, f, {0.3, kLineY + (i % 2 ? -0.0005 : 0.0005), 0}, t += 0.001);
  EXPECT_EQ(drain(e).size(), 10u);
}

// Grid cell (i, j) of a triangle of a wrapped n × m grid, and the wrapped Chebyshev distance.
int grid_distance(const Surface<4>& s, int t0, int t1) {
  const int m = s.grid->cols, n = s.grid->rows;
  const int a = s.triangles[t0][0], b = s.triangles[t1][0];
  int di = std::abs(a / m - b / m), dj = std::abs(a % m - b % m);
  di = std::min(di, n - di);
  dj = std::min(dj, m - dj);
  return std::max(di, dj);
}

TEST(SurfaceExplorer, CliffordTorusProbeKeepsItsSheetThroughTheShadow) {
  const Surface<4> s = clifford_torus(40, 40);
  Frame<4> f;
  apply_rotations(f, parse_rotation_list("xw=30,yw=20", 4));
  const ShadowIntersections in = shadow_intersections(s, f);
  ASSERT_EQ(in.coplanar_pairs, 0) << "a generic view";
  ASSERT_GT(in.segments.size(), 10u);
  std::vector<int> curve_of(in.segments.size(), -1);
  for (std::size_t c = 0; c < in.curves.size(); ++c)
    for (int sg : in.curves[c].segments) curve_of[sg] = static_cast<int>(c);
  const auto dist_to_segment = [&](const Vec3& p, const ShadowSegment& g) {
    return point_segment<3>(p, g.p0, g.p1).distance;
  };
  // A shadow-only segment where a's sheet is well below b's, far apart on the torus, with no other
  // curve near it: a short straight drag across it passes this curve once and no other.
  const double d = 0.04;
  int pick = -1;
  Vec3 mid = Vec3::Zero(), across = Vec3::Zero();
  for (std::size_t i = 0; i < in.segments.size() && pick < 0; ++i) {
    const ShadowSegment& g = in.segments[i];
    if (g.true_intersection || g.length() < 0.02) continue;
    const Vec3 m = 0.5 * (g.p0 + g.p1);
    const double wa = 0.5 * (g.depth_a0 + g.depth_a1), wb = 0.5 * (g.depth_b0 + g.depth_b1);
    if (!(wb - wa > 0.2) || grid_distance(s, g.a, g.b) < 8) continue;
    bool isolated = true;
    for (std::size_t j = 0; j < in.segments.size() && isolated; ++j)
      if (curve_of[j] != curve_of[i] && dist_to_segment(m, in.segments[j]) < 4 * d) isolated = false;
    // The curve is straight enough here: its segments near m point along g.
    const Vec3 dir = (g.p1 - g.p0).normalized();
    for (std::size_t j = 0; j < in.segments.size() && isolated; ++j)
      if (curve_of[j] == curve_of[i] && dist_to_segment(m, in.segments[j]) < 2 * d &&
          std::abs((in.segments[j].p1 - in.segments[j].p0).normalized().dot(dir)) < 0.95)
        isolated = false;
    if (!isolated) continue;
    const auto& tr = s.triangles[g.a];
    const Vec3 x0 = f.shadow(s.vertices[tr[0]]), n = (f.shadow(s.vertices[tr[1]]) - x0).cross(f.shadow(s.vertices[tr[2]]) - x0);
    pick = static_cast<int>(i);
    mid = m;
    across = n.normalized().cross(dir);  // in a's shadow plane, across the curve
  }
  ASSERT_GE(pick, 0) << "no isolated crossing found";
  const ShadowSegment& g = in.segments[pick];

  SurfaceExplorer e(s.triangles, static_cast<int>(s.vertices.size()));
  e.refresh_crossings(s.vertices, f);
  // Start on a at the curve, step back off it, forget that, and drag across.
  const auto& tr = s.triangles[g.a];
  const Vec3 x0 = f.shadow(s.vertices[tr[0]]), e1 = f.shadow(s.vertices[tr[1]]) - x0,
             e2 = f.shadow(s.vertices[tr[2]]) - x0;
  Eigen::Matrix<double, 3, 2> basis;
  basis << e1, e2;
  const Eigen::Vector2d bm = basis.colPivHouseholderQr().solve(mid - x0);
  ASSERT_TRUE(e.place_at({g.a, bm[0], bm[1]}));
  const Vec3 from = mid - d * across, to = mid + d * across;
  e.move_to(s.vertices, f, from, 0);
  drain(e);
  const int start = e.probe().triangle;
  double time = 0, last_w = e.probe_depth(s.vertices, f), max_w_jump = 0;
  const Drag dr = drag(e, s, f, from, to, 200, time);
  for (std::size_t i = 0; i < dr.steps.size(); ++i) {
    ASSERT_TRUE(dr.steps[i].ok);
    ASSERT_TRUE(dr.steps[i].force.allFinite());
    const double w = dr.w[i];
    max_w_jump = std::max(max_w_jump, std::abs(w - last_w));
    last_w = w;
  }
  const std::vector<ExplorerEvent> ev = drain(e);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_FALSE(ev[0].above);
  EXPECT_LT(ev[0].w_self, ev[0].w_other);
  EXPECT_LE(grid_distance(s, ev[0].triangle, g.a), 2);
  EXPECT_LE(grid_distance(s, ev[0].other, g.b), 2);
  EXPECT_NEAR(ev[0].w_other - ev[0].w_self, 0.5 * (g.depth_b0 + g.depth_b1 - g.depth_a0 - g.depth_a1), 0.05);
  // Where it passed, b's sheet is the visible one: a probe following the picture would jump there.
  const int vis = visible_triangle(s, f, ev[0].point_vec(), 1e-9);
  ASSERT_GE(vis, 0);
  EXPECT_LE(grid_distance(s, vis, g.b), 2);
  EXPECT_GE(grid_distance(s, vis, g.a), 6);
  // And the probe did not: it ends next to where it started on the torus, its w never jumped.
  EXPECT_LE(grid_distance(s, e.probe().triangle, start), 2);
  EXPECT_GE(grid_distance(s, e.probe().triangle, g.b), 6);
  EXPECT_LT(max_w_jump, 0.02) << "continuous in w, no jump by the sheets' gap "
                              << ev[0].w_other - ev[0].w_self;
}

TEST(SurfaceExplorer, WavHoldsTheCuesAtTheirTimes) {
  const Surface<4> s = two_sheets();
  const Frame<4> f;
  SurfaceExplorer e(s.triangles, static_cast<int>(s.vertices.size()));
  e.refresh_crossings(s.vertices, f);
  double time = 0;
  // On A: below at about 0.2 s; then on B: above at about 0.9 s.
  ASSERT_TRUE(e.place(s.vertices, f, {0.2, -0.4, 0}));
  drag(e, s, f, {0.2, -0.4, 0}, {0.2, 0.4, 0}, 400, time);
  time = 0.5;
  ASSERT_TRUE(e.place(s.vertices, f, {0.2, -0.4, z_b(-0.4)}));
  drag(e, s, f, {0.2, -0.4, z_b(-0.4)}, {0.2, 0.4, z_b(0.4)}, 800, time);
  const std::vector<ExplorerEvent> ev = drain(e);
  ASSERT_EQ(ev.size(), 2u);
  ASSERT_FALSE(ev[0].above);
  ASSERT_TRUE(ev[1].above);
  const std::vector<float> pcm = render_cues(explore_cues(ev), {}, 1.5, {});
  const auto path = std::filesystem::temp_directory_path() / "s4d_explore_cues.wav";
  write_wav(path, pcm, kAudioSampleRate);
  const WavData wav = read_wav(path);
  std::filesystem::remove(path);
  const std::vector<float> x = wav.samples();
  const int r = wav.sample_rate;
  EXPECT_LT(test::peak(test::window(x, 0, ev[0].time - 0.001, r)), 1e-4) << "silent before the first pass";
  EXPECT_GT(test::peak(test::window(x, ev[0].time, ev[0].time + 0.05, r)), 0.05);
  EXPECT_LT(test::dominant_frequency(test::window(x, ev[0].time + 0.005, ev[0].time + 0.06, r), r), 250);
  EXPECT_LT(test::peak(test::window(x, ev[0].time + 0.25, ev[1].time - 0.001, r)), 1e-4) << "silent between";
  EXPECT_GT(test::dominant_frequency(test::window(x, ev[1].time + 0.005, ev[1].time + 0.06, r), r), 1000);
  // The onset sample itself: nothing before round(t * rate), sound right after.
  const long n1 = std::lround(ev[1].time * r);
  EXPECT_EQ(wav.pcm[n1 - 1], 0);
  EXPECT_NE(wav.pcm[n1 + 5], 0);
}

TEST(SurfaceExplorer, HapticLoopHoldsTheProjectionWhileTheHandPushesOff) {
  const Surface<4> s = two_sheets();
  const Frame<4> f;
  auto arm = std::make_unique<SimulatedArm>();
  Vec3 lo, hi;
  shadow_box(s.vertices, f, lo, hi);
  const DeviceMapping map = fit_shadow_box(lo, hi, arm->capabilities());
  auto scene = std::make_unique<SurfaceExplorerScene>(s, f, map);
  SurfaceExplorerScene& ex = *scene;
  const Vec3 start(-0.2, -0.6, 0);
  ASSERT_TRUE(ex.place(start));
  ASSERT_TRUE(on_sheet_a(ex.explorer().probe().triangle));
  // The hand walks along y across the line and pushes off A's plane (+z in the shadow, towards B's
  // side and away) by up to 0.25 scene units, against the spring.
  const double seconds = 3;
  arm->set_position(map.to_device(start));
  arm->set_hand_script([map, start, seconds](double t) {
    const double u = std::clamp(t / seconds, 0.0, 1.0);
    return map.to_device(start + Vec3(0, 1.2 * u, 0.25 * std::sin(3.14159265 * u)));
  });
  HapticLoopConfig cfg;
  cfg.realtime_priority = false;
  HapticLoop loop(std::move(arm), std::move(scene), cfg);
  double max_off = 0, max_gap = 0;
  std::vector<ExplorerEvent> ev;
  for (int i = 0; i < 3000; ++i) {
    loop.run_ticks(1);
    const ExploreStats& st = ex.stats();
    ASSERT_NEAR(st.probe.z(), 0, 1e-12) << "the probe stays on A";
    max_off = std::max(max_off, std::abs(st.device.z()));
    // The device point's projection on A (z = 0); the probe is that of C + V/R.
    max_gap = std::max(max_gap, (st.probe - Vec3(st.device.x(), st.device.y(), 0)).norm());
    while (auto e = ex.pop_event()) ev.push_back(*e);
  }
  const HapticSnapshot& snap = loop.snapshot();
  EXPECT_GT(max_off, 0.05) << "the hand did push the device off the surface";
  EXPECT_LT(max_gap, 2e-3) << "the probe held the projection (V/R and the encoder's step are all)";
  EXPECT_TRUE(std::isfinite(snap.max_force_output));
  EXPECT_GT(snap.max_force_output, 0.05) << "the spring pulled back";
  EXPECT_EQ(snap.safety.nonfinite, 0u);
  EXPECT_FALSE(ex.stats().left_component);
  EXPECT_EQ(ex.stats().zero_force_ticks, 0u);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_FALSE(ev[0].above);
  EXPECT_NEAR(ev[0].point[1], kLineY, 1e-9);
  // The anchor the loop shows is the probe, in device coordinates.
  EXPECT_LT((snap.tool.anchor - map.to_device(ex.stats().probe)).norm(), 1e-2);
}

TEST(SurfaceExplorer, ForcesStayFiniteForEdgeOnTrianglesAndNaNInput) {
  // A sheet whose columns i = 5 and 6 share their shadow x and differ in w: that cell is seen
  // edge-on (its two triangles' shadows are segments), yet the surface is continuous in R^4.
  Surface<4> s;
  add_sheet(s, 12, [](double x, double y) {
    const double col = (x + 1) * 5.5;  // 0 .. 11
    if (col > 5.5) return Vec4(x - 2.0 / 11, y, 0, 0.3);
    return Vec4(x, y, 0, 0.0);
  });
  const Frame<4> f;
  SurfaceExplorer e(s.triangles, static_cast<int>(s.vertices.size()));
  e.refresh_crossings(s.vertices, f);
  ASSERT_TRUE(e.place(s.vertices, f, {-0.6, 0.1, 0}));
  double time = 0;
  const Drag d = drag(e, s, f, {-0.6, 0.1, 0}, {0.5, 0.2, 0}, 300, time);
  for (const ExplorerStep& st : d.steps) {
    ASSERT_TRUE(st.ok);
    ASSERT_TRUE(st.force.allFinite());
    ASSERT_TRUE(st.probe.allFinite());
  }
  EXPECT_GT(e.counters().degenerate_passes, 0u);
  EXPECT_LT((d.steps.back().probe - Vec3(0.5, 0.2, 0)).norm(), 0.01) << "passed the edge-on cell";
  EXPECT_NEAR(e.probe_depth(s.vertices, f), 0.3, 1e-9) << "and reached the far side in w";

  // NaN and infinite device input: rejected, counted, the probe kept, no force.
  const ProbeLocation before = e.probe();
  for (const auto& [c, v, rate] : {std::tuple{Vec3(kNaN, 0, 0), Vec3::Zero().eval(), 1000.0},
                                   std::tuple{Vec3(0.1, 0, 0), Vec3(0, std::numeric_limits<double>::infinity(), 0), 1000.0},
                                   std::tuple{Vec3(0.1, 0, 0), Vec3::Zero().eval(), 0.0},
                                   std::tuple{Vec3(0.1, 0, 0), Vec3(1e300, 0, 0), 1e-300}}) {
    const ExplorerStep st = e.update(s.vertices, f, c, v, rate, time, kSpring);
    EXPECT_FALSE(st.ok);
    EXPECT_TRUE(st.force.allFinite());
    EXPECT_EQ(st.force, Vec3::Zero());
  }
  EXPECT_EQ(e.counters().rejected_inputs, 4u);
  EXPECT_EQ(e.probe().triangle, before.triangle);
  EXPECT_EQ(e.probe().b1, before.b1);
  // A vertex of the probe's triangle gone NaN (a simulation in trouble): no force, nothing moves;
  // once it is finite again the probe carries on.
  std::vector<Vec4> broken = s.vertices;
  broken[s.triangles[e.probe().triangle][1]] = Vec4::Constant(kNaN);
  const ExplorerStep st = e.update(broken, f, {0.4, 0.2, 0}, Vec3::Zero(), 1000, time, kSpring);
  EXPECT_FALSE(st.ok);
  EXPECT_EQ(st.force, Vec3::Zero());
  EXPECT_GT(e.counters().numerical, 0u);
  EXPECT_TRUE(e.update(s.vertices, f, {0.4, 0.2, 0}, Vec3::Zero(), 1000, time, kSpring).ok);
  // Too few positions for the mesh: refused, not read out of bounds.
  EXPECT_FALSE(e.update(std::span(s.vertices).first(10), f, {0.4, 0.2, 0}, Vec3::Zero(), 1000, time, kSpring).ok);

  // Through the haptic scene: a NaN device reading gives a zero (finite) force.
  SurfaceExplorerScene scene(s, f, DeviceMapping{});
  ASSERT_TRUE(scene.place({-0.6, 0.1, 0}));
  DeviceState bad;
  bad.position = Vec3(kNaN, 0, 0);
  const ToolOutput out = scene.step(bad, 1e-3);
  EXPECT_TRUE(out.force.allFinite());
  EXPECT_EQ(out.force, Vec3::Zero());
  EXPECT_TRUE(out.anchor.allFinite());
  EXPECT_EQ(scene.stats().zero_force_ticks, 1u);
}

TEST(SurfaceExplorer, ClampedAtBoundaryEdges) {
  const Surface<4> s = two_sheets();
  const Frame<4> f;
  SurfaceExplorer e(s.triangles, static_cast<int>(s.vertices.size()));
  ASSERT_TRUE(e.place(s.vertices, f, {0.5, -0.5, 0}));
  double time = 0;
  const Drag d = drag(e, s, f, {0.5, -0.5, 0}, {1.6, -0.3, 0.05}, 200, time);
  const Vec3 p = d.steps.back().probe;
  EXPECT_NEAR(p.x(), 1.0, 1e-12) << "held on the boundary";
  EXPECT_NEAR(p.y(), -0.3 + 0.2 / 0.2 / 1000, 1e-9) << "sliding along it with the hand (C + V/R)";
  EXPECT_GT(e.counters().boundary_stops, 0u);
  // The spring pulls the device back towards the boundary.
  EXPECT_LT(d.steps.back().force.x(), 0);
}

TEST(SurfaceExplorer, SceneInstallsAnOfferedViewInTheTick) {
  const Surface<4> s = two_sheets();
  const Frame<4> f;
  SurfaceExplorerScene scene(s, f, DeviceMapping{});
  ASSERT_TRUE(scene.place({0.1, -0.5, 0}));
  DeviceState d;
  d.position = DeviceMapping{}.to_device({0.1, -0.5, 0});
  scene.step(d, 1e-3);
  Frame<4> turned;
  apply_rotations(turned, parse_rotation_list("xw=30", 4));
  scene.offer_view(make_explore_view(scene.explorer().triangles(), scene.positions(), turned, DeviceMapping{}));
  scene.offer_view(make_explore_view(scene.explorer().triangles(), scene.positions(), turned, DeviceMapping{}));
  EXPECT_EQ(scene.stats().views_installed, 0u);
  scene.step(d, 1e-3);
  EXPECT_EQ(scene.stats().views_installed, 1u) << "the latest offer, once";
  EXPECT_LT((scene.frame().matrix() - turned.matrix()).norm(), 1e-15);
  scene.step(d, 1e-3);
  EXPECT_EQ(scene.stats().views_installed, 1u);
  EXPECT_FALSE(scene.pop_event().has_value());  // frees the retired view
  // The probe is where it was on the surface; its shadow point follows the turned frame.
  EXPECT_TRUE(on_sheet_a(scene.explorer().probe().triangle));
}

TEST(SurfaceExplorerPath, ParsesAndWalksAtSteadySpeed) {
  const std::vector<Vec3> p = parse_point_list("0,0,0; 1,0,0 ;1, 2, 0;");
  ASSERT_EQ(p.size(), 3u);
  const PolylinePath path(p);
  EXPECT_DOUBLE_EQ(path.length(), 3);
  EXPECT_LT((path.at_time(1.5, 3) - Vec3(1, 0.5, 0)).norm(), 1e-12);
  EXPECT_LT((path.at_time(-1, 3) - Vec3(0, 0, 0)).norm(), 1e-12);
  EXPECT_LT((path.at_time(9, 3) - Vec3(1, 2, 0)).norm(), 1e-12);
  for (const char* bad : {"1,2", "0,0,0", "nan,0,0;1,1,1", "0,0,0;1,1,x", ""}) {
    try {
      parse_point_list(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("--through"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace s4d
