// A build without Regina (the web page, for now): the functions of the Regina bridge
// (knot_invariants.cpp, diagram_codes.cpp, regina_refinements.cpp) say that they need it, so
// every caller shows that instead of a name. Another invariant engine drops in here later: it
// defines compute_invariants and a KnotRefinements of its own.
#include "core/error.hpp"
#include "knots/diagram_codes.hpp"
#include "knots/knot_info.hpp"
#include "knots/knot_invariants.hpp"
#include "knots/knot_naming.hpp"

namespace s4d {

namespace {

[[noreturn]] void needs_regina(const std::string& what) {
  throw Error(what + " needs Regina, which this build (the web page) does not have yet: use the desktop build");
}

class WithoutRegina final : public KnotRefinements {
 public:
  std::string engine() const override { return "none"; }
  KnotDiagram table_diagram(const KnotFactor&) const override { needs_regina("a table knot's diagram"); }
  std::string cover_signature(const KnotDiagram&, int) const override { needs_regina("covers of the knot group"); }
  std::optional<std::size_t> reidemeister_search(const KnotDiagram&, const std::vector<KnotDiagram>&,
                                                 int) const override {
    needs_regina("the Reidemeister search");
  }
  bool complement_is_solid_torus(const KnotDiagram&) const override { needs_regina("unknot recognition"); }
};

}  // namespace

std::string KnotInvariants::jones_text() const { return jones.str_half("t"); }
std::string KnotInvariants::alexander_text() const { return alexander.str_half("t"); }
std::string KnotInvariants::homfly_text() const { return homfly.str("a", "z"); }

KnotInvariants compute_invariants(const KnotDiagram&) { needs_regina("naming (knot invariants)"); }
ReginaCodes regina_codes(const KnotDiagram&) { needs_regina("Regina's codes"); }
bool is_unknot(const KnotDiagram&, bool) { needs_regina("unknot recognition"); }

KnotDiagram diagram_from_pd(const std::string&) { needs_regina("reading a PD code"); }
KnotDiagram diagram_from_dt(const std::string&) { needs_regina("reading a DT code"); }
KnotDiagram diagram_from_knot_sig(const std::string&) { needs_regina("reading a knot signature"); }
std::string dt_code(const KnotDiagram&) { needs_regina("a DT code"); }

const KnotRefinements& regina_refinements() {
  static const WithoutRegina r;
  return r;
}
std::string cover_signature(const KnotDiagram&, int) { needs_regina("covers of the knot group"); }

}  // namespace s4d
