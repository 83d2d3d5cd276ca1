// The explorer's mesh walk (straight moves in one triangle's shadow plane, continued across mesh
// edges), its crossing events, the crossing table and the placement (see surface_explorer.hpp).
//
// [SECTION] Crossing table
// [SECTION] Topology
// [SECTION] Geometry
// [SECTION] Walk
// [SECTION] Events
#include "interact/live/surface_explorer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "core/error.hpp"
#include "proximity/closest_points.hpp"
#include "proximity/shadow_intersections.hpp"

namespace s4d {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A triangle whose shadow's (2 area)² is below this times its longest edge to the fourth (height
// under 1e-7 of its length) is seen edge-on: a sliver's plane is noise.
constexpr double kSliver = 1e-14;
bool is_flat(double g11, double g22, double det) {
  const double l2 = std::max(g11, g22);
  return det > kSliver * l2 * l2;
}

using Bary = std::array<double, 2>;  // (b1, b2); b0 = 1 - b1 - b2

// (b1, b2) of the point of the plane of (x0, x0 + e1, x0 + e2) nearest to p; false when degenerate.
bool plane_bary(const Vec3& x0, const Vec3& e1, const Vec3& e2, const Vec3& p, Bary& out) {
  const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
  const double det = g11 * g22 - g12 * g12;
  if (!is_flat(g11, g22, det)) return false;
  const Vec3 r = p - x0;
  const double r1 = e1.dot(r), r2 = e2.dot(r);
  out = {(g22 * r1 - g12 * r2) / det, (g11 * r2 - g12 * r1) / det};
  return true;
}

}  // namespace

// [SECTION] Crossing table

CrossingTable build_crossing_table(std::span<const Triangle> triangles, std::span<const Vec4> positions,
                                   const Frame<4>& frame) {
  for (const Triangle& t : triangles)
    for (int v : t)
      if (v < 0 || v >= static_cast<int>(positions.size()))
        throw Error("crossing table: a triangle uses vertex " + std::to_string(v) + " but there are " +
                    std::to_string(positions.size()) + " positions");
  Surface<4> s;
  s.vertices.assign(positions.begin(), positions.end());
  s.triangles.assign(triangles.begin(), triangles.end());
  const ShadowIntersections r = shadow_intersections(s, frame);

  CrossingTable table;
  table.segments = static_cast<int>(r.segments.size());
  table.coplanar_pairs = r.coplanar_pairs;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec4& p : positions) {
    const Vec3 q = frame.shadow(p);
    if (!q.allFinite()) continue;
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  table.shadow_diagonal = (hi - lo).allFinite() ? (hi - lo).norm() : 0.0;

  const int nt = static_cast<int>(triangles.size());
  table.first.assign(nt + 1, 0);
  for (const ShadowSegment& g : r.segments) {
    ++table.first[g.a + 1];
    ++table.first[g.b + 1];
  }
  std::partial_sum(table.first.begin(), table.first.end(), table.first.begin());
  table.entries.resize(table.first[nt]);
  std::vector<int> fill(table.first.begin(), table.first.end() - 1);
  const auto corners = [&](int t, Vec3& x0, Vec3& e1, Vec3& e2) {
    x0 = frame.shadow(positions[triangles[t][0]]);
    e1 = frame.shadow(positions[triangles[t][1]]) - x0;
    e2 = frame.shadow(positions[triangles[t][2]]) - x0;
  };
  for (const ShadowSegment& g : r.segments) {
    Vec3 ax0, ae1, ae2, bx0, be1, be2;
    corners(g.a, ax0, ae1, ae2);
    corners(g.b, bx0, be1, be2);
    CrossingTable::Entry ea, eb;
    bool ok = true;
    for (int k = 0; k < 2; ++k) {
      const Vec3& p = k == 0 ? g.p0 : g.p1;
      ok = ok && plane_bary(ax0, ae1, ae2, p, ea.q[k]) && plane_bary(bx0, be1, be2, p, eb.q[k]);
      ea.o[k] = eb.q[k];
      eb.o[k] = ea.q[k];
    }
    ea.other = g.b;
    eb.other = g.a;
    if (!ok) {  // the finder skips shadows seen edge-on, so this does not happen; keep it harmless
      ea.other = eb.other = -1;
      ea.q[1] = ea.q[0];
      eb.q[1] = eb.q[0];
    }
    table.entries[fill[g.a]++] = ea;
    table.entries[fill[g.b]++] = eb;
  }
  return table;
}

// [SECTION] Topology

SurfaceExplorer::SurfaceExplorer(std::span<const Triangle> triangles, int vertex_count,
                                 const ExplorerSettings& settings)
    : triangles_(triangles.begin(), triangles.end()), vertex_count_(vertex_count), settings_(settings) {
  const int nt = static_cast<int>(triangles_.size());
  for (int t = 0; t < nt; ++t) {
    const Triangle& tr = triangles_[t];
    for (int v : tr)
      if (v < 0 || v >= vertex_count)
        throw Error("explorer: triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) +
                    " of a mesh with " + std::to_string(vertex_count) + " vertices");
    if (tr[0] == tr[1] || tr[1] == tr[2] || tr[0] == tr[2])
      throw Error("explorer: triangle " + std::to_string(t) + " repeats a vertex");
  }
  // Edges sorted by their vertex pair; each group of equal edges is one mesh edge.
  struct Edge {
    int lo, hi, t, k;
  };
  std::vector<Edge> edges;
  edges.reserve(3 * triangles_.size());
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = triangles_[t][(k + 1) % 3], b = triangles_[t][(k + 2) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), t, k});
    }
  std::sort(edges.begin(), edges.end(),
            [](const Edge& x, const Edge& y) { return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi; });
  neighbours_.assign(nt, {-1, -1, -1});
  std::vector<int> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    if (j - i == 2) {  // a manifold edge; more than two triangles: a boundary for the walk
      neighbours_[edges[i].t][edges[i].k] = edges[i + 1].t;
      neighbours_[edges[i + 1].t][edges[i + 1].k] = edges[i].t;
    }
    for (std::size_t m = i + 1; m < j; ++m) parent[find(edges[m].t)] = find(edges[i].t);
    i = j;
  }
  component_.assign(nt, -1);
  std::vector<int> label(nt, -1);
  for (int t = 0; t < nt; ++t) {
    const int root = find(t);
    if (label[root] < 0) label[root] = components_++;
    component_[t] = label[root];
  }
  table_.first.assign(nt + 1, 0);
}

void SurfaceExplorer::refresh_crossings(std::span<const Vec4> positions, const Frame<4>& frame) {
  CrossingTable t = build_crossing_table(triangles_, positions, frame);
  swap_crossings(t);
}

// [SECTION] Geometry

struct SurfaceExplorer::Geometry {
  Vec3 x0, e1, e2;         // shadow of corner 0; edges to corners 1 and 2
  std::array<double, 3> w;  // 4D depth of the corners
  double g11, g12, g22, det;
  bool flat;               // false: the shadow is seen edge-on (no plane to walk in)
  Vec3 corner(int k) const { return k == 0 ? x0 : (k == 1 ? Vec3(x0 + e1) : Vec3(x0 + e2)); }
  Vec3 at(const Bary& b) const { return x0 + b[0] * e1 + b[1] * e2; }
  const Frame<4>* frame = nullptr;  // reads the depth between the corners (perspective-correct)
  double depth(const Bary& b) const { return frame->depth_at(std::array<double, 3>{1 - b[0] - b[1], b[0], b[1]}, w); }
};

bool SurfaceExplorer::geometry(int t, std::span<const Vec4> positions, const Frame<4>& frame,
                               Geometry& g) const {
  const Triangle& tr = triangles_[t];
  Vec4 q[3];
  for (int k = 0; k < 3; ++k) q[k] = frame.to_view(positions[tr[k]]);
  if (!q[0].allFinite() || !q[1].allFinite() || !q[2].allFinite()) return false;
  g.frame = &frame;
  g.x0 = frame.project(q[0]);
  g.e1 = frame.project(q[1]) - g.x0;
  g.e2 = frame.project(q[2]) - g.x0;
  for (int k = 0; k < 3; ++k) g.w[k] = q[k][3];
  g.g11 = g.e1.dot(g.e1);
  g.g12 = g.e1.dot(g.e2);
  g.g22 = g.e2.dot(g.e2);
  g.det = g.g11 * g.g22 - g.g12 * g.g12;
  g.flat = is_flat(g.g11, g.g22, g.det);
  return true;
}

Vec3 SurfaceExplorer::probe_point(std::span<const Vec4> positions, const Frame<4>& frame) const {
  Geometry g;
  if (!probe_.valid() || static_cast<int>(positions.size()) < vertex_count_ ||
      !geometry(probe_.triangle, positions, frame, g))
    return Vec3::Constant(kNaN);
  return g.at({probe_.b1, probe_.b2});
}

double SurfaceExplorer::probe_depth(std::span<const Vec4> positions, const Frame<4>& frame) const {
  Geometry g;
  if (!probe_.valid() || static_cast<int>(positions.size()) < vertex_count_ ||
      !geometry(probe_.triangle, positions, frame, g))
    return kNaN;
  return g.depth({probe_.b1, probe_.b2});
}

bool SurfaceExplorer::place(std::span<const Vec4> positions, const Frame<4>& frame, const Vec3& p) {
  if (!p.allFinite() || static_cast<int>(positions.size()) < vertex_count_) return false;
  double best = std::numeric_limits<double>::infinity(), best_w = -best;
  ProbeLocation loc;
  Geometry g;
  const double tie = 1e-12 * std::max(1.0, table_.shadow_diagonal);
  for (int t = 0; t < triangle_count(); ++t) {
    if (!geometry(t, positions, frame, g)) continue;
    const ClosestPoints<3> c = point_triangle<3>(p, g.corner(0), g.corner(1), g.corner(2));
    if (!std::isfinite(c.distance)) continue;
    const Bary b{c.wb[1], c.wb[2]};
    const double w = g.depth(b);
    if (c.distance < best - tie || (c.distance <= best + tie && w > best_w)) {
      best = c.distance;
      best_w = w;
      loc = {t, b[0], b[1]};
    }
  }
  return loc.valid() && place_at(loc);
}

bool SurfaceExplorer::place_at(const ProbeLocation& location) {
  if (location.triangle < 0 || location.triangle >= triangle_count() || !std::isfinite(location.b1) ||
      !std::isfinite(location.b2))
    return false;
  double b1 = std::clamp(location.b1, 0.0, 1.0), b2 = std::clamp(location.b2, 0.0, 1.0);
  if (b1 + b2 > 1) {
    const double s = b1 + b2;
    b1 /= s;
    b2 /= s;
  }
  probe_ = {location.triangle, b1, b2};
  have_last_event_ = false;
  ++counters_.placements;
  return true;
}

// [SECTION] Walk

namespace {

// Puts b exactly on edge k (the edge opposite corner k) and inside the triangle.
void snap_to_edge(Bary& b, int k) {
  b[0] = std::max(0.0, b[0]);
  b[1] = std::max(0.0, b[1]);
  if (k == 1) b[0] = 0;
  if (k == 2) b[1] = 0;
  if (k == 0 || b[0] + b[1] > 1) {
    const double s = b[0] + b[1];
    b = s > 0 ? Bary{b[0] / s, b[1] / s} : Bary{0.5, 0.5};
  }
}

// Barycentric weight of corner k.
double weight(const Bary& b, int k) { return k == 0 ? 1 - b[0] - b[1] : b[k - 1]; }

Bary from_weights(const double w[3]) { return {w[1], w[2]}; }

}  // namespace

ExplorerStep SurfaceExplorer::update(std::span<const Vec4> positions, const Frame<4>& frame, const Vec3& c,
                                     const Vec3& v, double rate_hz, double time,
                                     const DampedSpring& spring) noexcept {
  ++counters_.updates;
  ExplorerStep out;
  if (!c.allFinite() || !v.allFinite() || !std::isfinite(rate_hz) || !(rate_hz > 0) ||
      !Vec3(c + v / rate_hz).allFinite()) {
    ++counters_.rejected_inputs;
    out.probe = probe_point(positions, frame);
    return out;
  }
  if (!probe_.valid()) return out;
  Vec3 probe = Vec3::Constant(kNaN);
  const Vec3 f = navigation_force<3>(
      c, v, rate_hz,
      [&](const Vec3& predicted) {
        probe = move_to(positions, frame, predicted, time);
        return probe;
      },
      spring);
  out.probe = probe;
  if (!probe.allFinite() || !f.allFinite()) {
    ++counters_.numerical;
    return out;
  }
  out.force = f;
  out.ok = true;
  return out;
}

Vec3 SurfaceExplorer::move_to(std::span<const Vec4> positions, const Frame<4>& frame, const Vec3& target,
                              double time) noexcept {
  if (!probe_.valid()) return Vec3::Constant(kNaN);
  if (static_cast<int>(positions.size()) < vertex_count_) {
    ++counters_.numerical;
    return Vec3::Constant(kNaN);
  }
  if (!target.allFinite()) {
    ++counters_.rejected_inputs;
    return probe_point(positions, frame);
  }
  Walk walk{probe_.triangle, {probe_.b1, probe_.b2}, -1};
  Geometry g;
  bool have_g = false;
  int step = 0;
  for (; step < settings_.max_walk_steps; ++step) {
    have_g = geometry(walk.t, positions, frame, g);
    if (!have_g) {
      ++counters_.numerical;
      break;
    }
    const int k_exit = g.flat ? walk_flat(walk, g, target, positions, frame, time) : walk_edge_on(walk, g, target, positions, frame);
    if (k_exit < 0) break;
    cross_edge(walk, k_exit);
  }
  if (step == settings_.max_walk_steps) ++counters_.step_limit_hits;
  probe_ = {walk.t, walk.b[0], walk.b[1]};
  if (!have_g || !geometry(walk.t, positions, frame, g)) return Vec3::Constant(kNaN);
  const Vec3 p = g.at(walk.b);
  if (have_last_event_ && !rearmed_ && (p - last_event_.point_vec()).norm() > rearm_distance()) rearmed_ = true;
  return p;
}

// On a triangle whose shadow is a proper triangle: towards the target's projection on its shadow
// plane, leaving by the edge the straight move crosses first (the first corner weight to reach
// zero). Stops on the edge nearest the target at a fold of the shadow or the mesh's boundary.
int SurfaceExplorer::walk_flat(Walk& walk, const Geometry& g, const Vec3& target, std::span<const Vec4> positions,
                               const Frame<4>& frame, double time) {
  const int t = walk.t;
  Bary& b = walk.b;
  const Vec3 r = target - g.x0;
  const double r1 = g.e1.dot(r), r2 = g.e2.dot(r);
  const Bary goal{(g.g22 * r1 - g.g12 * r2) / g.det, (g.g11 * r2 - g.g12 * r1) / g.det};
  double s_exit = 1;
  int k_exit = -1;
  for (int k = 0; k < 3; ++k) {
    const double w0 = weight(b, k), w1 = weight(goal, k);
    if (w1 < 0) {
      const double s = w0 <= 0 ? 0.0 : w0 / (w0 - w1);
      if (s < s_exit) {
        s_exit = s;
        k_exit = k;
      }
    }
  }
  Bary next = goal;
  if (k_exit >= 0) {
    next = {b[0] + s_exit * (goal[0] - b[0]), b[1] + s_exit * (goal[1] - b[1])};
    snap_to_edge(next, k_exit);
  }
  // Leaving at once by the edge we came in by: both sides pull back, the shadow folds here and
  // the nearest point is on this edge.
  const bool fold = k_exit >= 0 && k_exit == walk.entered && s_exit <= 1e-12;
  const bool boundary = k_exit >= 0 && neighbours_[t][k_exit] < 0;
  if (fold || boundary) {
    crossings_on(g, t, b, next, positions, frame, time);  // up to the edge, then along it
    b = next;
    const int a = (k_exit + 1) % 3, c = (k_exit + 2) % 3;
    const Vec3 xa = g.corner(a), xc = g.corner(c);
    const double len2 = (xc - xa).squaredNorm();
    const double lambda = len2 > 0 ? std::clamp((target - xa).dot(xc - xa) / len2, 0.0, 1.0) : 0.0;
    double w[3] = {0, 0, 0};
    w[a] = 1 - lambda;
    w[c] = lambda;
    next = from_weights(w);
    ++(fold ? counters_.ridge_stops : counters_.boundary_stops);
    k_exit = -1;  // stop here
  }
  crossings_on(g, t, b, next, positions, frame, time);
  b = next;
  return k_exit;
}

// Seen edge-on, the triangle's shadow is a segment (all its edges on one line), so distances cannot
// choose the way on. Leave by the edge whose neighbour has the target on its far side (a flat
// neighbour) or, failing that, into an edge-on neighbour, not back; else stop at the edge point
// nearest the target.
int SurfaceExplorer::walk_edge_on(Walk& walk, const Geometry& g, const Vec3& target, std::span<const Vec4> positions,
                                  const Frame<4>& frame) {
  const int t = walk.t;
  ++counters_.degenerate_passes;
  int best_rank = 3, k_exit = -1;
  double best_d = std::numeric_limits<double>::infinity();
  Bary best_b = walk.b;
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, c = (k + 2) % 3;
    const ClosestPoints<3> cp = point_segment<3>(target, g.corner(a), g.corner(c));
    if (!std::isfinite(cp.distance)) continue;
    const int nb = neighbours_[t][k];
    int rank = 2;  // stop here
    Geometry gn;
    if (k != walk.entered && nb >= 0 && geometry(nb, positions, frame, gn)) {
      if (!gn.flat) {
        rank = 1;
      } else {
        int opposite = 0;  // nb's corner off the shared edge
        for (int j = 0; j < 3; ++j)
          if (triangles_[nb][j] != triangles_[t][a] && triangles_[nb][j] != triangles_[t][c]) opposite = j;
        Bary goal;
        if (plane_bary(gn.x0, gn.e1, gn.e2, target, goal) && weight(goal, opposite) > 0) rank = 0;
      }
    }
    if (rank < best_rank || (rank == best_rank && cp.distance < best_d)) {
      double w[3] = {0, 0, 0};
      w[a] = cp.wb[0];
      w[c] = cp.wb[1];
      best_rank = rank;
      best_d = cp.distance;
      best_b = from_weights(w);
      k_exit = rank < 2 ? k : -1;
    }
  }
  walk.b = best_b;
  return k_exit;
}

// Across edge k_exit into the neighbour of the mesh, whatever lies nearer in the shadow.
void SurfaceExplorer::cross_edge(Walk& walk, int k_exit) {
  const int t = walk.t;
  const int nb = neighbours_[t][k_exit];
  const int a = (k_exit + 1) % 3, c = (k_exit + 2) % 3;
  const int va = triangles_[t][a], vc = triangles_[t][c];
  const double wa = weight(walk.b, a), wc = weight(walk.b, c);
  const Triangle& tn = triangles_[nb];
  double w[3] = {0, 0, 0};
  int third = 0;
  for (int k = 0; k < 3; ++k) {
    if (tn[k] == va) w[k] = wa;
    else if (tn[k] == vc) w[k] = wc;
    else third = k;
  }
  walk.b = from_weights(w);
  walk.t = nb;
  walk.entered = third;
  ++counters_.edges_walked;
}

// [SECTION] Events

void SurfaceExplorer::crossings_on(const Geometry& g, int t, const Bary& a, const Bary& b,
                                   std::span<const Vec4> positions, const Frame<4>& frame, double time) {
  const std::span<const CrossingTable::Entry> entries = table_.of(t);
  const double d1 = b[0] - a[0], d2 = b[1] - a[1];
  if (entries.empty() || (d1 == 0 && d2 == 0)) return;
  struct Hit {
    double s, u;
    const CrossingTable::Entry* e;
  };
  constexpr int kMaxHits = 8;  // per straight move in one triangle; more are emitted unsorted
  std::array<Hit, kMaxHits> hits;
  int n = 0;
  const auto emit_hit = [&](const Hit& h) {
    const Bary p{a[0] + h.s * d1, a[1] + h.s * d2};
    const Bary o{h.e->o[0][0] + h.u * (h.e->o[1][0] - h.e->o[0][0]),
                 h.e->o[0][1] + h.u * (h.e->o[1][1] - h.e->o[0][1])};
    const Triangle& to = triangles_[h.e->other];
    const double w_other = frame.depth_at(std::array<double, 3>{1 - o[0] - o[1], o[0], o[1]}, std::array<double, 3>{
        frame.depth(positions[to[0]]), frame.depth(positions[to[1]]), frame.depth(positions[to[2]])});
    ExplorerEvent e;
    e.time = time;
    e.w_self = g.depth(p);
    e.w_other = w_other;
    e.above = e.w_self > e.w_other;
    e.triangle = t;
    e.other = h.e->other;
    const Vec3 x = g.at(p);
    for (int k = 0; k < 3; ++k) e.point[k] = x[k];
    emit(e);
  };
  for (const CrossingTable::Entry& e : entries) {
    if (e.other < 0) continue;
    const double e1 = e.q[1][0] - e.q[0][0], e2 = e.q[1][1] - e.q[0][1];
    const double len2 = e1 * e1 + e2 * e2;
    if (!(len2 > 0)) continue;
    // Sides of the segment's line at both ends of the move; a point on the line counts as the
    // positive side, so arriving on it and leaving it is one pass, not two.
    const double sa = e1 * (a[1] - e.q[0][1]) - e2 * (a[0] - e.q[0][0]);
    const double sb = e1 * (b[1] - e.q[0][1]) - e2 * (b[0] - e.q[0][0]);
    if ((sa >= 0) == (sb >= 0)) continue;
    const double s = sa / (sa - sb);
    const double p1 = a[0] + s * d1, p2 = a[1] + s * d2;
    const double u = ((p1 - e.q[0][0]) * e1 + (p2 - e.q[0][1]) * e2) / len2;
    if (!(u >= 0 && u <= 1)) continue;
    const Hit h{s, u, &e};
    if (n == kMaxHits) {
      emit_hit(h);
      continue;
    }
    int i = n++;
    for (; i > 0 && hits[i - 1].s > s; --i) hits[i] = hits[i - 1];
    hits[i] = h;
  }
  for (int i = 0; i < n; ++i) emit_hit(hits[i]);
}

double SurfaceExplorer::rearm_distance() const {
  const double tol = 1e-9 * std::max(1.0, table_.shadow_diagonal);  // one pass seen by two segments
  const double h = settings_.rearm_distance >= 0 ? settings_.rearm_distance : 0.002 * table_.shadow_diagonal;
  return std::isfinite(h) ? std::max(h, tol) : tol;
}

void SurfaceExplorer::emit(const ExplorerEvent& e) {
  // A pass near the last one before the probe got away from it is the same pass: seen twice in
  // one move (the shared end of two segments, both sides of a mesh edge the curve crosses there)
  // or the hand trembling across the curve.
  if (have_last_event_ && !rearmed_ && (last_event_.point_vec() - e.point_vec()).norm() <= rearm_distance()) {
    ++counters_.events_merged;
    return;
  }
  have_last_event_ = true;
  rearmed_ = false;
  last_event_ = e;
  ++counters_.events;
  if (!events_.try_push(e)) ++counters_.events_dropped;
}

}  // namespace s4d
