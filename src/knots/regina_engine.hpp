// The Regina side of the knot engine's seam, declared without Regina's headers; defined in the
// regina_*.cpp files, which a build with S4D_WITH_REGINA=OFF leaves out (and so must its callers).
#pragma once
#include <string>

#include "knots/knot_invariants.hpp"

#if S4D_WITH_REGINA
namespace s4d {

KnotInvariants regina_invariants(const KnotDiagram& diagram);
ReginaCodes regina_code_texts(const KnotDiagram& diagram);
bool regina_is_unknot(const KnotDiagram& diagram, bool use_topology);
KnotDiagram regina_diagram_from_pd(const std::string& code);
KnotDiagram regina_diagram_from_dt(const std::string& code);
std::string regina_dt(const KnotDiagram& diagram);

}  // namespace s4d
#endif
