// placed(): the placement's steps on any shape, in the documented order.
#include "shape/placement.hpp"

#include <string>
#include <type_traits>
#include <utility>

#include "core/error.hpp"

namespace s4d {

namespace {

Shape lifted(Shape shape) {
  if (auto* c = std::get_if<Curve<3>>(&shape)) return lift_to_4d(*c);
  if (auto* s = std::get_if<Surface<3>>(&shape)) return lift_to_4d(*s);
  return shape;
}

}  // namespace

Shape placed(Shape shape, const Placement& p) {
  if (p.is_identity()) return shape;
  if (p.matrix || p.w_by_row != 0 || p.offset.w() != 0) shape = lifted(std::move(shape));
  bool reflects = p.matrix && p.matrix->determinant() < 0;
  reflects = reflects != (p.mirror.size() % 2 == 1);
  std::visit(
      [&](auto& s) {
        using T = std::decay_t<decltype(s)>;
        constexpr int D = T::kDim;
        for (int a : p.mirror)
          if (a < 0 || a >= D)
            throw Error("mirror axis " + std::to_string(a) + " is not an axis of R^" + std::to_string(D));
        if constexpr (D == 4) {
          if (p.matrix) for_each_point(s, [&](Vec<D>& x) { x = *p.matrix * x; });
        }
        for_each_point(s, [&](Vec<D>& x) {
          x *= p.scale;
          for (int a : p.mirror) x[a] = -x[a];
        });
        if (p.w_by_row != 0) {
          if constexpr (std::is_same_v<T, Surface<4>>) {
            if (!s.grid || s.grid->rows < 2) throw Error("w_by_row needs a grid surface with two rows or more");
            for (int i = 0; i < s.grid->rows; ++i)
              for (int j = 0; j < s.grid->cols; ++j)
                s.vertices[s.grid->index(i, j)][3] +=
                    p.w_by_row * (static_cast<double>(i) / (s.grid->rows - 1) - 0.5);
          } else {
            throw Error("w_by_row needs a grid surface of R^4");
          }
        }
        const Vec<D> o = p.offset.template head<D>();
        for_each_point(s, [&](Vec<D>& x) { x += o; });
        if constexpr (std::is_same_v<T, Surface<D>>) {
          if (reflects)
            for (Triangle& t : s.triangles) std::swap(t[1], t[2]);
        }
      },
      shape);
  return shape;
}

}  // namespace s4d
