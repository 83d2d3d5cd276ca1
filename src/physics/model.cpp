// Building the immutable Model: springs of the paper's three kinds, CSR adjacency, stability
// bounds, and the contact thicknesses checked against the initial state.
#include "physics/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "core/error.hpp"
#include "physics/spring_forces.hpp"
#include "proximity/bvh.hpp"
#include "proximity/closest_points.hpp"
#include "proximity/separating_axes.hpp"
#include "proximity/smallest_within.hpp"
#include "shape/topology.hpp"

namespace s4d {

Integrator parse_integrator(std::string_view name) {
  if (name == "symplectic-euler") return Integrator::kSymplecticEuler;
  if (name == "paper-euler" || name == "explicit-euler") return Integrator::kPaperEuler;
  throw Error("unknown integrator '" + std::string(name) +
              "' (known: symplectic-euler, paper-euler)");
}

const char* integrator_name(Integrator integrator) {
  return integrator == Integrator::kPaperEuler ? "paper-euler" : "symplectic-euler";
}

namespace {

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

template <int D>
void grid_springs(const Surface<D>& s, const Grid& g, double k, double shear, double bend,
                  std::vector<Spring>& out) {
  std::unordered_set<std::uint64_t> seen;
  auto add = [&](int i0, int j0, int i1, int j1, SpringKind kind, double stiffness) {
    if (!g.wrap_i && (i1 < 0 || i1 >= g.rows)) return;
    if (!g.wrap_j && (j1 < 0 || j1 >= g.cols)) return;
    i1 = (i1 + g.rows) % g.rows;
    j1 = (j1 + g.cols) % g.cols;
    const int a = g.index(i0, j0), b = g.index(i1, j1);
    if (a == b || !seen.insert(edge_key(a, b)).second) return;
    out.push_back({a, b, (s.vertices[a] - s.vertices[b]).norm(), stiffness, kind});
  };
  // Kinds in order, so that a wrapped short grid keeps the stiffer kind of a repeated pair; within
  // a kind one direction at a time, so that runs of springs have consecutive first ends and one
  // offset to the other (the R^4 kernel reads such a group of four without an index).
  const auto each = [&](int di, int dj, SpringKind kind, double stiffness) {
    for (int i = 0; i < g.rows; ++i)
      for (int j = 0; j < g.cols; ++j) add(i, j, i + di, j + dj, kind, stiffness);
  };
  each(1, 0, SpringKind::kStructural, k);
  each(0, 1, SpringKind::kStructural, k);
  each(1, 1, SpringKind::kShear, shear);
  // The other diagonal, from (i + 1, j) up to (i, j + 1).
  for (int i = 0; i < g.rows; ++i)
    for (int j = 0; j < g.cols; ++j)
      if (g.wrap_i || i + 1 < g.rows) add((i + 1) % g.rows, j, i, j + 1, SpringKind::kShear, shear);
  each(2, 0, SpringKind::kBending, bend);
  each(0, 2, SpringKind::kBending, bend);
}

template <int D>
void mesh_springs(const Surface<D>& s, double k, double bend, std::vector<Spring>& out) {
  const std::vector<MeshEdge> edges = mesh_edges(s.triangles);
  std::unordered_set<std::uint64_t> seen;
  for (const MeshEdge& e : edges) {
    seen.insert(edge_key(e.a, e.b));
    out.push_back({e.a, e.b, (s.vertices[e.a] - s.vertices[e.b]).norm(), k,
                   SpringKind::kStructural});
  }
  // Bending: the two vertices opposite an edge shared by exactly two triangles.
  std::unordered_map<std::uint64_t, std::vector<int>> opposite;
  for (const Triangle& t : s.triangles)
    for (int c = 0; c < 3; ++c) opposite[edge_key(t[c], t[(c + 1) % 3])].push_back(t[(c + 2) % 3]);
  std::vector<std::pair<std::uint64_t, std::vector<int>>> sorted(opposite.begin(), opposite.end());
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [key, opp] : sorted) {
    if (opp.size() != 2 || opp[0] == opp[1]) continue;
    if (!seen.insert(edge_key(opp[0], opp[1])).second) continue;
    out.push_back({opp[0], opp[1], (s.vertices[opp[0]] - s.vertices[opp[1]]).norm(), bend,
                   SpringKind::kBending});
  }
}

void require(bool ok, const std::string& message) {
  if (!ok) throw Error("physics: " + message);
}

template <int D>
void validate(const PhysicsParams<D>& p) {
  auto finite_pos = [](double x) { return std::isfinite(x) && x > 0; };
  auto finite_nonneg = [](double x) { return std::isfinite(x) && x >= 0; };
  require(finite_pos(p.time_step), "time_step must be a positive number of seconds");
  require(finite_pos(p.thickness), "thickness must be positive");
  require(p.gravity.allFinite(), "gravity must be finite");
  require(finite_pos(p.mass), "mass must be positive");
  require(finite_nonneg(p.stiffness), "stiffness must be >= 0");
  require(finite_nonneg(p.shear_scale) && finite_nonneg(p.bending_scale),
          "shear and bending scales must be >= 0");
  require(std::isfinite(p.beta) && p.beta >= 0 && p.beta <= 4, "beta must be in [0, 4]");
  require(finite_nonneg(p.damping) && finite_nonneg(p.spring_damping), "damping must be >= 0");
  require(finite_nonneg(p.friction), "friction must be >= 0");
  require(p.collision_iterations >= 1 && p.collision_iterations <= 100,
          "collision_iterations must be in [1, 100]");
  require(p.ccd_passes >= 1 && p.ccd_passes <= 100, "ccd_passes must be in [1, 100]");
  require(finite_pos(p.max_speed), "max_speed must be positive");
  require(finite_nonneg(p.max_step_motion), "max_step_motion must be >= 0");
  require(p.max_substeps >= 1 && p.max_substeps <= 100000, "max_substeps must be >= 1");
}

}  // namespace

template <int D>
std::vector<Spring> make_springs(const Surface<D>& surface, double k, double shear_scale,
                                 double bending_scale) {
  std::vector<Spring> out;
  const bool grid_ok = surface.grid && surface.grid->rows >= 2 && surface.grid->cols >= 2 &&
                       static_cast<std::size_t>(surface.grid->rows) * surface.grid->cols ==
                           surface.vertices.size();
  if (grid_ok)
    grid_springs(surface, *surface.grid, k, k * shear_scale, k * bending_scale, out);
  else
    mesh_springs(surface, k, k * bending_scale, out);
  return out;
}

template <int D>
bool Model<D>::mesh_adjacent(int i, int j) const {
  const auto first = adjacency.begin() + adjacency_offset[i];
  const auto last = adjacency.begin() + adjacency_offset[i + 1];
  return std::binary_search(first, last, j);
}

template <int D>
bool Model<D>::near_adjacent(const Triangle& a, const Triangle& b) const {
  for (int i : a)
    for (int j : b)
      if (i == j || mesh_adjacent(i, j)) return true;
  return false;
}

template <int D>
int Model<D>::substeps(double dt) const {
  if (params.integrator == Integrator::kPaperEuler) return 1;
  // Symplectic Euler is stable for h·ω < 2; we keep h·ω <= 1 and h·(damping rate) <= 0.5.
  const double n = std::max(dt * omega_max, 2 * dt * damping_rate);
  if (!std::isfinite(n)) return params.max_substeps;
  return std::clamp(static_cast<int>(std::ceil(n)), 1, params.max_substeps);
}

Chain make_chain(int segments, bool closed, double length, double thickness) {
  Chain chain;
  chain.segments = segments;
  chain.closed = closed;
  const double reach = std::floor(1 + 1.5 * thickness / (length / std::max(segments, 1)));
  chain.exclusion = static_cast<int>(std::clamp(std::isfinite(reach) ? reach : 2.0, 2.0, std::max(2.0, segments / 4.0)));
  return chain;
}

template <int D>
std::vector<Spring> make_springs(const Curve<D>& curve, double k, double bending_scale) {
  std::vector<Spring> out;
  std::unordered_set<std::uint64_t> seen;
  int first = 0;
  for (const Polyline<D>& c : curve.components) {
    const int n = static_cast<int>(c.points.size());
    auto add = [&](int i, int step, SpringKind kind, double stiffness) {
      const int j = i + step;
      if (!c.closed && j >= n) return;
      const int a = first + i, b = first + j % n;
      if (a == b || !seen.insert(edge_key(a, b)).second) return;
      out.push_back({a, b, (c.points[static_cast<std::size_t>(i)] - c.points[static_cast<std::size_t>(j % n)]).norm(),
                     stiffness, kind});
    };
    // Kinds in order, as on a grid: a short closed chain keeps the stiffer kind of a repeated pair.
    for (int i = 0; i < n; ++i) add(i, 1, SpringKind::kStructural, k);
    for (int i = 0; i < n; ++i) add(i, 2, SpringKind::kBending, k * bending_scale);
    first += n;
  }
  return out;
}

template <int D>
int body_vertex_count(const Body<D>& body) {
  if (const auto* s = std::get_if<Surface<D>>(&body)) return static_cast<int>(s->vertices.size());
  return static_cast<int>(std::get<Curve<D>>(body).point_count());
}

template <int D>
int ModelBuilder<D>::next_vertex() const {
  int first = 0;
  for (const Body<D>& b : bodies_) first += body_vertex_count(b);
  return first;
}

template <int D>
int ModelBuilder<D>::take(Body<D> body, double mass_per_vertex) {
  require(std::isfinite(mass_per_vertex), "mass must be finite");
  const int first = next_vertex();
  bodies_.push_back(std::move(body));
  masses_.push_back(mass_per_vertex > 0 ? mass_per_vertex : params_.mass);
  return first;
}

template <int D>
int ModelBuilder<D>::add_body(const Surface<D>& surface, double mass_per_vertex) {
  require(!surface.vertices.empty() && !surface.triangles.empty(),
          "a body needs vertices and triangles");
  for (const Vec<D>& p : surface.vertices) require(p.allFinite(), "a body has a non-finite vertex");
  const int nv = static_cast<int>(surface.vertices.size());
  for (const Triangle& t : surface.triangles)
    for (int i : t) require(i >= 0 && i < nv, "a triangle uses vertex " + std::to_string(i) +
                                                  " of a body with " + std::to_string(nv));
  return take(surface, mass_per_vertex);
}

template <int D>
int ModelBuilder<D>::add_body(const Curve<D>& curve, double mass_per_vertex) {
  require(!curve.components.empty(), "a curve body needs a component");
  for (const Polyline<D>& c : curve.components) {
    const std::size_t n = c.points.size();
    require(n >= (c.closed ? 3u : 2u), std::string("a ") + (c.closed ? "closed" : "open") +
                                           " curve component needs at least " + (c.closed ? "3" : "2") +
                                           " points, not " + std::to_string(n));
    for (const Vec<D>& p : c.points) require(p.allFinite(), "a curve has a non-finite point");
    for (std::size_t k = 0; k < c.segment_count(); ++k)
      require(c.seg_a(k) != c.seg_b(k), "a curve has two equal consecutive points (point " + std::to_string(k) +
                                            "): no direction for its spring");
  }
  return take(curve, mass_per_vertex);
}

template <int D>
int ModelBuilder<D>::add_body(const Body<D>& body, double mass_per_vertex) {
  return std::visit([&](const auto& b) { return add_body(b, mass_per_vertex); }, body);
}

namespace {

template <int D>
void add_vertices(Model<D>& m, const std::vector<Vec<D>>& points, double mass) {
  for (const Vec<D>& p : points) {
    m.initial.push_back(p);
    m.mass.push_back(mass);
    m.inv_mass.push_back(1.0 / mass);
  }
}

// A chain's segments and where each lies along it.
template <int D>
void add_chains(Model<D>& m, const Curve<D>& curve, int off, double thickness) {
  for (const Polyline<D>& c : curve.components) {
    const int n = static_cast<int>(c.points.size());
    const Chain chain = make_chain(static_cast<int>(c.segment_count()), c.closed, c.length(), thickness);
    const int id = static_cast<int>(m.chains.size());
    m.chains.push_back(chain);
    for (int k = 0; k < chain.segments; ++k) {
      m.segments.push_back({off + k, off + (k + 1) % n});
      m.segment_place.push_back({id, k});
    }
    off += n;
  }
}

// Two cells as simplices, for the kernels of proximity/.
template <int D, std::size_t K>
Simplex<D, static_cast<int>(K)> cell_simplex(const std::vector<Vec<D>>& x, const std::array<int, K>& c) {
  Simplex<D, static_cast<int>(K)> s;
  for (std::size_t i = 0; i < K; ++i) s[i] = x[c[i]];
  return s;
}

// The closest distance of two cells sharing no vertex, by the same kernel as ever for triangles.
template <int D>
double cell_distance(const Simplex<D, 3>& a, const Simplex<D, 3>& b) {
  return triangle_triangle<D>(a, b).distance;
}
template <int D>
double cell_distance(const Simplex<D, 2>& a, const Simplex<D, 2>& b) {
  return segment_segment<D>(a[0], a[1], b[0], b[1]).distance;
}

// The smallest gap of any two cells sharing no vertex (d_all) and of those the springs do not
// keep apart (d_far), within `search`; the pair of d_all in worst. On a mesh much finer than
// `search` one pass at it tests hundreds of pairs a cell, so the radius doubles from a small one
// (proximity/smallest_within.hpp): d_far >= d_all, so the pass that finds d_far has the pair of
// d_all too. The last pass, at `search`, keeps what its candidates give beyond it, as one pass did.
template <int D, std::size_t K, class Near>
void initial_gaps(const Model<D>& m, const std::vector<std::array<int, K>>& cells, double search, Near near,
                  double& d_all, double& d_far, std::array<int, 2>& worst) {
  constexpr int k = static_cast<int>(K);
  const std::size_t nc = cells.size();
  std::vector<Box<D>> boxes(nc);
  for (std::size_t t = 0; t < nc; ++t)
    for (int v : cells[t]) boxes[t].add(m.initial[v]);
  Bvh<D> bvh;
  bvh.build(boxes);
  smallest_within(search, [&](double r) {
    const bool last = r >= search;
    d_all = d_far = std::numeric_limits<double>::infinity();
    worst = {-1, -1};
    bvh.self_pairs(r, [&](int i, int j) {
      const auto& a = cells[i];
      const auto& b = cells[j];
      for (int u : a)
        for (int w : b)
          if (u == w) return;
      const Simplex<D, k> sa = cell_simplex<D, K>(m.initial, a), sb = cell_simplex<D, K>(m.initial, b);
      if (!last && provably_farther<D, k, k>(sa, sb, r)) return;
      const double d = cell_distance<D>(sa, sb);
      if (d < d_all) {
        d_all = d;
        worst = {std::min(i, j), std::max(i, j)};
      }
      if (!near(i, j)) d_far = std::min(d_far, d);
    });
    return d_far;
  });
}

}  // namespace

template <int D>
Model<D> ModelBuilder<D>::build() const {
  validate(params_);
  require(!bodies_.empty(), "the world has no body");
  bool any_surface = false, any_curve = false;
  for (const Body<D>& b : bodies_) (std::holds_alternative<Surface<D>>(b) ? any_surface : any_curve) = true;
  require(!(any_surface && any_curve), "a world holds surfaces or curves, not both");
  Model<D> m;
  m.params = params_;
  m.body_first_vertex.push_back(0);
  m.body_first_triangle.push_back(0);
  m.body_first_segment.push_back(0);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const int off = m.nv;
    std::vector<Spring> springs;
    if (const auto* curve = std::get_if<Curve<D>>(&bodies_[b])) {
      for (const Polyline<D>& c : curve->components) add_vertices(m, c.points, masses_[b]);
      add_chains(m, *curve, off, params_.thickness);
      springs = make_springs(*curve, params_.stiffness, params_.bending_scale);
    } else {
      const Surface<D>& s = std::get<Surface<D>>(bodies_[b]);
      add_vertices(m, s.vertices, masses_[b]);
      for (const Triangle& t : s.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;  // degenerate: no area, no cell
        m.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
      }
      springs = make_springs(s, params_.stiffness, params_.shear_scale, params_.bending_scale);
    }
    for (Spring sp : springs) {
      sp.a += off;
      sp.b += off;
      m.springs.push_back(sp);
    }
    m.nv += body_vertex_count(bodies_[b]);
    m.body_first_vertex.push_back(m.nv);
    m.body_first_triangle.push_back(static_cast<int>(m.triangles.size()));
    m.body_first_segment.push_back(static_cast<int>(m.segments.size()));
  }
  if constexpr (D == 4) m.spring_groups = pack_spring_groups(m.springs);
  // CSR adjacency over mesh (or curve) edges.
  std::vector<std::vector<int>> adj(m.nv);
  for (const Triangle& t : m.triangles)
    for (int c = 0; c < 3; ++c) {
      adj[t[c]].push_back(t[(c + 1) % 3]);
      adj[t[(c + 1) % 3]].push_back(t[c]);
    }
  for (const Segment& s : m.segments) {
    adj[s[0]].push_back(s[1]);
    adj[s[1]].push_back(s[0]);
  }
  m.adjacency_offset.push_back(0);
  for (auto& a : adj) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    m.adjacency.insert(m.adjacency.end(), a.begin(), a.end());
    m.adjacency_offset.push_back(static_cast<int>(m.adjacency.size()));
  }
  // Stability bounds (Gershgorin row sums of M⁻¹K and M⁻¹C; β = 0 stiffness, see substeps()).
  std::vector<double> ksum(m.nv, 0.0), csum(m.nv, 0.0);
  for (const Spring& s : m.springs) {
    ksum[s.a] += s.k;
    ksum[s.b] += s.k;
    csum[s.a] += params_.spring_damping;
    csum[s.b] += params_.spring_damping;
  }
  for (int i = 0; i < m.nv; ++i) {
    m.omega_max = std::max(m.omega_max, std::sqrt(2 * ksum[i] * m.inv_mass[i]));
    m.damping_rate = std::max(m.damping_rate, (params_.damping + 2 * csum[i]) * m.inv_mass[i]);
  }
  // Thicknesses: the contact layer must lie below every rest gap that springs do not guard, and
  // the hard layer below every gap at all, or the first step would already be "in contact".
  double d_all = std::numeric_limits<double>::infinity(), d_far = d_all;
  std::array<int, 2> worst{-1, -1};
  if (any_curve) {
    initial_gaps(m, m.segments, params_.thickness, [&](int i, int j) { return m.chain_near(i, j); }, d_all, d_far,
                 worst);
  } else {
    initial_gaps(m, m.triangles, params_.thickness,
                 [&](int i, int j) { return m.near_adjacent(m.triangles[i], m.triangles[j]); }, d_all, d_far, worst);
  }
  require(!(d_all <= 1e-9 * params_.thickness),
          std::string("the initial state intersects itself: ") + (any_curve ? "segments " : "triangles ") +
              std::to_string(worst[0]) + " and " + std::to_string(worst[1]) + " touch");
  m.contact_thickness = std::min(params_.thickness, 0.9 * d_far);
  m.hard_thickness = std::min(0.25 * m.contact_thickness, 0.5 * d_all);
  return m;
}

#define S4D_INSTANTIATE(D)                                                                    \
  template struct Model<D>;                                                                   \
  template class ModelBuilder<D>;                                                             \
  template std::vector<Spring> make_springs<D>(const Surface<D>&, double, double, double);      \
  template std::vector<Spring> make_springs<D>(const Curve<D>&, double, double);               \
  template int body_vertex_count<D>(const Body<D>&);
S4D_INSTANTIATE(2)
S4D_INSTANTIATE(3)
S4D_INSTANTIATE(4)
#undef S4D_INSTANTIATE

}  // namespace s4d
