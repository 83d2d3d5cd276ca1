// Reidemeister moves on abstract diagrams, without Regina: R1 and R2 removal, R3 moves across
// triangular faces, oriented smoothing and a greedy/random simplification. The faces come from the
// rotation system the crossing signs define (as KnotDiagram::pd does), so every move is checked
// against the planar diagram, not just the Gauss code.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "knots/knot_diagram.hpp"

namespace s4d {

// A diagram reduced to what the moves need: a sign per crossing and, per component, its visits.
struct GaussVisit {
  int crossing = 0;
  bool over = false;
  friend bool operator==(const GaussVisit&, const GaussVisit&) = default;
};
struct GaussDiagram {
  std::vector<int> sign;                         // per crossing, +1 or -1
  std::vector<std::vector<GaussVisit>> comps;    // per component (empty: a crossing-free circle)

  int crossings() const { return static_cast<int>(sign.size()); }
  static GaussDiagram of(const KnotDiagram& d);
  KnotDiagram diagram() const;  // passages and crossings rebuilt, normalised (no geometry)
  // A text key of the diagram as labelled (crossings relabelled in order of first visit).
  std::string key() const;
  // Drops the crossings marked in `gone` and relabels the rest in order of first visit.
  void remove_crossings(const std::vector<char>& gone);
  // Crossing k changed (over and under swapped, sign negated).
  void switch_crossing(int k);
  // The oriented smoothing of crossing k: one component split in two, or two joined in one.
  GaussDiagram smoothed(int k) const;
};

// One R1 (a kink) or R2 (a bigon face whose strands pass over, resp. under, at both ends) removal;
// false when there is none.
bool remove_r1(GaussDiagram& g);
bool remove_r2(GaussDiagram& g);
// R1 and R2 removals until none is left.
void reduce_r1_r2(GaussDiagram& g);
// A triangular face where an R3 move applies (one strand over at both its crossings of the
// triangle): its three edges, each as (component, position of the visit it leaves).
struct R3Move {
  std::array<std::pair<int, int>, 3> edges;
};
std::vector<R3Move> r3_moves(const GaussDiagram& g);
// Moves the strand across: each edge's two visits swap places (the crossings keep their strands,
// over/under and signs); `move` must come from r3_moves of this same diagram.
void apply_r3(GaussDiagram& g, const R3Move& move);

struct SimplifyOptions {
  int attempts = 64;           // random walks of R3 moves tried after R1/R2 stall
  int walk_length = 0;         // R3 moves per walk (0: three times the crossings)
  std::uint64_t seed = 0x5eed;
};
// R1/R2 removal, then random walks of R3 moves (each followed by R1/R2 removal) kept when they
// lose crossings. Its crossings bound the crossing number from above.
KnotDiagram simplify_diagram(const KnotDiagram& d, const SimplifyOptions& options = {});
GaussDiagram simplify_gauss(GaussDiagram g, const SimplifyOptions& options = {});

// Over and under alternate along every component (crossing-free ones aside).
bool is_alternating(const KnotDiagram& d);
// Connected pieces of the diagram's shadow: components joined where they cross.
int diagram_pieces(const KnotDiagram& d);

}  // namespace s4d
