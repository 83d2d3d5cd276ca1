// The PD code written out: our own diagram's, with or without Regina (diagram_codes.hpp).
#include "knots/diagram_codes.hpp"

namespace s4d {

std::string pd_list(const KnotDiagram& diagram) {
  std::string s = "[";
  bool first = true;
  for (const auto& x : diagram.pd()) {
    s += std::string(first ? "" : ",") + "[" + std::to_string(x[0]) + "," + std::to_string(x[1]) + "," +
         std::to_string(x[2]) + "," + std::to_string(x[3]) + "]";
    first = false;
  }
  return s + "]";
}

}  // namespace s4d
