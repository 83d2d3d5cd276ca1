// Grid triangulation (see grid_mesh.hpp).
#include "shape/grid_mesh.hpp"

#include <string>

#include "core/error.hpp"

namespace s4d {

std::vector<Triangle> grid_triangles(const Grid& g) {
  const int min_rows = g.wrap_i ? 3 : 2;
  const int min_cols = g.wrap_j ? 3 : 2;
  if (g.rows < min_rows || g.cols < min_cols)
    throw Error("a " + std::string(g.wrap_i ? "wrapped " : "") + "grid of " +
                std::to_string(g.rows) + " × " + std::to_string(g.cols) +
                " vertices is too small to triangulate (need at least " + std::to_string(min_rows) +
                " × " + std::to_string(min_cols) + ")");
  const int cells_i = g.wrap_i ? g.rows : g.rows - 1;
  const int cells_j = g.wrap_j ? g.cols : g.cols - 1;
  std::vector<Triangle> tris;
  tris.reserve(static_cast<std::size_t>(cells_i) * cells_j * 2);
  for (int i = 0; i < cells_i; ++i) {
    const int i1 = (i + 1) % g.rows;
    for (int j = 0; j < cells_j; ++j) {
      const int j1 = (j + 1) % g.cols;
      const int a = g.index(i, j), b = g.index(i1, j), c = g.index(i1, j1), d = g.index(i, j1);
      tris.push_back({a, b, c});
      tris.push_back({a, c, d});
    }
  }
  return tris;
}

}  // namespace s4d
