// One line describing a shape for people: kind, dimension, size and topology. The GUI's scene
// panel and the demo's report print the same words.
#pragma once
#include <string>

#include "shape/shape.hpp"

namespace s4d {

std::string describe_shape(const Shape& shape);

}  // namespace s4d
