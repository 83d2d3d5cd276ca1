// A slice's name from the one naming decision (see slice_naming.hpp).
#include "knots/slice_naming.hpp"

#include "core/error.hpp"

namespace s4d {

std::string SliceNaming::headline() const {
  std::string s = name;
  if (!error.empty()) return s + ": " + error;
  if (components > 0 && !proven) s += "  [not proven]";
  if (components > 1 || open_components > 0) s += "  (" + std::to_string(components) + " components";
  if (open_components > 0) s += ", " + std::to_string(open_components) + " open arc" + (open_components > 1 ? "s" : "");
  if (components > 1 || open_components > 0) s += ")";
  return s;
}

SliceNaming name_slice(const Curve<3>& slice, double level, const NamingOptions& options) {
  SliceNaming out;
  out.level = level;
  Curve<3> closed;
  for (const Polyline<3>& line : slice.components) {
    if (line.closed)
      closed.components.push_back(line);
    else
      ++out.open_components;
  }
  out.components = static_cast<int>(closed.components.size());
  if (closed.components.empty()) {
    out.name = out.open_components > 0 ? "open arcs only" : "empty";
    out.proven = true;
    return out;
  }
  try {
    const KnotNaming naming = name_knot(closed, options);
    out.name = naming.name();
    out.proven = naming.proven();
    out.candidates = naming.candidates();
    out.linking = naming.identification.invariants.linking;
    out.decided_by = naming.decided_by;
  } catch (const Error& e) {
    out.name = "not named";
    out.error = e.what();
  }
  return out;
}

}  // namespace s4d
