// The codes through Regina's readers (Link::fromPD, Link::fromDT, written after SnapPea's).
#include "core/error.hpp"
#include "knots/regina_engine.hpp"
#include "knots/regina_link.hpp"

namespace s4d {

KnotDiagram regina_diagram_from_pd(const std::string& text) {
  try {
    return diagram_from_regina(regina::Link::fromPD(text));
  } catch (const regina::InvalidArgument& e) {
    throw Error("not a PD code of a knot or link ('" + text + "'): " + e.what());
  }
}

KnotDiagram regina_diagram_from_dt(const std::string& text) {
  try {
    return diagram_from_regina(regina::Link::fromDT(text));
  } catch (const regina::InvalidArgument& e) {
    throw Error("not a DT code of a knot ('" + text + "'): " + e.what());
  }
}

std::string regina_dt(const KnotDiagram& diagram) { return to_regina_link(diagram).dt(false); }

}  // namespace s4d
