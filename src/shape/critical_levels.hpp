// The critical levels of a view's depth on a triangle mesh, by PL Morse theory (Banchoff): a
// vertex's lower link (its neighbours below it, and the link edges between them) tells whether the
// slices change there: a circle is born (minimum), dies (maximum), or curves join or split
// (saddle, possibly a multiple one). Births − saddles + deaths is the mesh's Euler characteristic.
#pragma once
#include <vector>

#include "core/frame.hpp"
#include "shape/surface.hpp"

namespace s4d {

enum class CriticalKind { kBirth, kSaddle, kDeath };
const char* critical_kind_name(CriticalKind k);  // "birth", "saddle", "death"

struct CriticalPoint {
  int vertex = 0;
  double level = 0;  // the vertex's depth
  CriticalKind kind = CriticalKind::kBirth;
  int multiplicity = 1;  // a saddle where k arcs of the lower link meet counts k - 1 times
};

// Every critical vertex of depth on the mesh in `frame`, by increasing level. Vertices of equal
// depth are ordered by index (a symbolic tie-break), so each vertex's lower link is its
// neighbours before it in (depth, index) order. A vertex adds 1 − χ(lower link) to the Euler
// characteristic of the part below it: +1 with no lower neighbour is a birth, +1 otherwise a death
// (its whole link is below), 1 − k < 0 a saddle of multiplicity k − 1, and 0 a regular vertex (on
// a boundary, where the link is a path, a maximum is regular). Vertices no triangle uses are left
// out. Throws Error for a triangle whose vertex index is out of range.
template <int D>
std::vector<CriticalPoint> critical_points(const Surface<D>& mesh, const Frame<D>& frame);

struct CriticalCount {
  int births = 0, saddles = 0, deaths = 0;  // saddles with multiplicity
  int euler_characteristic() const { return births - saddles + deaths; }
};
CriticalCount count_critical(const std::vector<CriticalPoint>& points);

}  // namespace s4d
