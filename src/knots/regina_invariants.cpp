// The bridge to Regina: our KnotDiagram becomes a regina::Link; Regina simplifies it and computes
// the polynomials, which come back as our own Laurent types.
#include <triangulation/dim3.h>

#include "core/error.hpp"
#include "knots/diagram_moves.hpp"
#include "knots/regina_engine.hpp"
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

// Regina's Laurent2 keeps its terms private. By Morton's bounds the powers of alpha of an
// n-crossing, m-component diagram lie within writhe -+ (s - 1) for its s <= n + m Seifert circles,
// so within [-(2n + m), 2n + m]; those of z within [1 - m, n]. Probing that box is exact. (A box of
// n + m + 1 lost alpha^-14 of 11a_263, which the own engine's tests found.)
Laurent2 from_regina(const regina::Laurent2<regina::Integer>& p, long bound) {
  Laurent2 r;
  for (long i = -bound; i <= bound; ++i)
    for (long j = -bound; j <= bound; ++j) {
      const auto& c = p(i, j);
      if (!c.isZero()) r.add(i, j, c.longValue());
    }
  return r;
}

}  // namespace

KnotInvariants regina_invariants(const KnotDiagram& diagram) {
  KnotInvariants inv;  // the simplification and the polynomials; compute_invariants does the rest
  regina::Link link = to_regina_link(diagram);
  link.intelligentSimplify();
  inv.simplified_crossings = static_cast<int>(link.size());
  inv.simplified_alternating = link.isAlternating();
  if (link.size() > 0) inv.simplified_pd = link.pd();
  inv.simplified_pieces = diagram_pieces(diagram_from_regina(link));

  const long bound = 2 * static_cast<long>(link.size() + link.countComponents()) + 1;
  inv.homfly = from_regina(link.homflyAZ(), bound);
  inv.jones = from_regina(link.jones());
  return inv;
}

ReginaCodes regina_code_texts(const KnotDiagram& diagram) {
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

bool regina_is_unknot(const KnotDiagram& diagram, bool use_topology) {
  if (diagram.component_count() != 1) return false;
  regina::Link link = to_regina_link(diagram);
  link.intelligentSimplify();
  if (link.size() == 0) return true;
  if (!use_topology) return false;
  // The complement of a knot is a solid torus exactly when the knot is trivial.
  return link.complement().isSolidTorus();
}

}  // namespace s4d
