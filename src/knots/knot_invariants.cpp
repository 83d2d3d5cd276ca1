// The engine choice, the own engine's invariants and the texts both engines share.
#include "knots/knot_invariants.hpp"

#include "core/error.hpp"
#include "knots/diagram_moves.hpp"
#include "knots/own_codes.hpp"
#include "knots/own_polynomials.hpp"
#include "knots/regina_engine.hpp"

namespace s4d {

bool regina_available() { return S4D_WITH_REGINA != 0; }

KnotEngine default_knot_engine() { return regina_available() ? KnotEngine::kRegina : KnotEngine::kOwn; }

const char* engine_name(KnotEngine e) { return e == KnotEngine::kRegina ? "Regina" : "own"; }

KnotEngine parse_knot_engine(const std::string& text) {
  if (text == "own") return KnotEngine::kOwn;
  if (text == "regina" || text == "Regina") {
    if (!regina_available()) throw Error("this build has no Regina (built with S4D_WITH_REGINA=OFF); use --engine own");
    return KnotEngine::kRegina;
  }
  throw Error("unknown knot engine '" + text + "': use 'regina' or 'own'");
}

std::string KnotInvariants::jones_text() const { return jones.str_half("t"); }
std::string KnotInvariants::alexander_text() const { return alexander.str_half("t"); }
std::string KnotInvariants::homfly_text() const { return homfly.str("a", "z"); }

namespace {

KnotInvariants own_invariants(const KnotDiagram& diagram) {
  KnotInvariants inv;  // the simplification and the polynomials; compute_invariants does the rest
  const GaussDiagram simple = simplify_gauss(GaussDiagram::of(diagram));
  const KnotDiagram s = simple.diagram();
  inv.simplified_crossings = s.crossing_count();
  inv.simplified_alternating = is_alternating(s);
  if (s.crossing_count() > 0) inv.simplified_pd = s.pd_code();
  inv.simplified_pieces = diagram_pieces(s);
  inv.homfly = homfly_polynomial(simple);
  inv.jones = jones_from_homfly(inv.homfly, diagram.component_count());
  return inv;
}

}  // namespace

KnotInvariants compute_invariants(const KnotDiagram& diagram, KnotEngine engine) {
  // Each engine simplifies and computes the polynomials; what the diagram itself says and what
  // follows from the polynomials is the same for both.
#if S4D_WITH_REGINA
  KnotInvariants inv = engine == KnotEngine::kRegina ? regina_invariants(diagram) : own_invariants(diagram);
#else
  if (engine == KnotEngine::kRegina) throw Error("this build has no Regina (S4D_WITH_REGINA=OFF)");
  KnotInvariants inv = own_invariants(diagram);
#endif
  inv.engine = engine;
  inv.components = diagram.component_count();
  inv.diagram_crossings = diagram.crossing_count();
  inv.writhe = diagram.writhe();
  inv.linking = diagram.linking_numbers();
  inv.alexander = alexander_from_homfly(inv.homfly);
  inv.determinant = abs_at_t_minus_one(inv.jones);
  inv.fingerprint = homfly_fingerprint(inv.homfly);
  inv.mirror_fingerprint = homfly_fingerprint(inv.homfly.mirror_alpha());
  return inv;
}

ReginaCodes regina_codes(const KnotDiagram& diagram, KnotEngine engine) {
#if S4D_WITH_REGINA
  if (engine == KnotEngine::kRegina) return regina_code_texts(diagram);
#endif
  (void)engine;
  ReginaCodes c;
  c.oriented_gauss = oriented_gauss_text(diagram);
  c.gauss = gauss_text(diagram);
  c.dt = dt_text(diagram, false);
  c.dt_alpha = dt_text(diagram, true);
  return c;
}

bool is_unknot(const KnotDiagram& diagram, bool use_topology, KnotEngine engine) {
#if S4D_WITH_REGINA
  if (engine == KnotEngine::kRegina) return regina_is_unknot(diagram, use_topology);
#endif
  (void)engine;
  (void)use_topology;  // the own engine has no unknot recognition beyond simplification
  if (diagram.component_count() != 1) return false;
  return simplify_gauss(GaussDiagram::of(diagram)).crossings() == 0;
}

}  // namespace s4d
