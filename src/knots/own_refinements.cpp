// The naming's refinements without Regina: the table's diagrams from the index's knot signatures,
// and a Reidemeister search that walks the diagrams R3 moves (with R1/R2 removal) reach from the
// simplified diagram, comparing knot signatures. Covers of the knot group and unknot recognition
// need Regina: the engine says it lacks them and the naming leaves the name "not proven".
#include <algorithm>
#include <deque>
#include <set>

#include "core/error.hpp"
#include "knots/diagram_moves.hpp"
#include "knots/knot_naming.hpp"
#include "knots/own_codes.hpp"

namespace s4d {

namespace {

// Diagrams visited by the search before it gives up (each costs a signature, O(n^2)).
constexpr std::size_t kSearchBudget = 4000;

class OwnRefinements final : public KnotRefinements {
 public:
  std::string engine() const override { return "own engine"; }
  std::string search_text(int) const override {
    return "a Reidemeister search (own engine: R3 moves with R1/R2 removal, no extra crossings)";
  }

  KnotDiagram table_diagram(const KnotFactor& f) const override {
    KnotDiagram d = diagram_from_knot_sig(f.entry->sig);
    return f.chirality == Chirality::kMirror ? d.mirrored() : d;
  }

  std::string cover_signature(const KnotDiagram&, int) const override {
    throw Error("covers of the knot group need Regina, which this build lacks");
  }

  std::optional<std::size_t> reidemeister_search(const KnotDiagram& diagram, const std::vector<KnotDiagram>& targets,
                                                 int) const override {
    std::vector<std::string> sigs;
    // Without reflection: a diagram reached proves the knot, not just the knot up to mirror image.
    for (const KnotDiagram& t : targets) sigs.push_back(knot_sig(simplify_diagram(t), false));
    std::set<std::string> seen;
    std::deque<GaussDiagram> queue{simplify_gauss(GaussDiagram::of(diagram))};
    while (!queue.empty() && seen.size() < kSearchBudget) {
      GaussDiagram g = std::move(queue.front());
      queue.pop_front();
      const KnotDiagram d = g.diagram();
      if (d.component_count() != 1) continue;
      const std::string sig = knot_sig(d, false);
      if (!seen.insert(sig).second) continue;
      if (const auto it = std::find(sigs.begin(), sigs.end(), sig); it != sigs.end())
        return static_cast<std::size_t>(it - sigs.begin());
      for (const auto& tri : r3_moves(g)) {
        GaussDiagram h = g;
        apply_r3(h, tri);
        reduce_r1_r2(h);
        queue.push_back(std::move(h));
      }
    }
    return std::nullopt;
  }

  bool complement_is_solid_torus(const KnotDiagram&) const override {
    throw Error("unknot recognition needs Regina, which this build lacks");
  }
  bool has_covers() const override { return false; }
  bool has_unknot_recognition() const override { return false; }
};

}  // namespace

#if !S4D_WITH_REGINA
std::string cover_signature(const KnotDiagram&, int) {
  throw Error("covers of the knot group need Regina, which this build lacks");
}
#endif

const KnotRefinements& own_refinements() {
  static const OwnRefinements r;
  return r;
}

const KnotRefinements& refinements_of(KnotEngine engine) {
#if S4D_WITH_REGINA
  if (engine == KnotEngine::kRegina) return regina_refinements();
#endif
  (void)engine;
  return own_refinements();
}

}  // namespace s4d
