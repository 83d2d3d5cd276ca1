// The naming decision: the polynomials name a curve or leave candidates (knot_identify), then the
// refinements drop candidates or prove the one left; every step says what it used.
// Sections: [SECTION] texts, [SECTION] refinements, [SECTION] naming.
#include "knots/knot_naming.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <mutex>
#include <tuple>

#include "knots/knot_table.hpp"
#include "knots/link_table.hpp"

namespace s4d {

namespace {

// [SECTION] texts

std::string factor_label(const KnotFactor& f) {
  std::string s = f.text();
  if (f.entry && !f.entry->rolfsen_name.empty() && !f.entry->dt_name.empty()) s += " (DT " + f.entry->dt_name + ")";
  return s;
}

std::string name_of(const KnotIdentification& id) {
  if (id.candidates.size() == 1)
    return id.candidates[0].size() == 1 ? factor_label(id.candidates[0][0]) : factorisation_text(id.candidates[0]);
  std::string s = "one of:";
  for (std::size_t i = 0; i < id.candidates.size(); ++i) s += (i ? ", " : " ") + factorisation_text(id.candidates[i]);
  return s;
}

std::string chirality_sentence(const KnotFactor& f) {
  const std::string n = f.entry->display_name();
  const std::string table =
      !f.entry->rolfsen_name.empty() ? "the Rolfsen table's (Knot Atlas) diagram" : "the census diagram";
  switch (f.chirality) {
    case Chirality::kAsTable: return n + " as drawn in " + table + ", not its mirror image";
    case Chirality::kMirror: return "the mirror image of " + n + " as drawn in " + table;
    case Chirality::kAmphichiral: return n + " is amphichiral: the same knot as its mirror image (proven)";
    case Chirality::kUnknown:
      return "unknown: HOMFLY-PT cannot tell " + n + " from its mirror image, and no proof either way is known here";
  }
  return {};
}

std::string link_chirality_sentence(const LinkCandidate& l) {
  const std::string n = l.entry->name;
  switch (l.chirality) {
    case Chirality::kAsTable: return n + " as drawn in KnotInfo's link table, not its mirror image";
    case Chirality::kMirror: return "the mirror image of " + n + " as drawn in KnotInfo's link table";
    default: return "unknown: HOMFLY-PT (in every orientation) cannot tell " + n + " from its mirror image";
  }
}

// What the identification by the polynomials rests on.
const LinkTable& links_of(const NamingOptions& o) { return o.links ? *o.links : LinkTable::shipped(); }

std::vector<std::string> grounds(const KnotIdentification& id, const KnotIndex& index, const NamingOptions& o) {
  const KnotInvariants& v = id.invariants;
  if (id.kind == KnotKind::kUnknot && id.proven && v.simplified_crossings == 0)
    return {std::string("Reidemeister simplification to a diagram without crossings (") + engine_name(v.engine) +
            (v.engine == KnotEngine::kOwn ? " engine" : "") + ")"};
  if (id.kind == KnotKind::kUnknot && id.proven) return {"the complement is a solid torus (Regina's unknot recognition)"};
  std::vector<std::string> out;
  if ((id.kind == KnotKind::kPrime || id.kind == KnotKind::kComposite) && id.candidates.size() == 1) {
    out.push_back("the HOMFLY-PT polynomial, matched against every prime knot of the census to " +
                  std::to_string(index.max_crossings()) + " crossings" +
                  (id.kind == KnotKind::kComposite ? " and their products" : ""));
    if (id.proven)
      out.push_back("a simplified diagram of " + std::to_string(v.simplified_crossings) +
                    " crossings, so the census holds every knot it could be");
  } else if (id.kind == KnotKind::kLink && !id.link_candidates.empty()) {
    out.push_back(
        "the HOMFLY-PT polynomial in every orientation, the components' knot types and linking numbers, matched "
        "against Thistlethwaite's link table to " + std::to_string(links_of(o).max_crossings()) + " crossings");
    if (id.proven)
      out.push_back("a connected simplified diagram of " + std::to_string(v.simplified_crossings) +
                    " crossings, and no split or composite link with the same HOMFLY-PT, so the table holds every "
                    "link it could be");
  }
  return out;
}

// [SECTION] refinements

struct Context {
  const NamingOptions& options;
  const KnotIndex& index;
  const KnotRefinements& engine;
  KnotNaming& out;
};

// A table entry's cover signature, computed once per (engine, entry, index): the same candidates
// come back with every redrawing of a curve.
std::string table_signature(const KnotRefinements& engine, const void* entry, int max_index,
                            const std::function<KnotDiagram()>& diagram) {
  static std::mutex mutex;
  static std::map<std::tuple<const void*, const void*, int>, std::string> made;
  const auto key = std::make_tuple(static_cast<const void*>(&engine), entry, max_index);
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = made.find(key); it != made.end()) return it->second;
  }
  std::string sig = engine.cover_signature(diagram(), max_index);
  std::lock_guard<std::mutex> lock(mutex);
  return made.emplace(key, std::move(sig)).first->second;
}

std::string covers_text(const char* group, int max_index) {
  return std::string("covers of the ") + group + " group of index 2 to " + std::to_string(max_index);
}

// Links the HOMFLY-PT polynomial, the components and the linking numbers leave together (mostly
// mutants): covers of the link group tell most apart. The Reidemeister search takes knots only.
void refine_link(Context& c) {
  KnotIdentification& id = c.out.identification;
  const int n = c.options.link_cover_index;
  const auto table = std::count_if(id.link_candidates.begin(), id.link_candidates.end(),
                                   [](const LinkCandidate& l) { return l.entry != nullptr; });
  if (table < 2 || n < 2) return;
  const std::string covers = covers_text("link", n);
  if (!c.engine.has_covers()) {
    c.out.unavailable.push_back(covers);
    return;
  }
  const std::string mine = c.engine.cover_signature(id.diagram, n);
  c.out.further_used.push_back(covers + ", with their homology (" + c.engine.engine() + ")");
  std::vector<LinkCandidate> kept;
  for (const LinkCandidate& l : id.link_candidates)
    if (!l.entry || table_signature(c.engine, l.entry, n, [&] { return link_diagram(*l.entry); }) == mine)
      kept.push_back(l);
  if (kept.size() == id.link_candidates.size() || kept.empty()) return;
  c.out.decided_by.push_back(covers + " rule out " + std::to_string(id.link_candidates.size() - kept.size()) +
                             " candidate(s)");
  id.link_candidates = std::move(kept);
  const bool was_proven = id.proven;
  settle_link(id, c.index, links_of(c.options));
  if (id.proven && !was_proven)
    c.out.decided_by.push_back("then one table link left, a connected simplified diagram of " +
                               std::to_string(id.invariants.simplified_crossings) +
                               " crossings, and no split or composite link with the same HOMFLY-PT");
}

void prove_unknot(Context& c) {
  KnotIdentification& id = c.out.identification;
  if (!c.engine.has_unknot_recognition()) {
    c.out.unavailable.push_back("unknot recognition");
    return;
  }
  c.out.further_used.push_back("unknot recognition of the complement (" + c.engine.engine() +
                               ": is it a solid torus?)");
  id.proven = true;
  if (c.engine.complement_is_solid_torus(id.diagram)) {
    id.name = "unknot";
    c.out.decided_by.push_back("the complement is a solid torus (" + c.engine.engine() + "'s unknot recognition)");
    return;
  }
  id.kind = KnotKind::kUnknown;
  id.name = "a knot with trivial HOMFLY-PT polynomial that is not the unknot (its complement is not a solid torus)";
  c.out.decided_by.push_back("the complement is not a solid torus (" + c.engine.engine() + "'s unknot recognition)");
}

bool prime_with_diagram(const KnotFactorisation& f) { return f.size() == 1 && !f[0].entry->sig.empty(); }

// Covers: the number and homology of index-k covers are invariants of the knot group.
void drop_by_covers(Context& c) {
  KnotIdentification& id = c.out.identification;
  const int n = c.options.knot_cover_index;
  if (n < 2) return;
  const std::string covers = covers_text("knot", n);
  if (!c.engine.has_covers()) {
    c.out.unavailable.push_back(covers);
    return;
  }
  const std::string mine = c.engine.cover_signature(id.diagram, n);
  c.out.further_used.push_back(covers + ", with their homology (" + c.engine.engine() + ")");
  std::vector<KnotFactorisation> kept;
  for (const auto& f : id.candidates)
    if (!prime_with_diagram(f) ||
        table_signature(c.engine, f[0].entry, n, [&] { return c.engine.table_diagram(f[0]); }) == mine)
      kept.push_back(f);
  if (kept.size() < id.candidates.size() && !kept.empty()) {
    c.out.decided_by.push_back(covers + " rule out " + std::to_string(id.candidates.size() - kept.size()) +
                               " candidate(s)");
    id.candidates = std::move(kept);
  }
}

// Reaching a candidate's table diagram by Reidemeister moves proves the knot is that one.
void search_table_diagrams(Context& c) {
  KnotIdentification& id = c.out.identification;
  const int extra = c.options.rewrite_height;
  if (id.candidates.size() < 2 || extra < 0) return;
  std::vector<KnotDiagram> targets;
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < id.candidates.size(); ++i)
    if (prime_with_diagram(id.candidates[i])) {
      targets.push_back(c.engine.table_diagram(id.candidates[i][0]));
      which.push_back(i);
    }
  c.out.further_used.push_back(c.engine.search_text(extra) + " towards the candidates' table diagrams");
  if (const auto hit = c.engine.reidemeister_search(id.diagram, targets, extra)) {
    const KnotFactorisation found = id.candidates[which[*hit]];
    c.out.decided_by.push_back("Reidemeister moves turn the diagram into the table's diagram of " +
                               factorisation_text(found));
    id.candidates = {found};
  }
}

void refine_knot(Context& c) {
  KnotIdentification& id = c.out.identification;
  if (id.kind == KnotKind::kUnknot && !id.proven) return prove_unknot(c);
  if (id.candidates.size() < 2) return;
  drop_by_covers(c);
  search_table_diagrams(c);
  id.proven = id.candidates.size() == 1 && id.invariants.simplified_crossings <= c.index.max_crossings();
  if (id.proven)
    c.out.decided_by.push_back("then one candidate left, and a simplified diagram of " +
                               std::to_string(id.invariants.simplified_crossings) +
                               " crossings, so the census holds every knot it could be");
  id.kind = id.candidates[0].size() == 1 ? KnotKind::kPrime : KnotKind::kComposite;
  id.name = name_of(id);
}

// What refine_* would run on this identification ("" when nothing).
std::vector<std::string> refinements_due(const KnotIdentification& id, const NamingOptions& o) {
  if (id.kind == KnotKind::kLink) {
    const auto table = std::count_if(id.link_candidates.begin(), id.link_candidates.end(),
                                     [](const LinkCandidate& l) { return l.entry != nullptr; });
    if (table >= 2 && o.link_cover_index >= 2) return {covers_text("link", o.link_cover_index)};
    return {};
  }
  if (id.kind == KnotKind::kUnknot && !id.proven) return {"unknot recognition"};
  if (id.candidates.size() < 2) return {};
  std::vector<std::string> due;
  if (o.knot_cover_index >= 2) due.push_back(covers_text("knot", o.knot_cover_index));
  if (o.rewrite_height >= 0) due.push_back("a Reidemeister search");
  return due;
}

}  // namespace

// [SECTION] naming

std::vector<std::string> KnotNaming::candidates() const {
  const KnotIdentification& id = identification;
  std::vector<std::string> out;
  if (id.kind == KnotKind::kUnknot) out.push_back("unknot");
  for (const auto& f : id.candidates) out.push_back(factorisation_text(f));
  for (const auto& l : id.link_candidates) out.push_back(l.text());
  return out;
}

std::string KnotNaming::chirality() const {
  const KnotIdentification& id = identification;
  if (id.kind == KnotKind::kUnknot) return id.proven ? "the unknot is amphichiral" : "";
  if (id.kind == KnotKind::kLink)
    return id.link_candidates.size() == 1 && id.link_candidates[0].entry ? link_chirality_sentence(id.link_candidates[0])
                                                                         : "";
  if (id.candidates.size() != 1) return "";
  std::string s;
  for (const auto& k : id.candidates[0]) s += (s.empty() ? "" : "; ") + chirality_sentence(k);
  return s;
}

std::string KnotNaming::headline() const {
  std::string s = identification.headline();
  if (!unavailable.empty()) {
    std::string what;
    for (const auto& x : unavailable) what += (what.empty() ? "" : ", ") + x;
    s += "  [without Regina: " + what + " unavailable]";
  }
  if (skipped.empty()) return s;
  std::string what;
  for (const auto& x : skipped) what += (what.empty() ? "" : ", ") + x;
  return s + "  [fast: " + what + " skipped]";
}

namespace {

KnotNaming decide(KnotIdentification id, const NamingOptions& options, const KnotIndex& index) {
  KnotNaming out;
  out.identification = std::move(id);
  out.decided_by = grounds(out.identification, index, options);
  const std::vector<std::string> due = refinements_due(out.identification, options);
  if (due.empty()) return out;
  if (options.fast) {
    out.skipped = due;
    return out;
  }
  Context c{options, index, options.refinements ? *options.refinements : refinements_of(options.engine), out};
  if (out.identification.kind == KnotKind::kLink) refine_link(c);
  else refine_knot(c);
  return out;
}

// The link table is left to identify_diagram to load, and only for links.
IdentifyOptions identify_options(const NamingOptions& options, const KnotIndex& index) {
  IdentifyOptions o;
  o.frame = options.frame;
  o.index = &index;
  o.links = options.links;
  o.engine = options.engine;
  return o;
}

}  // namespace

KnotNaming name_diagram(const KnotDiagram& diagram, const NamingOptions& options) {
  const KnotIndex& index = options.index ? *options.index : KnotIndex::shipped();
  return decide(identify_diagram(diagram, identify_options(options, index)), options, index);
}

KnotNaming name_knot(const Curve<3>& curve, const NamingOptions& options) {
  const KnotIndex& index = options.index ? *options.index : KnotIndex::shipped();
  // In the view with fewest crossings among the given one and the principal axes (identify_knot).
  return decide(identify_knot(curve, identify_options(options, index)), options, index);
}

}  // namespace s4d
