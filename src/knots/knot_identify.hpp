// Names the knot or link of a curve: unknot, prime knots of the census (Rolfsen and DT names) with
// chirality, composite knots from HOMFLY-PT factorisations, links from Thistlethwaite's table (to
// 11 crossings) with their components and linking numbers. When the invariants cannot decide,
// every candidate is listed.
#pragma once
#include <string>
#include <vector>

#include "core/frame.hpp"
#include "knots/knot_diagram.hpp"
#include "knots/knot_index.hpp"
#include "knots/knot_invariants.hpp"
#include "knots/link_table.hpp"
#include "shape/curve.hpp"

namespace s4d {

enum class Chirality {
  kAsTable,      // the knot of the table's reference diagram
  kMirror,       // its mirror image
  kAmphichiral,  // proven equal to its mirror image (by Reidemeister moves, when indexing)
  kUnknown,      // HOMFLY-PT is symmetric and no proof of amphichirality is known
};
const char* chirality_name(Chirality c);  // "as-table", "mirror", "amphichiral", "unknown"

struct KnotFactor {
  const KnotTableEntry* entry = nullptr;
  Chirality chirality = Chirality::kAsTable;
  std::string text() const;  // "3_1", "3_1 mirror", "4_1"
};
// One possible answer: the prime factors of a knot (a single factor for a prime knot).
using KnotFactorisation = std::vector<KnotFactor>;
std::string factorisation_text(const KnotFactorisation& f);  // "3_1 # 3_1 mirror"

// One answer for a link: a table link as drawn, its mirror image, or either (kUnknown: HOMFLY-PT
// cannot tell them apart); or, with no entry, a split or composite link the invariants also allow.
struct LinkCandidate {
  const LinkTableEntry* entry = nullptr;
  Chirality chirality = Chirality::kAsTable;
  std::string other;  // without an entry: "Hopf link # 3_1", "split: L2a1 and unknot"
  std::string text() const;  // "L6a4", "L4a1 mirror", or `other`
};

enum class KnotKind { kUnknot, kPrime, kComposite, kLink, kUnknown };
const char* kind_name(KnotKind k);  // "unknot", "prime", "composite", "link", "unknown"

struct KnotIdentification {
  KnotKind kind = KnotKind::kUnknown;
  std::string name;       // one line for people: "5_1 (DT 5a_2)", "3_1 # 4_1", "unknot", ...
  bool proven = false;    // the invariants (or a 0-crossing diagram) leave no other possibility
  std::vector<KnotFactorisation> candidates;  // knots: every answer the invariants allow
  KnotInvariants invariants;
  KnotDiagram diagram;    // the diagram analysed (in `frame`)
  Frame<3> frame;         // the view actually used (after any generic perturbation)
  std::vector<KnotIdentification> components;  // links: each component on its own
  std::string link_name;  // links: a well-known name when the link is one ("Hopf link"), else ""
  std::vector<LinkCandidate> link_candidates;  // links: every answer the invariants allow
  // The name as the CLI and the GUI show it: "3_1 (DT 3a_1)", with "  [not proven]" when the
  // invariants leave other answers open.
  std::string headline() const { return name + (proven ? "" : "  [not proven]"); }
};

struct IdentifyOptions {
  Frame<3> frame;             // the view to start from
  bool choose_view = true;    // also try the curve's principal axes; keep the view with fewest crossings
  bool prove_unknot = false;  // use Regina's solid-torus recognition when only invariants say unknot
  KnotEngine engine = default_knot_engine();  // who computes the invariants
  const KnotIndex* index = nullptr;  // nullptr: KnotIndex::shipped()
  const LinkTable* links = nullptr;  // nullptr: LinkTable::shipped()
};

// Throws Error for invalid curves (see diagram_from_curve).
KnotIdentification identify_knot(const Curve<3>& curve, const IdentifyOptions& options = {});
KnotIdentification identify_diagram(const KnotDiagram& diagram, const IdentifyOptions& options = {});

// A link's name, and whether it is proven, from its table candidates as they stand (after further
// invariants dropped some): one left within the table's crossings is proven unless a split or
// composite link shares its invariants (those are listed as candidates then).
void settle_link(KnotIdentification& id, const KnotIndex& index, const LinkTable& links);

// The diagram of one component of a link on its own (crossings with other components dropped).
KnotDiagram component_diagram(const KnotDiagram& diagram, int component);

// A knot's type up to mirror image as the link table lists its links' components: "unknot",
// "3_1", "3_1#4_1" (factors sorted); "?" unless the identification is proven.
std::string knot_type_up_to_mirror(const KnotIdentification& knot);

// The paper's user-study question "are these the same knot?".
enum class Sameness { kSame, kMirror, kDifferent, kUndecided };
const char* sameness_name(Sameness s);  // "same", "mirror", "different", "undecided"
struct KnotComparison {
  Sameness verdict = Sameness::kUndecided;
  std::string reason;  // one sentence
  KnotIdentification a, b;
};
KnotComparison compare_knots(const Curve<3>& a, const Curve<3>& b, const IdentifyOptions& options = {});

}  // namespace s4d
