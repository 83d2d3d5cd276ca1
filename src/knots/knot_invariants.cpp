// The bridge to Regina: our KnotDiagram becomes a regina::Link; Regina simplifies it and computes
// the polynomials, which come back as our own Laurent types.
#include "knots/knot_invariants.hpp"

#include <triangulation/dim3.h>

#include "core/error.hpp"
#include "knots/regina_link.hpp"

namespace s4d {

regina::Link to_regina_link(const KnotDiagram& d) {
  std::vector<int> signs;
  signs.reserve(d.crossings.size());
  for (const auto& c : d.crossings) signs.push_back(c.sign);
  std::vector<std::vector<int>> comps;
  for (const auto& comp : d.components) {
    std::vector<int> visits;
    for (int p : comp) {
      const int label = d.passages[p].crossing + 1;
      visits.push_back(d.passages[p].over ? label : -label);
    }
    if (visits.empty()) visits.push_back(0);  // Regina's spelling of a crossing-free component
    comps.push_back(std::move(visits));
  }
  try {
    return regina::Link::fromData(signs.begin(), signs.end(), comps.begin(), comps.end());
  } catch (const std::exception& e) {
    throw Error(std::string("inconsistent knot diagram: ") + e.what());
  }
}

KnotDiagram diagram_from_regina(const regina::Link& link) {
  KnotDiagram d;
  d.crossings.resize(link.size());
  for (std::size_t i = 0; i < link.size(); ++i) d.crossings[i].sign = link.crossing(i)->sign();
  for (std::size_t c = 0; c < link.countComponents(); ++c) {
    std::vector<int> comp;
    const regina::StrandRef start = link.component(c);
    if (start.crossing()) {
      regina::StrandRef s = start;
      do {
        const int p = static_cast<int>(d.passages.size());
        const int k = static_cast<int>(s.crossing()->index());
        const bool over = s.strand() == 1;
        d.passages.push_back({k, over, static_cast<int>(c), 0.0});
        (over ? d.crossings[k].over : d.crossings[k].under) = p;
        comp.push_back(p);
        ++s;
      } while (s != start);
    }
    d.components.push_back(std::move(comp));
  }
  d.normalise();
  return d;
}

namespace {

Laurent1 from_regina(const regina::Laurent<regina::Integer>& p) {
  Laurent1 r;
  if (p.isZero()) return r;
  for (long e = p.minExp(); e <= p.maxExp(); ++e) r.add(e, p[e].longValue());
  return r;
}

// Laurent2 keeps its terms private; every exponent of a HOMFLY-PT polynomial of an n-crossing,
// m-component diagram lies within [-(n + m), n + m], so probing that box is exact.
Laurent2 from_regina(const regina::Laurent2<regina::Integer>& p, long bound) {
  Laurent2 r;
  for (long i = -bound; i <= bound; ++i)
    for (long j = -bound; j <= bound; ++j) {
      const auto& c = p(i, j);
      if (!c.isZero()) r.add(i, j, c.longValue());
    }
  return r;
}

std::string in_t_or_sqrt_t(const Laurent1& f) { return f.str_half("t"); }

// Connected pieces of a diagram's shadow: components joined where they cross.
int diagram_pieces(const KnotDiagram& d) {
  std::vector<int> parent(d.components.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& c : d.crossings) parent[root(d.passages[c.over].component)] = root(d.passages[c.under].component);
  int pieces = 0;
  for (std::size_t i = 0; i < parent.size(); ++i) pieces += root(static_cast<int>(i)) == static_cast<int>(i);
  return pieces;
}

}  // namespace

std::string KnotInvariants::jones_text() const { return in_t_or_sqrt_t(jones); }
std::string KnotInvariants::alexander_text() const { return in_t_or_sqrt_t(alexander); }
std::string KnotInvariants::homfly_text() const { return homfly.str("a", "z"); }

KnotInvariants compute_invariants(const KnotDiagram& diagram) {
  KnotInvariants inv;
  inv.components = diagram.component_count();
  inv.diagram_crossings = diagram.crossing_count();
  inv.writhe = diagram.writhe();
  inv.linking = diagram.linking_numbers();

  regina::Link link = to_regina_link(diagram);
  link.intelligentSimplify();
  inv.simplified_crossings = static_cast<int>(link.size());
  inv.simplified_alternating = link.isAlternating();
  if (link.size() > 0) inv.simplified_pd = link.pd();
  inv.simplified_pieces = diagram_pieces(diagram_from_regina(link));

  const long bound = static_cast<long>(link.size() + link.countComponents()) + 1;
  inv.homfly = from_regina(link.homflyAZ(), bound);
  inv.jones = from_regina(link.jones());
  inv.alexander = alexander_from_homfly(inv.homfly);
  inv.determinant = abs_at_t_minus_one(inv.jones);
  inv.fingerprint = homfly_fingerprint(inv.homfly);
  inv.mirror_fingerprint = homfly_fingerprint(inv.homfly.mirror_alpha());
  return inv;
}

ReginaCodes regina_codes(const KnotDiagram& diagram) {
  const regina::Link link = to_regina_link(diagram);
  ReginaCodes c;
  c.oriented_gauss = link.orientedGauss();
  if (link.countComponents() == 1) {
    c.gauss = link.gauss();
    // Regina writes DT codes for knots with at least one crossing (alphabetical: <= 26).
    if (link.size() > 0) {
      try {
        c.dt = link.dt(false);
        c.dt_alpha = link.dt(true);
      } catch (const std::exception&) {
        c.dt_alpha.clear();
      }
    }
  }
  return c;
}

bool is_unknot(const KnotDiagram& diagram, bool use_topology) {
  if (diagram.component_count() != 1) return false;
  regina::Link link = to_regina_link(diagram);
  link.intelligentSimplify();
  if (link.size() == 0) return true;
  if (!use_topology) return false;
  // The complement of a knot is a solid torus exactly when the knot is trivial.
  return link.complement().isSolidTorus();
}

}  // namespace s4d
