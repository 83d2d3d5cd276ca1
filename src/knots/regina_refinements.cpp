// The naming's refinements through Regina: covers of the knot or link group with their homology,
// a Reidemeister search by knot signatures, and solid-torus recognition of the complement.
#include <algorithm>

#include "core/error.hpp"
#include "knots/knot_info.hpp"
#include "knots/knot_naming.hpp"
#include "knots/regina_link.hpp"

namespace s4d {

namespace {

template <int k>
void covers_of_index(const regina::GroupPresentation& g, std::vector<std::string>& out) {
  g.enumerateCovers<k>([&](regina::GroupPresentation&& sub) { out.push_back(sub.abelianisation().str()); });
}

class ReginaRefinements final : public KnotRefinements {
 public:
  std::string engine() const override { return "Regina"; }

  KnotDiagram table_diagram(const KnotFactor& f) const override {
    regina::Link l = regina::Link::fromKnotSig(f.entry->sig);
    if (f.chirality == Chirality::kMirror) l.reflect();
    return diagram_from_regina(l);
  }

  std::string cover_signature(const KnotDiagram& diagram, int max_index) const override {
    return s4d::cover_signature(diagram, max_index);
  }

  std::optional<std::size_t> reidemeister_search(const KnotDiagram& diagram, const std::vector<KnotDiagram>& targets,
                                                 int extra) const override {
    std::vector<std::string> sigs;
    for (const KnotDiagram& t : targets) sigs.push_back(to_regina_link(t).knotSig());
    std::optional<std::size_t> hit;
    auto match = [&](const std::string& sig) {
      const auto it = std::find(sigs.begin(), sigs.end(), sig);
      if (it != sigs.end()) hit = static_cast<std::size_t>(it - sigs.begin());
      return hit.has_value();
    };
    regina::Link link = to_regina_link(diagram);
    link.intelligentSimplify();
    if (!match(link.knotSig()) && extra > 0)
      link.rewrite(extra, 1, nullptr, [&](const std::string& sig, const regina::Link&) { return match(sig); });
    return hit;
  }

  bool complement_is_solid_torus(const KnotDiagram& diagram) const override { return is_unknot(diagram, true); }
};

}  // namespace

const KnotRefinements& regina_refinements() {
  static const ReginaRefinements r;
  return r;
}

std::string cover_signature(const KnotDiagram& diagram, int max_index) {
  if (max_index > 7) throw Error("covers of index above 7 are too slow to count here");
  const regina::GroupPresentation g = to_regina_link(diagram).group(true);
  std::string sig;
  for (int k = 2; k <= max_index; ++k) {
    std::vector<std::string> homology;
    switch (k) {
      case 2: covers_of_index<2>(g, homology); break;
      case 3: covers_of_index<3>(g, homology); break;
      case 4: covers_of_index<4>(g, homology); break;
      case 5: covers_of_index<5>(g, homology); break;
      case 6: covers_of_index<6>(g, homology); break;
      case 7: covers_of_index<7>(g, homology); break;
    }
    std::sort(homology.begin(), homology.end());
    sig += std::to_string(k) + ":";
    for (const auto& h : homology) sig += " " + h + ",";
    sig += "; ";
  }
  return sig;
}

}  // namespace s4d
