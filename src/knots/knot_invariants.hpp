// Invariants of a knot or link diagram: Reidemeister simplification first, then the HOMFLY-PT,
// Jones and Alexander polynomials, the determinant and a crossing-number bound. Two engines compute
// them: Regina (the desktop's default) and the project's own (diagram_moves, own_polynomials; the
// only one in a build without Regina, S4D_WITH_REGINA=OFF, such as the web page), held equal to
// Regina's by the tests.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "knots/knot_diagram.hpp"
#include "knots/polynomial.hpp"

namespace s4d {

enum class KnotEngine { kRegina, kOwn };
// Whether this build has Regina; the default engine is Regina when it has.
bool regina_available();
KnotEngine default_knot_engine();
const char* engine_name(KnotEngine e);  // "Regina", "own"
// "regina" or "own" (Error otherwise, and for "regina" in a build without it).
KnotEngine parse_knot_engine(const std::string& text);

struct KnotInvariants {
  int components = 0;
  int diagram_crossings = 0;     // crossings of the diagram analysed
  int simplified_crossings = 0;  // after simplification: crossing number <= this
  bool simplified_alternating = false;  // a reduced alternating diagram has minimal crossings
  int simplified_pieces = 1;     // connected pieces of the simplified diagram (more: a split link)
  int writhe = 0;                // of the diagram analysed (not a knot invariant)
  std::vector<std::vector<int>> linking;  // components × components
  Laurent2 homfly;               // HOMFLY-PT in (alpha, z): alpha P+ - alpha^-1 P- = z P0, P(O) = 1
  Laurent1 jones;                // Jones polynomial in s = t^(1/2)
  Laurent1 alexander;            // Conway-normalised Alexander polynomial, in s = t^(1/2)
  std::int64_t determinant = 0;  // |Delta(-1)| = |V(-1)|
  std::uint64_t fingerprint = 0;         // homfly_fingerprint(homfly)
  std::uint64_t mirror_fingerprint = 0;  // the mirror image's
  std::string simplified_pd;     // PD code of the simplified diagram ("" if 0 crossings)
  KnotEngine engine = KnotEngine::kRegina;  // which engine computed them

  // Text forms in t when the powers allow it ("-t^-4 + t^-3 + t^-1"), else in t^(1/2).
  std::string jones_text() const;
  std::string alexander_text() const;
  std::string homfly_text() const;  // in a and z
  bool homfly_symmetric() const { return homfly == homfly.mirror_alpha(); }
};

// Regina's own forms of the codes of a diagram (before simplification); the own engine writes the
// same texts.
struct ReginaCodes {
  std::string gauss;           // Regina's classical Gauss code (knots)
  std::string oriented_gauss;  // Regina's oriented Gauss code ("+>1 -<2 ..."), knots and links
  std::string dt;              // Dowker-Thistlethwaite, numerical ("4 6 2"); knots only
  std::string dt_alpha;        // Dowker-Thistlethwaite, alphabetical ("bca"); knots only
};

KnotInvariants compute_invariants(const KnotDiagram& diagram, KnotEngine engine = default_knot_engine());
ReginaCodes regina_codes(const KnotDiagram& diagram, KnotEngine engine = default_knot_engine());

// True when the diagram is provably the unknot: it simplifies to no crossings, or (when
// `use_topology`, the engine is Regina and the invariants cannot decide) its complement is
// recognised as a solid torus by Regina's normal-surface algorithm (slow, exact). The own engine
// has no such recognition: it proves only by simplification.
bool is_unknot(const KnotDiagram& diagram, bool use_topology, KnotEngine engine = default_knot_engine());

}  // namespace s4d
