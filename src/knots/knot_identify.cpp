// Identification: a diagram's HOMFLY-PT fingerprint is looked up in the index, directly (prime
// knots), as a product of factors (composite knots), or per component (links).
#include "knots/knot_identify.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <Eigen/Eigenvalues>

#include "core/error.hpp"
#include "knots/braid_closure.hpp"
#include "proximity/shadow_crossings.hpp"

namespace s4d {

const char* chirality_name(Chirality c) {
  switch (c) {
    case Chirality::kAsTable: return "as-table";
    case Chirality::kMirror: return "mirror";
    case Chirality::kAmphichiral: return "amphichiral";
    case Chirality::kUnknown: return "unknown";
  }
  return "unknown";
}

const char* kind_name(KnotKind k) {
  switch (k) {
    case KnotKind::kUnknot: return "unknot";
    case KnotKind::kPrime: return "prime";
    case KnotKind::kComposite: return "composite";
    case KnotKind::kLink: return "link";
    case KnotKind::kUnknown: return "unknown";
  }
  return "unknown";
}

const char* sameness_name(Sameness s) {
  switch (s) {
    case Sameness::kSame: return "same";
    case Sameness::kMirror: return "mirror";
    case Sameness::kDifferent: return "different";
    case Sameness::kUndecided: return "undecided";
  }
  return "undecided";
}

std::string KnotFactor::text() const {
  std::string s = entry ? entry->display_name() : "?";
  if (chirality == Chirality::kMirror) s += " mirror";
  return s;
}

std::string factorisation_text(const KnotFactorisation& f) {
  std::string s;
  for (std::size_t i = 0; i < f.size(); ++i) s += (i ? " # " : "") + f[i].text();
  return s;
}

KnotDiagram component_diagram(const KnotDiagram& d, int component) {
  KnotDiagram out;
  out.components.resize(1);
  std::vector<int> new_crossing(d.crossings.size(), -1);
  for (int p : d.components.at(component)) {
    const Passage& v = d.passages[p];
    const DiagramCrossing& c = d.crossings[v.crossing];
    if (d.passages[c.over].component != d.passages[c.under].component) continue;
    if (new_crossing[v.crossing] < 0) {
      new_crossing[v.crossing] = static_cast<int>(out.crossings.size());
      out.crossings.push_back(c);
    }
    const int np = static_cast<int>(out.passages.size());
    out.passages.push_back({new_crossing[v.crossing], v.over, 0, v.position});
    (v.over ? out.crossings[new_crossing[v.crossing]].over
            : out.crossings[new_crossing[v.crossing]].under) = np;
    out.components[0].push_back(np);
  }
  out.normalise();
  return out;
}

namespace {

Chirality chirality_of(const KnotTableEntry& e, bool mirrored) {
  if (e.homfly_symmetric) return e.amphichiral ? Chirality::kAmphichiral : Chirality::kUnknown;
  return mirrored ? Chirality::kMirror : Chirality::kAsTable;
}

// Depth-first search for factorisations: the remaining fingerprint (and its mirror's) must be
// either one table entry (a leaf) or a small entry times the rest.
struct FactorSearch {
  const KnotIndex& index;
  std::vector<const KnotTableEntry*> small;  // entries that may be non-last factors
  std::set<std::vector<std::pair<const KnotTableEntry*, int>>> seen;
  std::vector<KnotFactorisation> found;
  int max_factors = 1;

  void leaf(std::uint64_t key, std::uint64_t mirror_key, int budget,
            std::vector<std::pair<const KnotTableEntry*, int>>& path) {
    for (int side = 0; side < 2; ++side) {
      for (const KnotTableEntry* e : index.with_key(side == 0 ? key : mirror_key)) {
        if (e->crossings > budget) continue;
        if (side == 1 && e->homfly_symmetric) continue;  // already found on side 0
        auto full = path;
        full.emplace_back(e, side);
        auto canon = full;
        std::sort(canon.begin(), canon.end());
        if (!seen.insert(canon).second) continue;
        KnotFactorisation f;
        for (const auto& [entry, mirrored] : canon) f.push_back({entry, chirality_of(*entry, mirrored)});
        found.push_back(std::move(f));
      }
    }
  }

  void search(std::uint64_t key, std::uint64_t mirror_key, int budget, std::size_t first,
              std::vector<std::pair<const KnotTableEntry*, int>>& path) {
    leaf(key, mirror_key, budget, path);
    if (static_cast<int>(path.size()) + 1 >= max_factors) return;
    for (std::size_t i = first; i < small.size(); ++i) {
      const KnotTableEntry* e = small[i];
      if (e->crossings + 3 > budget) continue;  // the rest needs at least 3 crossings
      for (int mirrored = 0; mirrored < (e->homfly_symmetric ? 1 : 2); ++mirrored) {
        const std::uint64_t k = mirrored ? e->mirror_key : e->key;
        const std::uint64_t km = mirrored ? e->key : e->mirror_key;
        path.emplace_back(e, mirrored);
        search(modp::mul(key, modp::inv(k)), modp::mul(mirror_key, modp::inv(km)),
               budget - e->crossings, i, path);
        path.pop_back();
      }
    }
  }
};

std::string prime_label(const KnotFactor& f) {
  const KnotTableEntry& e = *f.entry;
  std::string s = f.text();
  if (!e.rolfsen_name.empty() && !e.dt_name.empty()) s += " (DT " + e.dt_name + ")";
  return s;
}

bool is_one(const Laurent2& p) {
  return p.terms.size() == 1 && p.terms.count({0, 0}) && p.terms.at({0, 0}) == 1;
}

// (alpha - alpha^-1) / z to the power m - 1: the HOMFLY-PT polynomial of the m-component unlink.
Laurent2 unlink_homfly(int m) {
  Laurent2 r;
  r.add(0, 0, 1);
  Laurent2 delta;
  delta.add(1, -1, 1);
  delta.add(-1, -1, -1);
  for (int i = 1; i < m; ++i) r = r * delta;
  return r;
}

void identify_knot_invariants(KnotIdentification& id, const KnotIndex& index, bool prove_unknot) {
  const KnotInvariants& inv = id.invariants;
  const int c = inv.simplified_crossings;
  if (is_one(inv.homfly)) {
    id.kind = KnotKind::kUnknot;
    id.proven = c == 0 || is_unknot(id.diagram, prove_unknot);
    id.name = id.proven ? "unknot" : "unknot? (trivial HOMFLY-PT, not proven)";
    return;
  }
  FactorSearch fs{index, {}, {}, {}, std::max(1, c / 3)};
  for (const auto& e : index.entries())
    if (e.crossings <= KnotIndex::kFactorCrossings && e.mirror_key != 0) fs.small.push_back(&e);
  std::vector<std::pair<const KnotTableEntry*, int>> path;
  fs.search(inv.fingerprint, inv.mirror_fingerprint, c, 0, path);
  id.candidates = std::move(fs.found);
  std::sort(id.candidates.begin(), id.candidates.end(), [](const auto& x, const auto& y) {
    auto total = [](const KnotFactorisation& f) {
      int n = 0;
      for (const auto& k : f) n += k.entry->crossings;
      return n;
    };
    if (x.size() != y.size()) return x.size() < y.size();
    if (total(x) != total(y)) return total(x) < total(y);
    return factorisation_text(x) < factorisation_text(y);
  });
  if (id.candidates.empty()) {
    id.kind = KnotKind::kUnknown;
    id.name = c > index.max_crossings()
                  ? "unknown (" + std::to_string(c) + " crossings after simplification; the table "
                    "goes to " + std::to_string(index.max_crossings()) + ")"
                  : "unknown (not in the table, not a product of table knots)";
    return;
  }
  // With at most max_crossings after simplification, the knot is prime and in the census, or a
  // product the search covered; a single candidate is then the answer.
  id.proven = id.candidates.size() == 1 && c <= index.max_crossings();
  const auto& best = id.candidates.front();
  id.kind = best.size() == 1 ? KnotKind::kPrime : KnotKind::kComposite;
  if (id.candidates.size() == 1) {
    id.name = best.size() == 1 ? prime_label(best.front()) : factorisation_text(best);
  } else {
    id.name = "one of:";
    for (std::size_t i = 0; i < id.candidates.size(); ++i)
      id.name += (i ? ", " : " ") + factorisation_text(id.candidates[i]);
  }
}

// Well-known links by HOMFLY-PT, made once from braid words.
struct KnownLink {
  const char* name;
  int strands;
  std::vector<int> word;
};

std::string known_link_name(const KnotInvariants& inv) {
  static const std::vector<std::pair<std::uint64_t, std::string>> table = [] {
    const std::vector<KnownLink> links = {
        {"Hopf link (L2a1)", 2, {1, 1}},
        {"Solomon link (L4a1, T(2,4))", 2, {1, 1, 1, 1}},
        {"Borromean rings (L6a4)", 3, {1, -2, 1, -2, 1, -2}},
        {"T(2,6) torus link", 2, {1, 1, 1, 1, 1, 1}},
        {"T(3,3) torus link", 3, {1, 2, 1, 2, 1, 2}},
    };
    std::vector<std::pair<std::uint64_t, std::string>> t;
    for (const auto& l : links) {
      const KnotInvariants inv = compute_invariants(braid_diagram(l.strands, l.word));
      t.emplace_back(inv.fingerprint, l.name);
      if (inv.mirror_fingerprint != inv.fingerprint)
        t.emplace_back(inv.mirror_fingerprint, std::string(l.name) + " mirror");
    }
    return t;
  }();
  if (inv.homfly == unlink_homfly(inv.components))
    return "unlink of " + std::to_string(inv.components) + " components (by HOMFLY-PT)";
  for (const auto& [key, name] : table)
    if (key == inv.fingerprint) return name;
  return {};
}

}  // namespace

KnotIdentification identify_diagram(const KnotDiagram& diagram, const IdentifyOptions& options) {
  const KnotIndex& index = options.index ? *options.index : KnotIndex::shipped();
  KnotIdentification id;
  id.diagram = diagram;
  id.frame = options.frame;
  id.invariants = compute_invariants(diagram);
  if (diagram.component_count() == 1) {
    identify_knot_invariants(id, index, options.prove_unknot);
    return id;
  }
  id.kind = KnotKind::kLink;
  for (int i = 0; i < diagram.component_count(); ++i) {
    IdentifyOptions sub = options;
    sub.index = &index;
    id.components.push_back(identify_diagram(component_diagram(diagram, i), sub));
    id.components.back().frame = id.frame;
  }
  id.link_name = known_link_name(id.invariants);
  if (id.invariants.simplified_crossings == 0)
    id.link_name = "unlink of " + std::to_string(diagram.component_count()) + " components";
  id.proven = false;
  std::string s = id.link_name.empty() ? "link of " + std::to_string(diagram.component_count()) +
                                             " components"
                                       : id.link_name;
  s += ": ";
  for (std::size_t i = 0; i < id.components.size(); ++i) s += (i ? ", " : "") + id.components[i].name;
  const auto lk = id.invariants.linking;
  s += "; linking numbers";
  for (std::size_t i = 0; i < lk.size(); ++i)
    for (std::size_t j = i + 1; j < lk.size(); ++j)
      s += " lk(" + std::to_string(i) + "," + std::to_string(j) + ")=" + std::to_string(lk[i][j]);
  id.name = s;
  return id;
}

namespace {
// Candidate views: the given one, and views down each principal axis of the curve's points (a
// view down the axis of least spread usually shows the fewest crossings).
std::vector<Frame<3>> candidate_frames(const Curve<3>& curve, const Frame<3>& given) {
  std::vector<Frame<3>> frames{given};
  Vec3 mean = Vec3::Zero();
  const double n = static_cast<double>(curve.point_count());
  for (const auto& c : curve.components)
    for (const auto& p : c.points) mean += p;
  mean /= n;
  Mat<3> cov = Mat<3>::Zero();
  for (const auto& c : curve.components)
    for (const auto& p : c.points) cov += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Mat<3>> eig(cov);
  const Mat<3> v = eig.eigenvectors();  // columns by increasing eigenvalue
  for (int k = 0; k < 3; ++k) {
    Mat<3> r;
    r.col(2) = v.col(k);                  // depth along this axis
    r.col(0) = v.col((k + 1) % 3);
    r.col(1) = v.col((k + 2) % 3);
    frames.emplace_back(r);
  }
  return frames;
}
}  // namespace

KnotIdentification identify_knot(const Curve<3>& curve, const IdentifyOptions& options) {
  validate_knot_curve(curve);
  Frame<3> best = options.frame;
  if (options.choose_view) {
    std::size_t fewest = SIZE_MAX;
    for (const auto& f : candidate_frames(curve, options.frame)) {
      const auto found = shadow_crossings<3>(curve, f);
      if (found.crossings.size() < fewest) {
        fewest = found.crossings.size();
        best = f;
      }
    }
  }
  Frame<3> used;
  const KnotDiagram d = diagram_from_curve(curve, best, {}, &used);
  IdentifyOptions o = options;
  o.frame = used;
  return identify_diagram(d, o);
}

KnotComparison compare_knots(const Curve<3>& a, const Curve<3>& b, const IdentifyOptions& options) {
  KnotComparison r;
  r.a = identify_knot(a, options);
  r.b = identify_knot(b, options);
  const KnotInvariants& ia = r.a.invariants;
  const KnotInvariants& ib = r.b.invariants;
  if (ia.components != ib.components) {
    r.verdict = Sameness::kDifferent;
    r.reason = "they have different numbers of components";
    return r;
  }
  const bool same_poly = ia.homfly == ib.homfly;
  const bool mirror_poly = ia.homfly == ib.homfly.mirror_alpha();
  if (!same_poly && !mirror_poly) {
    r.verdict = Sameness::kDifferent;
    r.reason = "their HOMFLY-PT polynomials differ, even up to mirror image";
    return r;
  }
  if (ia.components == 1 && r.a.kind == KnotKind::kUnknot && r.b.kind == KnotKind::kUnknot &&
      r.a.proven && r.b.proven) {
    r.verdict = Sameness::kSame;
    r.reason = "both are the unknot";
    return r;
  }
  if (ia.components == 1 && r.a.proven && r.b.proven) {
    const auto& fa = r.a.candidates.front();
    const auto& fb = r.b.candidates.front();
    bool same_entries = fa.size() == fb.size();
    bool all_same = true, all_mirror = true, any_unknown = false;
    for (std::size_t i = 0; same_entries && i < fa.size(); ++i) {
      if (fa[i].entry != fb[i].entry) same_entries = false;
      const Chirality ca = fa[i].chirality, cb = fb[i].chirality;
      if (ca == Chirality::kUnknown) any_unknown = true;
      if (ca == Chirality::kAmphichiral || ca == Chirality::kUnknown) continue;
      all_same = all_same && ca == cb;
      all_mirror = all_mirror && ca != cb;
    }
    if (same_entries && !any_unknown) {
      if (all_same) {
        r.verdict = Sameness::kSame;
        r.reason = "both are " + r.a.name;
      } else if (all_mirror) {
        r.verdict = Sameness::kMirror;
        r.reason = "one is the mirror image of the other (" + r.a.name + " and " + r.b.name + ")";
      } else {
        r.verdict = Sameness::kDifferent;
        r.reason = "different chiralities of the factors (" + r.a.name + " and " + r.b.name + ")";
      }
      return r;
    }
    if (!same_entries) {
      r.verdict = Sameness::kDifferent;
      r.reason = "they are " + r.a.name + " and " + r.b.name;
      return r;
    }
  }
  r.verdict = Sameness::kUndecided;
  r.reason = same_poly ? "they have the same HOMFLY-PT polynomial, which does not decide"
                       : "their HOMFLY-PT polynomials are mirror images, which does not decide";
  return r;
}

}  // namespace s4d
