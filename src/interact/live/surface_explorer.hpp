// SurfaceExplorer: the paper's multimodal exploration of a 4D surface (4.3, 5.3). A probe held on the
// surface's 3D shadow follows the surface's own continuity: it walks across mesh edges, not across
// the shadow, so it passes straight through the shadow's self-intersection curves staying on its
// sheet; each pass is an event (above / below in w) for the sound cues; the hand is guided by the
// navigation spring towards the probe's projected prediction (4.3.1).
//
// [SECTION] Events
// [SECTION] Crossing table
// [SECTION] Explorer
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/frame.hpp"
#include "haptics/force_models.hpp"
#include "haptics/spsc_queue.hpp"
#include "shape/surface.hpp"

namespace s4d {

// [SECTION] Events

// The probe passed an intersection curve of the shadow: there its sheet crossed the shadow of
// another sheet (`other`), nearer the viewer in w (above) or farther (below). Plain data so it
// crosses threads by copy.
struct ExplorerEvent {
  double time = 0;       // s, the time given to the update that passed it
  bool above = false;    // the probe's sheet has the larger w (nearer) at the crossing
  int triangle = -1;     // the probe's triangle
  int other = -1;        // the other sheet's triangle
  double point[3] = {};  // shadow point of the crossing
  double w_self = 0;     // 4D depth of the probe's sheet there
  double w_other = 0;    // ... of the other sheet
  Vec3 point_vec() const { return {point[0], point[1], point[2]}; }
};

// [SECTION] Crossing table

// The shadow's intersection segments arranged per triangle, each end in barycentric coordinates of
// both triangles (b1, b2; b0 = 1 - b1 - b2), so the segments ride on the mesh when it moves a little
// between refreshes.
struct CrossingTable {
  struct Entry {
    int other = -1;                  // the triangle of the other sheet
    std::array<double, 2> q[2] = {};  // the segment's ends in this triangle's (b1, b2)
    std::array<double, 2> o[2] = {};  // ... in the other triangle's
  };
  std::vector<int> first;      // nt + 1: entries of triangle t are [first[t], first[t + 1])
  std::vector<Entry> entries;
  int segments = 0;            // intersection segments found (each gives two entries)
  int coplanar_pairs = 0;      // sheets overlapping in area: the view is not generic there
  double shadow_diagonal = 0;  // of the shadow's bounding box, for tolerances

  std::span<const Entry> of(int t) const {
    if (t < 0 || t + 1 >= static_cast<int>(first.size())) return {};
    return std::span<const Entry>(entries).subspan(first[t], first[t + 1] - first[t]);
  }
};

// Heavy (the shadow's intersection curves, proximity/shadow_intersections): for setup or the UI
// thread when the frame or the positions changed, never the 1 kHz tick. Throws Error when
// `positions` does not cover the triangles' indices.
CrossingTable build_crossing_table(std::span<const Triangle> triangles, std::span<const Vec4> positions,
                                   const Frame<4>& frame);

// [SECTION] Explorer

// Where the probe is: a triangle and barycentric coordinates (1 - b1 - b2, b1, b2).
struct ProbeLocation {
  int triangle = -1;
  double b1 = 0, b2 = 0;
  bool valid() const { return triangle >= 0; }
};

struct ExplorerSettings {
  int max_walk_steps = 128;  // triangles one move may cross; the rest waits for the next tick
  // After a pass, further passes within this distance (shadow units) of it are the same pass
  // jittering (a hand's tremor, an encoder's step) until the probe has moved farther away: one cue
  // per pass, not a burst. < 0: 0.002 of the shadow's diagonal.
  double rearm_distance = -1;
};

// Trouble met and work done, counted rather than thrown (the tick never throws).
struct ExplorerCounters {
  std::uint64_t updates = 0;
  std::uint64_t rejected_inputs = 0;  // non-finite device point, velocity or rate: ignored
  std::uint64_t numerical = 0;        // non-finite or missing vertex positions met: probe kept
  std::uint64_t edges_walked = 0;     // mesh edges the probe crossed
  std::uint64_t boundary_stops = 0;   // moves clamped at a boundary edge
  std::uint64_t ridge_stops = 0;      // moves stopped on a fold of the shadow (an edge both sides pull back)
  std::uint64_t degenerate_passes = 0;  // triangles seen edge-on in the shadow, passed along an edge
  std::uint64_t step_limit_hits = 0;  // moves cut by max_walk_steps
  std::uint64_t events = 0;           // crossing events emitted
  std::uint64_t events_dropped = 0;   // ... lost because nobody drained the buffer
  std::uint64_t events_merged = 0;    // passes taken for the previous one (within rearm_distance)
  std::uint64_t placements = 0;       // place / place_at calls (the only way the probe jumps)
};

struct ExplorerStep {
  Vec3 force = Vec3::Zero();  // the navigation spring, in the spring's units; zero when !ok
  Vec3 probe = Vec3::Zero();  // C_p', the probe's shadow point after the move
  bool ok = false;            // false: the input was rejected or the geometry was not finite
};

class SurfaceExplorer {
 public:
  static constexpr std::size_t kEventCapacity = 256;

  // The mesh topology (copied once; positions are never copied). Throws Error for a triangle index
  // outside [0, vertex_count) or a triangle repeating a vertex.
  SurfaceExplorer(std::span<const Triangle> triangles, int vertex_count, const ExplorerSettings& settings = {});

  // --- Set-up (not the tick) ---
  // Recomputes the crossing table for these positions and frame (heavy: see build_crossing_table).
  void refresh_crossings(std::span<const Vec4> positions, const Frame<4>& frame);
  // Installs a table built elsewhere (e.g. on the UI thread). No allocation: the tables swap.
  void swap_crossings(CrossingTable& table) { std::swap(table_, table); }
  const CrossingTable& crossings() const { return table_; }
  // Puts the probe on the surface point whose shadow is nearest to `p` (brute force over the
  // triangles; ties go to the larger w, the visible sheet). False when no triangle is usable.
  bool place(std::span<const Vec4> positions, const Frame<4>& frame, const Vec3& p);
  // Puts the probe at a given location (clamped into the triangle). False for an invalid triangle.
  bool place_at(const ProbeLocation& location);

  // --- The tick: no allocation, no throw ---
  // 4.3.1: C_p = C + V / R, C_p' = the probe walked on its sheet towards C_p, and the damped spring
  // from C to C_p' (force_models' navigation_force). c, v in shadow space; the spring in the same
  // units (force per shadow unit). Non-finite c, v or rate are rejected (counted, probe kept).
  ExplorerStep update(std::span<const Vec4> positions, const Frame<4>& frame, const Vec3& c, const Vec3& v,
                      double rate_hz, double time, const DampedSpring& spring) noexcept;
  // Walks the probe towards `target` (shadow space) along the mesh, emitting crossing events, and
  // returns where it ends: the target's projection on the probe's sheet when it is reached within
  // max_walk_steps triangles; clamped at boundary edges and stopped on folds of the shadow.
  Vec3 move_to(std::span<const Vec4> positions, const Frame<4>& frame, const Vec3& target, double time) noexcept;

  // --- Events: one consumer thread drains them (the producer is whoever runs the tick) ---
  std::optional<ExplorerEvent> pop_event() { return events_.try_pop(); }

  // --- Queries ---
  const ProbeLocation& probe() const { return probe_; }
  // The probe's shadow point and 4D depth for these positions (NaN point if not placed or not finite).
  Vec3 probe_point(std::span<const Vec4> positions, const Frame<4>& frame) const;
  double probe_depth(std::span<const Vec4> positions, const Frame<4>& frame) const;
  int triangle_count() const { return static_cast<int>(triangles_.size()); }
  int vertex_count() const { return vertex_count_; }
  std::span<const Triangle> triangles() const { return triangles_; }
  // The triangle across edge k of t (the edge opposite corner k), or -1 on a boundary (or an edge
  // shared by more than two triangles, which the walk treats as a boundary).
  int neighbour(int t, int k) const { return neighbours_[t][k]; }
  // Connected piece of the mesh (through shared edges) that triangle t belongs to: a "body".
  int component(int t) const { return component_[t]; }
  int component_count() const { return components_; }
  const ExplorerCounters& counters() const { return counters_; }
  void reset_counters() { counters_ = {}; }
  ExplorerSettings& settings() { return settings_; }

 private:
  struct Geometry;  // one triangle's shadow and depths, computed from the positions on the fly
  bool geometry(int t, std::span<const Vec4> positions, const Frame<4>& frame, Geometry& g) const;
  // Crossing events on the straight move a -> b (barycentric of t).
  void crossings_on(const Geometry& g, int t, const std::array<double, 2>& a, const std::array<double, 2>& b,
                    std::span<const Vec4> positions, const Frame<4>& frame, double time);
  void emit(const ExplorerEvent& e);
  // move_to's walk across the mesh: the probe's triangle, its weights there, and the edge it came
  // in by (-1 at the start). Each step returns the edge to leave by, or -1 to stop.
  struct Walk {
    int t = -1;
    std::array<double, 2> b{};
    int entered = -1;
  };
  int walk_flat(Walk& walk, const Geometry& g, const Vec3& target, std::span<const Vec4> positions,
                const Frame<4>& frame, double time);
  int walk_edge_on(Walk& walk, const Geometry& g, const Vec3& target, std::span<const Vec4> positions,
                   const Frame<4>& frame);
  void cross_edge(Walk& walk, int k_exit);

  std::vector<Triangle> triangles_;              // nt × 3
  std::vector<std::array<int, 3>> neighbours_;   // nt × 3, across the edge opposite each corner
  std::vector<int> component_;                   // nt
  int components_ = 0;
  int vertex_count_ = 0;
  ExplorerSettings settings_;
  CrossingTable table_;
  ProbeLocation probe_;
  SpscQueue<ExplorerEvent, kEventCapacity> events_;
  double rearm_distance() const;
  bool have_last_event_ = false;
  bool rearmed_ = false;      // the probe has gone farther than rearm_distance from the last event
  ExplorerEvent last_event_;
  ExplorerCounters counters_;
};

}  // namespace s4d
