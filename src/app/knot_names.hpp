// The knots the Scene panel has named: naming takes a moment (invariants, Regina's census), so a
// name is worked out on request and kept while its curve's points stay the same.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "io/scene.hpp"

namespace s4d {

class KnotNames {
 public:
  // Whether the object is a curve, which can be named.
  static bool nameable(const SceneObject& obj);
  // The line shown for the object ("knot: 3_1 (DT 3a_1)", or why it is no knot), or nullptr when
  // it has not been named since its points last changed.
  const std::string* find(const SceneObject& obj);
  // Names the object (as `shadow4d knot identify` does) and keeps the line. Never throws for a
  // bad curve: the line says what is wrong.
  const std::string& name(const SceneObject& obj);

 private:
  struct Named {
    std::string object;
    std::size_t points_hash = 0;
    std::string line;
  };
  std::vector<Named> named_;
};

}  // namespace s4d
