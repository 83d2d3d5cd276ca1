// A slice's name from the one naming decision (see slice_naming.hpp).
#include "knots/slice_naming.hpp"

#include "core/error.hpp"

namespace s4d {

std::string SliceNaming::headline() const {
  std::string s = label;
  if (!error.empty()) return s + ": " + error;
  if (components > 0 && !proven) s += "  [not proven]";
  if (components > 1) {
    s += "  linking numbers";
    for (std::size_t i = 0; i < linking.size(); ++i)
      for (std::size_t j = i + 1; j < linking[i].size(); ++j)
        s += " lk(" + std::to_string(i) + "," + std::to_string(j) + ")=" + std::to_string(linking[i][j]);
  }
  if (open_components > 0)
    s += "  (" + std::to_string(open_components) + " open arc" + (open_components > 1 ? "s" : "") + ")";
  return s;
}

std::string short_knot_name(const KnotIdentification& id, const std::vector<std::string>& candidates) {
  if (!id.link_name.empty()) return id.link_name;
  if (candidates.size() == 1) return candidates[0];
  if (candidates.empty()) return id.name;
  std::string s = "one of:";
  for (std::size_t i = 0; i < candidates.size(); ++i) s += (i ? ", " : " ") + candidates[i];
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
    out.name = out.label = out.open_components > 0 ? "open arcs only" : "empty";
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
    out.label = short_knot_name(naming.identification, out.candidates);
  } catch (const Error& e) {
    out.name = out.label = "not named";
    out.error = e.what();
  }
  return out;
}

}  // namespace s4d
