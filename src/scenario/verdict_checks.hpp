// The measurable outcomes of the paper's scenarios: knottedness of a ribbon's centre line,
// lifted components, a cloth that slid off, deformation, a shadow's self-intersection curves.
// Pure functions of positions.
#pragma once
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "shape/surface.hpp"

namespace s4d {

struct KnotCheck {
  int min_crossings = 0;      // of the closed 3D centre line, over the views checked
  int max_crossings = 0;
  int open_crossings = 0;     // most crossings of the open (unclosed) centre line over the views
                              // not looking within 30° of `along` (end-on, a straight line's
                              // shadow degenerates and counts spurious crossings)
  long determinant = 0;       // knot determinant (3 for the trefoil, 1 for the unknot)
  int simplified_crossings = -1;
  unsigned long long fingerprint = 0;  // HOMFLY fingerprint (knot type up to mirror, see knots/)
  std::string error;          // non-empty when the knot engine could not read the curve
};

// Centre line of a grid ribbon (average across columns), its first three coordinates, closed far
// away: both ends extended along their end directions, then joined through `via` (3 numbers).
std::vector<Vec3> ribbon_centre_line(const std::vector<Vec4>& x, const Grid& grid);
KnotCheck check_knot(const std::vector<Vec3>& centre, const Vec3& via, const Vec3& along);

// The self-intersection curves of a surface's 3D shadow in one view (the Clifford torus pinch).
struct ShadowCheck {
  double total_length = 0;    // of all intersection curves in shadow space
  int segments = 0;
  int curves = 0;
  int true_curves = 0;        // curves through a true 4D intersection (must stay 0)
  int coplanar_pairs = 0;     // overlapping coplanar shadow triangles: the view is not generic
};
ShadowCheck check_shadow(const Surface<4>& surface, const std::string& view);

// Connected components of a triangle mesh (vertex labels 0..k-1).
std::vector<int> vertex_components(int nv, const std::vector<Triangle>& tris, int* count);

}  // namespace s4d
