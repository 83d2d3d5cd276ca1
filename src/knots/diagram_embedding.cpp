// The drawing: half-edges from the PD code, faces by walking them, the barycentric subdivision
// (crossings, edge midpoints, face centres), Tutte's embedding with the largest simple face
// outside (the next one where that drawing loses a crossing), strands along crossing -> edge
// midpoint -> crossing, depth +-h at each crossing.
// Sections: [SECTION] faces, [SECTION] drawing
#include "knots/diagram_embedding.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>

#include "core/error.hpp"
#include "knots/relax.hpp"
#include "knots/resample.hpp"

namespace s4d {

namespace {

// [SECTION] faces

struct Map {
  int n = 0;                            // crossings
  std::vector<std::array<int, 4>> x;    // PD: edge labels (0-based) counter-clockwise per crossing
  std::vector<int> twin;                // half-edge 4c + s -> the other end of the same edge
  std::vector<int> face;                // half-edge -> face index
  std::vector<std::vector<int>> faces;  // face -> half-edges leaving its corners, in order
};

Map build_map(const KnotDiagram& d) {
  Map m;
  m.n = d.crossing_count();
  for (const auto& q : d.pd()) m.x.push_back({q[0] - 1, q[1] - 1, q[2] - 1, q[3] - 1});
  const int h = 4 * m.n;
  std::vector<std::vector<int>> ends(2 * m.n);
  for (int i = 0; i < h; ++i) ends.at(m.x[i / 4][i % 4]).push_back(i);
  m.twin.assign(h, -1);
  for (const auto& e : ends) {
    if (e.size() != 2) throw Error("the diagram's PD code is inconsistent (an edge without two ends)");
    m.twin[e[0]] = e[1];
    m.twin[e[1]] = e[0];
  }
  // Leaving along half-edge i, arriving at its twin, the face on the right turns clockwise there.
  m.face.assign(h, -1);
  for (int i = 0; i < h; ++i) {
    if (m.face[i] >= 0) continue;
    std::vector<int> cycle;
    int j = i;
    do {
      m.face[j] = static_cast<int>(m.faces.size());
      cycle.push_back(j);
      const int t = m.twin[j];
      j = 4 * (t / 4) + (t % 4 + 3) % 4;
    } while (j != i);
    m.faces.push_back(std::move(cycle));
  }
  return m;
}

// [SECTION] drawing

struct Drawing {
  std::vector<Vec2> crossing, edge;  // positions of crossing nodes and edge midpoints
};

// The faces that may go outside, largest first: those whose corners are distinct crossings.
std::vector<int> outer_faces(const Map& m) {
  std::vector<int> out;
  for (int f = 0; f < static_cast<int>(m.faces.size()); ++f) {
    std::set<int> corners;
    for (int i : m.faces[f]) corners.insert(i / 4);
    if (corners.size() == m.faces[f].size()) out.push_back(f);
  }
  std::stable_sort(out.begin(), out.end(), [&](int a, int b) { return m.faces[a].size() > m.faces[b].size(); });
  if (out.empty()) throw Error("the diagram has no face to draw outside (it is not reduced enough to draw)");
  return out;
}

Drawing tutte(const Map& m, int outer) {
  const int nc = m.n, ne = 2 * m.n, nf = static_cast<int>(m.faces.size());
  const int nodes = nc + ne + nf;
  std::vector<std::set<int>> adj(nodes);
  auto link = [&](int a, int b) {
    if (a == b) return;
    adj[a].insert(b);
    adj[b].insert(a);
  };
  for (int i = 0; i < 4 * nc; ++i) {
    const int c = i / 4, e = nc + m.x[c][i % 4], f = nc + ne + m.face[i];
    link(c, e);
    link(c, f);
    link(e, f);
  }
  std::vector<int> fixed_at(nodes, -1);
  std::vector<Vec2> pos(nodes, Vec2::Zero());
  std::vector<int> ring;
  for (int i : m.faces[outer]) {
    ring.push_back(i / 4);
    ring.push_back(nc + m.x[i / 4][i % 4]);
  }
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const double a = -2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(ring.size());
    fixed_at[ring[k]] = static_cast<int>(k);
    pos[ring[k]] = Vec2(std::cos(a), std::sin(a));
  }
  const int outer_node = nc + ne + outer;
  // Every other node sits at the mean of its neighbours (the outer face's centre is left out).
  std::vector<int> var(nodes, -1);
  int nv = 0;
  for (int v = 0; v < nodes; ++v)
    if (fixed_at[v] < 0 && v != outer_node) var[v] = nv++;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(nv, nv);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(nv, 2);
  for (int v = 0; v < nodes; ++v) {
    if (var[v] < 0) continue;
    for (int u : adj[v]) {
      if (u == outer_node) continue;
      a(var[v], var[v]) += 1;
      if (var[u] >= 0)
        a(var[v], var[u]) -= 1;
      else
        b.row(var[v]) += pos[u].transpose();
    }
  }
  const Eigen::MatrixXd sol = a.partialPivLu().solve(b);
  for (int v = 0; v < nodes; ++v)
    if (var[v] >= 0) pos[v] = sol.row(var[v]).transpose();
  Drawing dr;
  dr.crossing.assign(pos.begin(), pos.begin() + nc);
  dr.edge.assign(pos.begin() + nc, pos.begin() + nc + ne);
  return dr;
}

// The curve of the drawing: strands through the nodes, lifted at the crossings, checked against
// the diagram (throws Error when a crossing was lost or its sign disagrees), resampled, relaxed.
Curve<3> draw(const KnotDiagram& d, const Map& m, const Drawing& dr, const DiagramEmbedding& options);

}  // namespace

Curve<3> curve_from_diagram(const KnotDiagram& d, const DiagramEmbedding& options) {
  if (d.component_count() == 0) throw Error("the diagram has no components");
  if (d.crossing_count() == 0) {
    if (d.component_count() != 1)
      throw Error("a crossing-free diagram of several circles is a split unlink; draw each circle apart");
    Polyline<3> c{{}, true};
    for (int i = 0; i < 64; ++i) {
      const double t = 2 * std::numbers::pi * i / 64;
      c.points.emplace_back(std::cos(t), std::sin(t), 0.0);
    }
    Curve<3> out;
    out.components.push_back(std::move(c));
    return out;
  }
  for (const auto& comp : d.components)
    if (comp.empty()) throw Error("a component without crossings cannot be drawn with the others");
  const Map m = build_map(d);
  if (static_cast<int>(m.faces.size()) != m.n + 2)
    throw Error("the diagram is not planar or not connected (" + std::to_string(m.faces.size()) +
                " faces for " + std::to_string(m.n) + " crossings; a connected planar one has " +
                std::to_string(m.n + 2) + ")");
  // The largest face outside draws best; where its drawing lines strands up so that a crossing is
  // lost (a few census diagrams, such as 7_7's), the next face is tried.
  std::optional<Error> first;
  for (int outer : outer_faces(m)) {
    try {
      return draw(d, m, tutte(m, outer), options);
    } catch (const Error& e) {
      if (!first) first = e;
    }
  }
  throw *first;
}

namespace {

Curve<3> draw(const KnotDiagram& d, const Map& m, const Drawing& dr, const DiagramEmbedding& options) {

  // Edge numbering of pd(): along each component, edge k leaves passage k.
  std::vector<int> out_edge(d.passages.size());
  int next = 0;
  for (const auto& comp : d.components)
    for (std::size_t k = 0; k < comp.size(); ++k) out_edge[comp[k]] = next++;
  // The lift: small against the drawing's finest feature, so strands cross only where they should.
  double finest = 1e9;
  for (int e = 0; e < 2 * m.n; ++e)
    for (int c = 0; c < m.n; ++c) finest = std::min(finest, (dr.edge[e] - dr.crossing[c]).norm());
  const double h = std::max(0.25 * finest, 1e-6);
  // Per passage: the crossing (the under strand's vertex nudged a little along its way out, so the
  // two strands never share a vertex), halfway to the edge's midpoint, the midpoint, and halfway
  // on to the next crossing, with the depth +-h at the crossing fading to 0 at the midpoint.
  auto build = [&](double flip) {
    Curve<3> curve;
    for (const auto& comp : d.components) {
      Polyline<3> pl{{}, true};
      const std::size_t k = comp.size();
      for (std::size_t i = 0; i < k; ++i) {
        const Passage& v = d.passages[comp[i]];
        const Passage& w = d.passages[comp[(i + 1) % k]];
        const Vec2 c = dr.crossing[v.crossing], e = dr.edge[out_edge[comp[i]]];
        const Vec2 c2 = dr.crossing[w.crossing];
        const double z = v.over ? h : -h, z2 = w.over ? h : -h;
        const Vec2 at = v.over ? c : Vec2(c + 0.05 * (e - c));
        auto put = [&](const Vec2& q, double depth) { pl.points.emplace_back(flip * q.x(), q.y(), depth); };
        put(at, z);
        put(0.5 * (c + e), 0.3 * z);
        put(e, 0.0);
        put(0.5 * (e + c2), 0.3 * z2);
      }
      curve.components.push_back(std::move(pl));
    }
    return curve;
  };
  // The drawing may come out as the mirror image of the diagram (which way round the outer face
  // goes is a choice): match the drawn crossings to the nodes, compare signs, reflect if needed.
  auto signs_agree = [&](const Curve<3>& curve) {
    Frame<3> used;
    const KnotDiagram drawn = diagram_from_curve(curve, Frame<3>(), {}, &used);
    if (drawn.crossing_count() != d.crossing_count())
      throw Error("internal: the drawing has " + std::to_string(drawn.crossing_count()) +
                  " crossings, the diagram " + std::to_string(d.crossing_count()));
    int agree = 0;
    for (int c = 0; c < d.crossing_count(); ++c) {
      int best = 0;
      for (int k = 1; k < drawn.crossing_count(); ++k)
        if ((drawn.crossings[k].point - dr.crossing[c]).norm() <
            (drawn.crossings[best].point - dr.crossing[c]).norm())
          best = k;
      agree += drawn.crossings[best].sign == d.crossings[c].sign ? 1 : 0;
    }
    return agree;
  };
  Curve<3> curve = build(1.0);
  const int agree = signs_agree(curve);
  if (agree != d.crossing_count()) {
    if (agree != 0) throw Error("internal: the drawing's crossing signs disagree with the diagram's");
    curve = build(-1.0);
  }
  const int points = std::max(60, options.points_per_crossing * d.crossing_count());
  curve = resample_curve_to_count(curve, points);
  if (options.relax_iterations > 0) curve = relax(curve, options.relax_iterations);
  return curve;
}

}  // namespace

}  // namespace s4d
