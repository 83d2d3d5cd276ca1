// Triangulates an (i, j) grid of vertices, the layout shared by cloth, ribbons and tori.
#pragma once
#include <vector>

#include "shape/surface.hpp"

namespace s4d {

// Two triangles per grid cell, counter-clockwise in (u, v) = (i, j): cell (i, j) gives
// (i,j) (i+1,j) (i+1,j+1) and (i,j) (i+1,j+1) (i,j+1). A wrapped direction also joins its
// last row/column to its first. Needs rows, cols >= 2 (>= 3 in a wrapped direction, so that
// no two triangles share all three vertices); throws s4d::Error otherwise.
std::vector<Triangle> grid_triangles(const Grid& g);

}  // namespace s4d
