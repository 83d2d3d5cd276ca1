// Placement: how a generated or loaded object is put into the scene, applied once when it is
// built — the scenarios' "a cloth squashed into a thin ribbon, turned into w, moved aside".
#pragma once
#include <optional>
#include <vector>

#include "core/vec.hpp"
#include "shape/shape.hpp"

namespace s4d {

struct Placement {
  // Applied in this order: the linear map of R^4 (an object of R^3 is lifted to R^4 first),
  // the scale, the mirrored axes, the w ramp along a grid's rows, then the offset.
  std::optional<Mat<4>> matrix;
  double scale = 1;
  std::vector<int> mirror;       // axes whose sign flips (0 = x ... 3 = w)
  double w_by_row = 0;           // grid surfaces of R^4: w += w_by_row × (row / (rows − 1) − ½)
  Vec4 offset = Vec4::Zero();    // added last; a non-zero w lifts an object of R^3 to R^4

  bool is_identity() const {
    return !matrix && scale == 1 && mirror.empty() && w_by_row == 0 && offset.isZero(0);
  }
};

// The placed shape. Surfaces keep their triangles counter-clockwise when the placement
// reflects (a negative determinant or an odd number of mirrored axes). Throws s4d::Error for a
// mirror axis the shape does not have or a w ramp on a shape that is no grid surface of R^4.
Shape placed(Shape shape, const Placement& placement);

}  // namespace s4d
