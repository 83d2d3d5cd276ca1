// Artin spin of an arc (see spun_knot.hpp).
#include "shape/spun_knot.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "shape/knotted_arc.hpp"

namespace s4d {

Surface<4> spin_arc(const std::vector<Vec3>& arc, int m) {
  if (arc.size() < 3) throw Error("spinning needs an arc of at least 3 points");
  if (m < 3) throw Error("spinning needs at least 3 angles");
  const int rows = static_cast<int>(arc.size()) - 2;
  if (arc.front().z() != 0.0 || arc.back().z() != 0.0)
    throw Error("a spun arc must start and end on the plane z = 0");
  for (int i = 1; i <= rows; ++i)
    if (!(arc[i].z() > 0))
      throw Error("a spun arc must stay strictly above z = 0 between its ends (point " +
                  std::to_string(i) + " does not)");

  Surface<4> s;
  s.vertices.reserve(static_cast<std::size_t>(rows) * m + 2);
  const int first_pole = 0;
  s.vertices.emplace_back(arc.front().x(), arc.front().y(), 0.0, 0.0);
  for (int i = 1; i <= rows; ++i)
    for (int j = 0; j < m; ++j) {
      const double th = 2.0 * std::numbers::pi * j / m;
      const Vec3& p = arc[i];
      s.vertices.emplace_back(p.x(), p.y(), p.z() * std::cos(th), p.z() * std::sin(th));
    }
  const int last_pole = static_cast<int>(s.vertices.size());
  s.vertices.emplace_back(arc.back().x(), arc.back().y(), 0.0, 0.0);

  auto ring = [&](int i, int j) { return 1 + (i - 1) * m + (j % m); };  // i in [1, rows]
  for (int j = 0; j < m; ++j) s.triangles.push_back({first_pole, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i < rows; ++i)
    for (int j = 0; j < m; ++j) {
      s.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      s.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  for (int j = 0; j < m; ++j) s.triangles.push_back({ring(rows, j), last_pole, ring(rows, j + 1)});
  return s;
}

Surface<4> spun_trefoil(int n, int m) { return spin_arc(trefoil_arc(n, false), m); }

}  // namespace s4d
