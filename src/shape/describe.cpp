#include "shape/describe.hpp"

#include <sstream>

#include "shape/topology.hpp"

namespace s4d {

std::string describe_shape(const Shape& shape) {
  std::ostringstream out;
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (requires { s.triangles; }) {
          const auto t = summarize_topology(s);
          out << "surface in R^" << T::kDim << ", " << t.vertices << " vertices, " << t.faces
              << " triangles, " << t.components << " component(s), Euler characteristic "
              << t.euler_characteristic << ", " << (t.closed ? "closed" : "with boundary") << ", "
              << (t.manifold ? "manifold" : "NOT manifold");
        } else {
          out << "curve in R^" << T::kDim << ", " << s.components.size() << " component(s), "
              << s.point_count() << " points, length " << s.length();
        }
      },
      shape);
  return out.str();
}

}  // namespace s4d
