// The vocabulary of whole-mesh proximity queries: cells (a mesh's simplices by vertex index) and
// what the queries answer (close pairs, the earliest impact of a step).
#pragma once
#include <array>

#include "proximity/closest_points.hpp"

namespace s4d {

// A cell is a simplex of a mesh given by vertex indices: K = 2 curve segments, K = 3 triangles.
template <int K>
using Cell = std::array<int, K>;

template <int D>
struct ProximityPair {
  int a = 0, b = 0;          // cell indices (self queries: a < b; pair queries: a in first mesh)
  ClosestPoints<D> closest;  // exact closest points, p on cell a, q on cell b
};

template <int D>
struct Impact {
  bool hit = false;          // some pair comes within the thickness during the step
  double t = 1;              // earliest such time in [0, 1] (conservative: never late)
  int a = -1, b = -1;        // the pair that hits first
  ClosestPoints<D> at_t;     // their closest points at time t
  int narrow_tests = 0;      // pairs that reached exact continuous collision (for tuning)
};

// Cells that share a vertex touch by construction and are never paired in self queries.
template <int KA, int KB>
inline bool share_vertex(const Cell<KA>& a, const Cell<KB>& b) {
  for (int i = 0; i < KA; ++i)
    for (int j = 0; j < KB; ++j)
      if (a[i] == b[j]) return true;
  return false;
}

}  // namespace s4d
