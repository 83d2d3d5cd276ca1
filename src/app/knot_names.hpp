// The knots the Scene panel names. A curve of a few crossings is named live, whenever its points
// change (about a millisecond once the census index is loaded); a larger one is named on request,
// since its invariants can take much longer. A name is kept while its curve's points stay the same.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "io/scene.hpp"

namespace s4d {

class KnotNames {
 public:
  // Curves with at most this many crossings in the xy shadow are named live.
  static constexpr int kLiveCrossings = 16;

  // Whether the object is a curve, which can be named.
  static bool nameable(const SceneObject& obj);
  // The line shown for the object ("knot: 3_1 (DT 3a_1)", or why it is no knot): named now if its
  // points changed and it is small; nullptr when it waits for a request (name).
  const std::string* live(const SceneObject& obj);
  // Names the object whatever its size (as `shadow4d knot identify` does). Never throws for a bad
  // curve: the line says what is wrong.
  const std::string& name(const SceneObject& obj);

 private:
  struct Named {
    std::string object;
    std::size_t points_hash = 0;
    bool named = false;  // false: too large to name live, and not asked yet
    std::string line;
  };
  // The object's entry, new (fresh) when it had none or its points changed since.
  Named& entry(const SceneObject& obj, bool& fresh);
  std::vector<Named> named_;
};

}  // namespace s4d
