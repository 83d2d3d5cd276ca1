// A knot is a chain in World<3>: its springs and collision cells, and the promise that a drag is
// an isotopy — a strand pulled straight through another is stopped (judged by a brute-force
// segment distance and a linking number that share no code with the engine), so the knot's name
// cannot change by dragging.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "knots/knot_identify.hpp"
#include "physics/world.hpp"
#include "test_curves.hpp"
#include "test_worlds.hpp"

namespace s4d {
namespace {

constexpr double kPi = std::numbers::pi;

// [brute force] The distance of segments p0p1 and q0q1 (Ericson, Real-Time Collision Detection
// 5.1.9): a closed form, not the engine's face enumeration.
double segment_distance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r);
  double s = 0, t = 0;
  if (a <= 1e-30 && e <= 1e-30) return r.norm();
  if (a <= 1e-30) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 1e-30) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return ((p0 + s * d1) - (q0 + t * d2)).norm();
}

// The smallest distance of two segments of the closed polylines (components of `sizes` points,
// flat in x) that share no vertex, by trying every pair.
double smallest_gap(const std::vector<Vec3>& x, const std::vector<int>& sizes) {
  struct Seg { int a, b; };
  std::vector<Seg> segs;
  int first = 0;
  for (int n : sizes) {
    for (int k = 0; k < n; ++k) segs.push_back({first + k, first + (k + 1) % n});
    first += n;
  }
  double best = INFINITY;
  for (std::size_t i = 0; i < segs.size(); ++i)
    for (std::size_t j = i + 1; j < segs.size(); ++j) {
      const Seg s = segs[i], t = segs[j];
      if (s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b) continue;
      best = std::min(best, segment_distance(x[s.a], x[s.b], x[t.a], x[t.b]));
    }
  return best;
}

// The linking number of two closed polygons from the crossings of their xy shadows: each crossing
// counts its sign, ±1/2.
double linking_number(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double sum = 0;
  const std::size_t na = a.size(), nb = b.size();
  for (std::size_t i = 0; i < na; ++i)
    for (std::size_t j = 0; j < nb; ++j) {
      const Vec3 p = a[i], dp = a[(i + 1) % na] - p, q = b[j], dq = b[(j + 1) % nb] - q;
      const double den = dp.x() * dq.y() - dp.y() * dq.x();
      if (std::abs(den) < 1e-15) continue;
      const Vec3 r = q - p;
      const double s = (r.x() * dq.y() - r.y() * dq.x()) / den, t = (r.x() * dp.y() - r.y() * dp.x()) / den;
      if (s < 0 || s >= 1 || t < 0 || t >= 1) continue;
      const double za = p.z() + s * dp.z(), zb = q.z() + t * dq.z();
      sum += 0.5 * (za > zb ? 1 : -1) * (den > 0 ? 1 : -1);
    }
  return sum;
}

Polyline<3> ring(const Vec3& centre, double radius, int n) {
  Polyline<3> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    p.points.push_back(centre + radius * Vec3(std::cos(t), std::sin(t), 0));
  }
  return p;
}

PhysicsParams<3> chain_params() {
  PhysicsParams<3> p;
  p.thickness = 0.05;
  p.damping = 0.05;
  return p;
}

struct Pulled {
  double smallest_gap = INFINITY;  // brute force, every tenth step
  long long contacts = 0;          // pairs the repulsion acted on, summed over the steps
};

// Pulls vertex v towards `to` (a spring of 100 N/unit capped at 2 N, as the window's band) for
// `steps` steps, the target moving there over the first half; checks every few steps that no two
// segments meet.
Pulled pull(World<3>& w, int v, const Vec3& to, int steps, const std::vector<int>& sizes) {
  const Vec3 from = w.positions()[static_cast<std::size_t>(v)];
  Pulled out;
  for (int s = 0; s < steps; ++s) {
    const double u = std::min(1.0, 2.0 * s / steps);
    const Vec3 target = from + u * (to - from);
    Vec3 f = 100 * (target - w.positions()[static_cast<std::size_t>(v)]) - 0.5 * w.velocities()[static_cast<std::size_t>(v)];
    if (f.norm() > 2) f *= 2 / f.norm();
    w.set_external_force(v, f);
    w.step();
    out.contacts += w.data().last_contacts;
    if (s % 10 == 0 || s + 1 == steps) {
      const std::vector<Vec3> x(w.positions().begin(), w.positions().end());
      out.smallest_gap = std::min(out.smallest_gap, smallest_gap(x, sizes));
    }
  }
  w.set_external_force(v, Vec3::Zero());
  return out;
}

Curve<3> curve_of(const World<3>& w, const Curve<3>& like) {
  Curve<3> c = like;
  std::size_t i = 0;
  for (auto& comp : c.components)
    for (Vec3& p : comp.points) p = w.positions()[i++];
  return c;
}

TEST(CurveWorld, AChainHasEdgeAndBendingSpringsAndSegmentCells) {
  Curve<3> c;
  c.components.push_back(ring(Vec3::Zero(), 1, 12));
  Polyline<3> open;
  open.closed = false;
  for (int i = 0; i < 5; ++i) open.points.emplace_back(0.2 * i, 0, 2);
  c.components.push_back(open);
  ModelBuilder<3> b(chain_params());
  EXPECT_EQ(b.add_body(c), 0);
  const Model<3> m = b.build();
  EXPECT_EQ(m.nv, 17);
  EXPECT_TRUE(m.curves());
  EXPECT_TRUE(m.triangles.empty());
  ASSERT_EQ(m.segments.size(), 12u + 4u);
  EXPECT_EQ(m.segments[11], (Segment{11, 0})) << "a closed component wraps";
  EXPECT_EQ(m.segments[12], (Segment{12, 13}));
  int structural = 0, bending = 0;
  for (const Spring& s : m.springs) (s.kind == SpringKind::kStructural ? structural : bending) += 1;
  EXPECT_EQ(structural, 12 + 4);
  EXPECT_EQ(bending, 12 + 3);
  EXPECT_TRUE(m.mesh_adjacent(11, 0));
  EXPECT_FALSE(m.mesh_adjacent(11, 12)) << "components are apart";
  // The ring's edges are 0.52 long, thickness 0.05: only the ring pairs are left to the springs.
  EXPECT_EQ(m.chains[0].exclusion, 2);
  EXPECT_TRUE(m.chain_near(0, 2));
  EXPECT_TRUE(m.chain_near(0, 10)) << "round the closed chain";
  EXPECT_FALSE(m.chain_near(0, 3));
  EXPECT_FALSE(m.chain_near(0, 12)) << "another chain";
  EXPECT_NEAR(m.contact_thickness, 0.05, 1e-12);
}

TEST(CurveWorld, AThickChainLeavesNearbySegmentsToItsSprings) {
  Curve<3> c;
  c.components.push_back(ring(Vec3::Zero(), 1, 100));  // edges 0.063
  PhysicsParams<3> p = chain_params();
  p.thickness = 0.2;
  ModelBuilder<3> b(p);
  b.add_body(c);
  const Model<3> m = b.build();
  EXPECT_EQ(m.chains[0].exclusion, static_cast<int>(std::floor(1 + 1.5 * 0.2 / (c.length() / 100))));
  EXPECT_NEAR(m.contact_thickness, 0.2, 1e-12) << "nothing the springs do not guard is nearer than δ";
}

TEST(CurveWorld, RefusalsSayWhatIsWrong) {
  auto error = [](auto&& build) -> std::string {
    try {
      build();
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  Curve<3> twice;  // the same point twice in a row
  twice.components.push_back(ring(Vec3::Zero(), 1, 8));
  twice.components[0].points.insert(twice.components[0].points.begin() + 3, twice.components[0].points[3]);
  EXPECT_NE(error([&] { ModelBuilder<3>(chain_params()).add_body(twice); }).find("two equal consecutive points"),
            std::string::npos);
  Curve<3> crossing;  // two rings through each other's strand
  crossing.components.push_back(ring(Vec3::Zero(), 1, 16));
  Polyline<3> other = ring(Vec3(2, 0, 0), 1, 16);
  crossing.components.push_back(other);
  EXPECT_NE(error([&] {
              ModelBuilder<3> b(chain_params());
              b.add_body(crossing);
              b.build();
            }).find("intersects itself: segments"),
            std::string::npos);
  EXPECT_NE(error([&] {
              ModelBuilder<3> b(chain_params());
              b.add_body(test::lone_triangle<3>(1.0));
              Curve<3> far;
              far.components.push_back(ring(Vec3(5, 5, 5), 1, 8));
              b.add_body(far);
              b.build();
            }).find("surfaces or curves, not both"),
            std::string::npos);
}

// A Hopf link, one ring held still; a vertex of the other is pulled straight through the held
// ring's strand. The strand stops it: the rings never meet and stay linked.
TEST(CurveWorld, AStrandPulledStraightThroughAnotherIsStopped) {
  Curve<3> c;
  c.components.push_back(ring(Vec3::Zero(), 1, 64));
  Polyline<3> other;  // in the xz plane, through the first ring's disc
  for (int i = 0; i < 40; ++i) {
    const double t = 2 * kPi * i / 40;
    other.points.emplace_back(1 + 0.5 * std::cos(t), 0, 0.5 * std::sin(t));
  }
  c.components.push_back(other);
  const std::vector<int> sizes{64, 40};
  ModelBuilder<3> b(chain_params());
  b.add_body(c);
  World<3> w(b.build());
  for (int i = 0; i < 64; ++i) w.pin(i);
  const int v = 64 + 20;  // at (0.5, 0, 0), inside the held ring's disc
  ASSERT_NEAR(w.positions()[v].x(), 0.5, 1e-9);
  const std::vector<Vec3> x0(w.positions().begin(), w.positions().end());
  ASSERT_EQ(std::abs(linking_number({x0.begin(), x0.begin() + 64}, {x0.begin() + 64, x0.end()})), 1);
  const Vec3 target(2.2, 0, 0);  // straight out through the held ring's strand at x = 1
  const Pulled p = pull(w, v, target, 3000, sizes);
  EXPECT_GT(p.smallest_gap, 0.25 * w.model().contact_thickness) << "never closer than the fail-safe's layer";
  EXPECT_GT(p.contacts, 0) << "the strands met";
  const std::vector<Vec3> x(w.positions().begin(), w.positions().end());
  EXPECT_EQ(std::abs(linking_number({x.begin(), x.begin() + 64}, {x.begin() + 64, x.end()})), 1)
      << "it did not pass through";
  EXPECT_GT((x[v] - target).norm(), 0.5) << "held back by the strand";
  EXPECT_LT(x[v].x(), 1.0);
  EXPECT_EQ(w.data().warnings.rollbacks, 0);
}

// A drag is an isotopy: the under strand of a crossing pulled straight up along the depth through
// the strand over it is stopped, so the knot keeps its name.
void expect_name_kept(const std::vector<bool>& standard, int crossing, bool unknot) {
  const Curve<3> start = test::braid_closure(standard, 240);
  const KnotIdentification before = identify_knot(start);
  ASSERT_EQ(before.kind == KnotKind::kUnknot, unknot) << before.name;
  ModelBuilder<3> b(chain_params());
  b.add_body(start);
  World<3> w(b.build());
  // The crossing's passes are at u = (c + 1/2)/q and that + 1: the lower one is pulled up.
  const int q = static_cast<int>(standard.size()), n = 240;
  const int first = static_cast<int>(std::lround((crossing + 0.5) / q * n / 2)), second = first + n / 2;
  const int under = w.positions()[first].z() < w.positions()[second].z() ? first : second;
  const Vec3 at = w.positions()[under];
  const Pulled p = pull(w, under, at + Vec3(0, 0, 1.4), 3000, {n});
  EXPECT_GT(p.smallest_gap, 0);
  EXPECT_GT(p.contacts, 0) << "the strand met the one over it (and pushed it, or slid round it)";
  const KnotIdentification after = identify_knot(curve_of(w, start));
  EXPECT_EQ(after.kind, before.kind) << after.name;
  EXPECT_EQ(after.name, before.name);
}

TEST(CurveWorld, AnUnknotDraggedStaysTheUnknot) { expect_name_kept({true, true, false}, 2, true); }

TEST(CurveWorld, ATrefoilDraggedStaysTheTrefoil) { expect_name_kept({true, true, true}, 0, false); }

// On release a curve rests where it was left: the springs take its shape, nothing pulls it back.
TEST(CurveWorld, RestHereKeepsTheShape) {
  Curve<3> c;
  c.components.push_back(ring(Vec3::Zero(), 1, 48));
  ModelBuilder<3> b(chain_params());
  b.add_body(c);
  World<3> w(b.build());
  pull(w, 0, Vec3(1.6, 0, 0), 800, {48});
  w.rest_here();
  w.stop();
  const std::vector<Vec3> left(w.positions().begin(), w.positions().end());
  for (int s = 0; s < 500; ++s) w.step();
  double moved = 0;
  for (std::size_t i = 0; i < left.size(); ++i) moved = std::max(moved, (w.positions()[i] - left[i]).norm());
  EXPECT_LT(moved, 1e-12);
  EXPECT_GT(left[0].x(), 1.3) << "the pull had moved it";
}

}  // namespace
}  // namespace s4d
