// Model<D>: what does not change during a run (masses, springs, collision cells, parameters), built
// once from one or more surfaces or curves; the physics kernels read it and write only Data<D>
// (see world.hpp). A knot is a chain in World<3>: its edges are structural springs, (i, i+2) pairs
// bending springs, and its segments the collision cells.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/vec.hpp"
#include "shape/curve.hpp"
#include "shape/surface.hpp"

namespace s4d {

enum class Integrator {
  kPaperEuler,       // Eq. 4 of the paper, one update per tick, no stability control
  kSymplecticEuler,  // the same update, substepped below a stability bound (default)
};
// "paper-euler" / "explicit-euler" and "symplectic-euler"; throws s4d::Error for anything else.
Integrator parse_integrator(std::string_view name);
const char* integrator_name(Integrator integrator);

enum class SpringKind : std::uint8_t { kStructural, kShear, kBending };

// One spring of the generalised Hooke law (paper Eq. 1): F = k |e|^(1+β) ê, e = length - rest.
struct Spring {
  int a = 0, b = 0;      // vertex indices
  double rest = 0;       // rest length, m
  double k = 0;          // stiffness, N/m^(1+β)
  SpringKind kind = SpringKind::kStructural;
};

// Four linear springs as the R^4 AVX kernel reads them (see spring_forces.hpp): the ends as byte
// offsets into an array of Vec<4> (one address computation fewer per load), stiffness and rest
// length in the lanes of the kernel's sums (springs 0, 2, 1, 3), loaded in one instruction each.
// A strided group (a grid's springs of one direction: ends a[0] + j and b[0] + j points) is read
// from a[0] and b[0] alone, its twenty-four other addresses fixed displacements from those two.
struct alignas(32) SpringGroup4 {
  double k[4];              // N/m, lane order 0, 2, 1, 3
  double rest[4];           // m, lane order 0, 2, 1, 3
  std::int32_t a[4], b[4];  // bytes, spring order
  std::int32_t strided = 0;  // 1: a[j] = a[0] + j·sizeof(Vec<4>), and the same for b
};

template <int D>
struct PhysicsParams {
  double time_step = 1e-3;            // s, the haptic tick
  double thickness = 0.02;            // δ, m: contact layer kept by repulsion
  Vec<D> gravity = Vec<D>::Zero();    // m/s², any direction of R^D
  double mass = 1e-3;                 // kg per vertex (ModelBuilder may override per body)
  double stiffness = 50;              // N/m^(1+β), structural springs
  double shear_scale = 0.5;           // shear stiffness = shear_scale × stiffness
  double bending_scale = 0.1;         // bending stiffness = bending_scale × stiffness
  double beta = 0;                    // exponent of paper Eq. 1 (0 = linear spring)
  double damping = 0.02;              // N·s/m, paper Eq. 2 on every vertex velocity
  double spring_damping = 0.02;       // N·s/m, along each spring on the relative velocity
  double friction = 0.3;              // Coulomb coefficient between touching surfaces (0 = slippery)
  Integrator integrator = Integrator::kSymplecticEuler;
  bool collisions = true;             // self- and mutual collision avoidance
  int collision_iterations = 4;       // Gauss-Seidel sweeps of the contact impulses
  // Contact pairs kept from step to step and carried along their normals (physics/contact_cache);
  // false: every pair found and solved afresh each step (the path before, kept to compare with).
  bool persistent_contacts = true;
  int ccd_passes = 6;                 // fail-safe passes before the global freeze
  double max_speed = 200;             // m/s: a faster vertex means the step exploded (rolled back)
  double max_step_motion = 0;         // m per step, 0 = δ (the paper clamps motion per frame to δ)
  int max_substeps = 256;             // cap of the symplectic substep count
};

// A curve's edge: two vertex indices (its collision cell).
using Segment = std::array<int, 2>;

// Where a segment lies along its curve component (a chain): segments a few edges apart along it
// touch through the chain itself, so the springs keep them apart, not the repulsion.
struct ChainPlace {
  int chain = 0;  // the component, counted over the model's curves
  int index = 0;  // the segment's index along it
};
struct Chain {
  int segments = 0;   // its segment count
  bool closed = true;
  int exclusion = 1;  // segments at most this many apart along it are left to the springs
};
// A chain of `segments` segments and `length` at contact thickness δ: segments closer along it
// than about 1.5 δ (counted in mean edges) are left to its springs, the ring pairs at least.
Chain make_chain(int segments, bool closed, double length, double thickness);
// Whether segments s and t lie on one chain at most its exclusion apart along it.
inline bool chain_near(const std::vector<ChainPlace>& places, const std::vector<Chain>& chains, int s, int t) {
  const ChainPlace& p = places[static_cast<std::size_t>(s)];
  const ChainPlace& q = places[static_cast<std::size_t>(t)];
  if (p.chain != q.chain) return false;
  const Chain& c = chains[static_cast<std::size_t>(p.chain)];
  int gap = p.index > q.index ? p.index - q.index : q.index - p.index;
  if (c.closed) gap = std::min(gap, c.segments - gap);
  return gap <= c.exclusion;
}

template <int D>
struct Model {
  PhysicsParams<D> params;
  int nv = 0;                              // vertices
  std::vector<double> mass;                // nv, kg
  std::vector<double> inv_mass;            // nv, 1/kg
  std::vector<Vec<D>> initial;             // nv × D, positions at build time
  std::vector<Spring> springs;             // ns
  std::vector<SpringGroup4> spring_groups; // ns / 4 (D = 4): springs[4g .. 4g+3] packed for AVX
  // The collision cells: triangles of surface bodies or segments of curve bodies (a world holds
  // one kind; ModelBuilder refuses a mix).
  std::vector<Triangle> triangles;         // nt × 3, global vertex indices
  std::vector<Segment> segments;           // nsg × 2, global vertex indices
  std::vector<ChainPlace> segment_place;   // nsg
  std::vector<Chain> chains;               // curve components
  std::vector<int> body_first_vertex;      // nb + 1, vertices of body b are [first[b], first[b+1])
  std::vector<int> body_first_triangle;    // nb + 1, same for triangles
  std::vector<int> body_first_segment;     // nb + 1, same for segments
  std::vector<int> adjacency_offset;       // nv + 1, CSR over mesh (or curve) edges
  std::vector<int> adjacency;              // 2 × mesh edges, sorted within each vertex
  double contact_thickness = 0;            // δ actually used (≤ params.thickness, below rest gaps)
  double hard_thickness = 0;               // η < δ: the continuous fail-safe keeps every gap above it
  double omega_max = 0;                    // rad/s, Gershgorin bound of sqrt(λ_max(M⁻¹K)) for β = 0
  double damping_rate = 0;                 // 1/s, bound of the damping matrix's M⁻¹C row sums

  int body_count() const { return static_cast<int>(body_first_vertex.size()) - 1; }
  bool mesh_adjacent(int i, int j) const;  // i and j joined by a mesh edge
  // Cells sharing a vertex or joined by a mesh edge: kept apart by springs, not by repulsion.
  bool near_adjacent(const Triangle& a, const Triangle& b) const;
  // Segments s and t of one chain at most its exclusion apart along it: kept apart by springs.
  bool chain_near(int s, int t) const { return s4d::chain_near(segment_place, chains, s, t); }
  bool curves() const { return !segments.empty(); }
  // Symplectic substeps needed for a tick dt (1 for the paper's integrator).
  int substeps(double dt) const;
};

// A body: a surface, or a curve (one chain a component; a link has several).
template <int D>
using Body = std::variant<Surface<D>, Curve<D>>;

// Builds a Model from surfaces or from curves. Springs: for a surface with a grid, the paper's
// structural, shear and bending springs; without one, mesh edges plus one bending spring across
// every edge shared by two triangles; for a curve, its edges and the (i, i+2) bending springs.
// Throws s4d::Error on bad parameters, bad meshes or curves, surfaces and curves together, or an
// initial state in which two cells sharing no vertex already touch.
template <int D>
class ModelBuilder {
 public:
  explicit ModelBuilder(PhysicsParams<D> params) : params_(std::move(params)) {}
  // Adds a body; mass_per_vertex <= 0 takes params.mass. Returns the index of its first vertex
  // (a curve's vertices are its components' points in order).
  int add_body(const Surface<D>& surface, double mass_per_vertex = 0);
  int add_body(const Curve<D>& curve, double mass_per_vertex = 0);
  int add_body(const Body<D>& body, double mass_per_vertex = 0);
  Model<D> build() const;

 private:
  int next_vertex() const;
  // Keeps a checked body; returns its first vertex.
  int take(Body<D> body, double mass_per_vertex);
  PhysicsParams<D> params_;
  std::vector<Body<D>> bodies_;
  std::vector<double> masses_;
};

// The springs of one surface (vertex indices local to it); exposed for tests.
template <int D>
std::vector<Spring> make_springs(const Surface<D>& surface, double k, double shear_scale,
                                 double bending_scale);
// A curve's springs: every edge, and (i, i+2) for bending, each pair once.
template <int D>
std::vector<Spring> make_springs(const Curve<D>& curve, double k, double bending_scale);

// A curve body's vertex count (its components' points).
template <int D>
int body_vertex_count(const Body<D>& body);

}  // namespace s4d
