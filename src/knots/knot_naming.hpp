// The one naming decision: every place that names a curve (`knot identify`, `knot info`, the Knot
// and Scene panels, the exercises, the slices) calls name_knot, so the same curve gets the same
// name everywhere, with the invariants that decided it. By default every refinement the engine
// has runs where the polynomials leave candidates; `fast` skips them for batch use and says so.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/frame.hpp"
#include "knots/knot_identify.hpp"
#include "shape/curve.hpp"

namespace s4d {

// The exact but slow invariants the naming refines with, behind one interface so that a build
// without Regina can stand in (regina_refinements() is the desktop's).
class KnotRefinements {
 public:
  virtual ~KnotRefinements() = default;
  virtual std::string engine() const = 0;  // named in the texts: "Regina"
  // The table's diagram of a prime knot, in the chirality the factor says.
  virtual KnotDiagram table_diagram(const KnotFactor& factor) const = 0;
  // Per index 2..max_index, the sorted homology of the connected covers of the group of the
  // knot or link (as cover_signature); equal for the same knot or link and its mirror.
  virtual std::string cover_signature(const KnotDiagram& diagram, int max_index) const = 0;
  // Reidemeister moves (up to `extra` crossings beyond the simplified diagram) from `diagram` to
  // one of `targets` (knots): the index of the one reached, if any.
  virtual std::optional<std::size_t> reidemeister_search(const KnotDiagram& diagram,
                                                         const std::vector<KnotDiagram>& targets,
                                                         int extra) const = 0;
  // Whether the knot's complement is a solid torus (exactly when it is the unknot).
  virtual bool complement_is_solid_torus(const KnotDiagram& diagram) const = 0;
  // What the engine can do: an engine without them says so, and the name stays "not proven".
  virtual bool has_covers() const { return true; }
  // How the naming names its Reidemeister search.
  virtual std::string search_text(int extra) const {
    return "a Reidemeister search (" + engine() + "'s rewrite, up to " + std::to_string(extra) + " extra crossing(s))";
  }
  virtual bool has_unknot_recognition() const { return true; }
};
// Regina's (only in a build with Regina: S4D_WITH_REGINA).
const KnotRefinements& regina_refinements();
// The own engine's: table diagrams from the index's knot signatures, a Reidemeister search by R3
// moves and R1/R2 removal; no covers, no unknot recognition.
const KnotRefinements& own_refinements();
// The refinements that go with an engine.
const KnotRefinements& refinements_of(KnotEngine engine);

struct NamingOptions {
  Frame<3> frame;          // the view to start from; the curve's principal axes are tried too
  bool fast = false;       // skip the refinements (covers, Reidemeister search, unknot recognition)
  int knot_cover_index = 6;  // covers of a knot group of index 2 .. this (6 tells 11n_34 from 11n_42)
  int link_cover_index = 5;  // the same for link groups (which have many more covers)
  int rewrite_height = 1;    // Reidemeister search: extra crossings allowed (0: none)
  const KnotIndex* index = nullptr;  // nullptr: KnotIndex::shipped()
  const LinkTable* links = nullptr;  // nullptr: LinkTable::shipped()
  KnotEngine engine = default_knot_engine();     // who computes the invariants
  const KnotRefinements* refinements = nullptr;  // nullptr: refinements_of(engine)
};

struct KnotNaming {
  KnotIdentification identification;      // name, proven, candidates, invariants, diagram named
  std::vector<std::string> decided_by;    // the invariants and proofs that decided it, in order
  std::vector<std::string> further_used;  // the refinements tried (decisive or not)
  std::vector<std::string> skipped;       // fast: the refinements that would have run
  std::vector<std::string> unavailable;   // refinements due that the engine cannot do (no Regina)
  const std::string& name() const { return identification.name; }
  bool proven() const { return identification.proven; }
  // Every answer still possible, as text ("unknot", "3_1 # 4_1 mirror", "L6a4").
  std::vector<std::string> candidates() const;
  // One sentence: which of the knot and its mirror image this is ("" when not decided).
  std::string chirality() const;
  // "3_1 (DT 3a_1)", with "  [not proven]" when other answers remain, "  [fast: ... skipped]"
  // when the fast mode left refinements out and "  [without Regina: ...]" when the engine lacks them.
  std::string headline() const;
};

// Names the curve: its diagram in the view with fewest crossings among `options.frame` and the
// principal axes, then the refinements. Throws Error for invalid curves (see diagram_from_curve).
KnotNaming name_knot(const Curve<3>& curve, const NamingOptions& options = {});
// The same from a diagram (its view is the caller's).
KnotNaming name_diagram(const KnotDiagram& diagram, const NamingOptions& options = {});

}  // namespace s4d
