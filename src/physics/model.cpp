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

template <int D>
int ModelBuilder<D>::add_body(const Surface<D>& surface, double mass_per_vertex) {
  int first = 0;
  for (const Surface<D>& b : bodies_) first += static_cast<int>(b.vertices.size());
  require(!surface.vertices.empty() && !surface.triangles.empty(),
          "a body needs vertices and triangles");
  for (const Vec<D>& p : surface.vertices) require(p.allFinite(), "a body has a non-finite vertex");
  const int nv = static_cast<int>(surface.vertices.size());
  for (const Triangle& t : surface.triangles)
    for (int i : t) require(i >= 0 && i < nv, "a triangle uses vertex " + std::to_string(i) +
                                                  " of a body with " + std::to_string(nv));
  require(std::isfinite(mass_per_vertex), "mass must be finite");
  bodies_.push_back(surface);
  masses_.push_back(mass_per_vertex > 0 ? mass_per_vertex : params_.mass);
  return first;
}

template <int D>
Model<D> ModelBuilder<D>::build() const {
  validate(params_);
  require(!bodies_.empty(), "the world has no body");
  Model<D> m;
  m.params = params_;
  m.body_first_vertex.push_back(0);
  m.body_first_triangle.push_back(0);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Surface<D>& s = bodies_[b];
    const int off = m.nv;
    for (const Vec<D>& p : s.vertices) {
      m.initial.push_back(p);
      m.mass.push_back(masses_[b]);
      m.inv_mass.push_back(1.0 / masses_[b]);
    }
    for (const Triangle& t : s.triangles) {
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;  // degenerate: no area, no cell
      m.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
    }
    for (Spring sp : make_springs(s, params_.stiffness, params_.shear_scale, params_.bending_scale)) {
      sp.a += off;
      sp.b += off;
      m.springs.push_back(sp);
    }
    m.nv += static_cast<int>(s.vertices.size());
    m.body_first_vertex.push_back(m.nv);
    m.body_first_triangle.push_back(static_cast<int>(m.triangles.size()));
  }
  if constexpr (D == 4) m.spring_groups = pack_spring_groups(m.springs);
  // CSR adjacency over mesh edges.
  std::vector<std::vector<int>> adj(m.nv);
  for (const Triangle& t : m.triangles)
    for (int c = 0; c < 3; ++c) {
      adj[t[c]].push_back(t[(c + 1) % 3]);
      adj[t[(c + 1) % 3]].push_back(t[c]);
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
  int worst_a = -1, worst_b = -1;
  const std::size_t nt = m.triangles.size();
  std::vector<Box<D>> boxes(nt);
  for (std::size_t t = 0; t < nt; ++t)
    for (int v : m.triangles[t]) boxes[t].add(m.initial[v]);
  Bvh<D> bvh;
  bvh.build(boxes);
  bvh.self_pairs(params_.thickness, [&](int i, int j) {
    const Triangle& a = m.triangles[i];
    const Triangle& b = m.triangles[j];
    for (int u : a)
      for (int w : b)
        if (u == w) return;
    const Simplex<D, 3> sa{m.initial[a[0]], m.initial[a[1]], m.initial[a[2]]};
    const Simplex<D, 3> sb{m.initial[b[0]], m.initial[b[1]], m.initial[b[2]]};
    const double d = triangle_triangle<D>(sa, sb).distance;
    if (d < d_all) {
      d_all = d;
      worst_a = std::min(i, j);
      worst_b = std::max(i, j);
    }
    if (!m.near_adjacent(a, b)) d_far = std::min(d_far, d);
  });
  require(!(d_all <= 1e-9 * params_.thickness),
          "the initial state intersects itself: triangles " + std::to_string(worst_a) + " and " +
              std::to_string(worst_b) + " touch");
  m.contact_thickness = std::min(params_.thickness, 0.9 * d_far);
  m.hard_thickness = std::min(0.25 * m.contact_thickness, 0.5 * d_all);
  return m;
}

#define S4D_INSTANTIATE(D)                                                                    \
  template struct Model<D>;                                                                   \
  template class ModelBuilder<D>;                                                             \
  template std::vector<Spring> make_springs<D>(const Surface<D>&, double, double, double);
S4D_INSTANTIATE(2)
S4D_INSTANTIATE(3)
S4D_INSTANTIATE(4)
#undef S4D_INSTANTIATE

}  // namespace s4d
