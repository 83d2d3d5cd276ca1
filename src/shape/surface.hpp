// Surface<D>: an indexed triangle mesh in R^D, with its (i,j) grid structure when it has one
// (cloth, ribbons, tori), which the physics uses for the paper's structural/shear/bending springs.
#pragma once
#include <array>
#include <optional>
#include <vector>

#include "core/vec.hpp"

namespace s4d {

using Triangle = std::array<int, 3>;

// Vertex (i, j) of a rows × cols grid is vertex i * cols + j. A wrapped direction joins its last
// row/column to its first (a cylinder wraps one, a torus both).
struct Grid {
  int rows = 0;
  int cols = 0;
  bool wrap_i = false;
  bool wrap_j = false;
  int index(int i, int j) const { return i * cols + j; }
  friend bool operator==(const Grid&, const Grid&) = default;
};

template <int D>
struct Surface {
  static constexpr int kDim = D;
  std::vector<Vec<D>> vertices;     // nv × D
  std::vector<Triangle> triangles;  // nt × 3, indices into vertices, counter-clockwise in (u, v)
  std::optional<Grid> grid;         // set when vertices are laid out as a grid

  std::size_t vertex_count() const { return vertices.size(); }
  std::size_t triangle_count() const { return triangles.size(); }
};

}  // namespace s4d
