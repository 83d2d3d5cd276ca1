// Identification: a diagram's HOMFLY-PT fingerprint is looked up in the index, directly (prime
// knots), as a product of factors (composite knots), or per component (links).
#include "knots/knot_identify.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <set>
#include <tuple>
#include <unordered_map>

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

std::string LinkCandidate::text() const {
  if (!entry) return other;
  return entry->name + (chirality == Chirality::kMirror ? " mirror" : "");
}

std::string knot_type_up_to_mirror(const KnotIdentification& k) {
  if (k.kind == KnotKind::kUnknot && k.proven) return "unknot";
  if (!k.proven || k.candidates.size() != 1) return "?";
  std::vector<std::string> factors;
  for (const auto& f : k.candidates[0]) factors.push_back(f.entry->display_name());
  std::sort(factors.begin(), factors.end());
  std::string s;
  for (const auto& f : factors) s += (s.empty() ? "" : "#") + f;
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

void identify_knot_invariants(KnotIdentification& id, const KnotIndex& index, bool prove_unknot, KnotEngine engine) {
  const KnotInvariants& inv = id.invariants;
  const int c = inv.simplified_crossings;
  if (is_one(inv.homfly)) {
    id.kind = KnotKind::kUnknot;
    id.proven = c == 0 || is_unknot(id.diagram, prove_unknot, engine);
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

// [SECTION] links

// Multisets of component knot types, "?" matching any one type.
bool same_knot_types(std::vector<std::string> table, std::vector<std::string> mine) {
  if (table.size() != mine.size()) return false;
  int wild_table = 0, wild_mine = 0;
  for (const auto& t : table) wild_table += t == "?";
  for (const auto& m : mine) wild_mine += m == "?";
  int unmatched_mine = 0;
  for (const auto& m : mine) {
    if (m == "?") continue;
    const auto it = std::find(table.begin(), table.end(), m);
    if (it == table.end()) ++unmatched_mine;
    else *it = "=";
  }
  int unmatched_table = 0;
  for (const auto& t : table) unmatched_table += t != "?" && t != "=";
  return unmatched_mine <= wild_table && unmatched_table <= wild_mine;
}

// A prime piece a split or composite link could be made of: a knot or a table link, in one
// orientation and chirality.
struct LinkPiece {
  std::uint64_t key = 0, inverse = 0;  // fingerprint and its inverse mod p
  int crossings = 0;
  std::string text;
  std::vector<std::string> knots;  // its components' knot types (LinkTableEntry::component_knots)
  std::vector<int> abs_linking;    // as LinkTableEntry::abs_linking
};

struct LinkPieces {
  std::vector<LinkPiece> all;                          // by crossings
  std::unordered_multimap<std::uint64_t, int> by_key;  // key: index into all
  std::uint64_t delta_inverse = 0;                     // 1 / P(2-component unlink)
};

// Knots of the index (both chiralities known up to kFactorCrossings) and every orientation of the
// table's links, made once per (index, table).
const LinkPieces& link_pieces(const KnotIndex& index, const LinkTable& links) {
  static std::mutex mutex;
  static std::map<std::pair<const KnotIndex*, const LinkTable*>, LinkPieces> made;
  std::lock_guard<std::mutex> lock(mutex);
  auto [it, fresh] = made.try_emplace({&index, &links});
  LinkPieces& p = it->second;
  if (!fresh) return p;
  auto add = [&](std::uint64_t key, int crossings, std::string text, std::vector<std::string> knots,
                 std::vector<int> abs_linking) {
    p.all.push_back({key, modp::inv(key), crossings, std::move(text), std::move(knots), std::move(abs_linking)});
  };
  for (const auto& e : index.entries())
    if (e.crossings <= KnotIndex::kFactorCrossings && e.mirror_key != 0) {
      add(e.key, e.crossings, e.display_name(), {e.display_name()}, {});
      if (!e.homfly_symmetric) add(e.mirror_key, e.crossings, e.display_name() + " mirror", {e.display_name()}, {});
    }
  for (const auto& l : links.entries()) {
    for (auto k : l.keys) add(k, l.crossings, l.name, l.component_knots, l.abs_linking);
    for (auto k : l.mirror_keys)
      if (std::find(l.keys.begin(), l.keys.end(), k) == l.keys.end())
        add(k, l.crossings, l.name + " mirror", l.component_knots, l.abs_linking);
  }
  std::stable_sort(p.all.begin(), p.all.end(), [](const LinkPiece& a, const LinkPiece& b) { return a.crossings < b.crossings; });
  for (std::size_t i = 0; i < p.all.size(); ++i) p.by_key.emplace(p.all[i].key, static_cast<int>(i));
  p.delta_inverse = modp::inv(homfly_fingerprint(unlink_homfly(2)));
  return p;
}

// Split or composite links whose HOMFLY-PT polynomial is `key`: P(A # B) = P(A) P(B) and
// P(A split from B) = delta P(A) P(B), so `key` = delta^s times a product of pieces of at most
// `budget` crossings in all (at least two pieces, or one and s >= 1). Stops after `limit`.
struct LinkPieceSearch {
  const LinkPieces& pieces;
  const std::vector<std::string>& knots;  // the link's components' types (knot_type_up_to_mirror)
  const std::vector<int>& abs_linking;    // and its |lk|, sorted
  std::size_t limit = 4;
  std::vector<std::string> found;

  // Without connected sums the components and linking numbers of the split link are known: they
  // must be the link's own.
  bool possible(const std::vector<const LinkPiece*>& path, int splits) const {
    const int k = static_cast<int>(path.size());
    if (k - 1 > splits) return true;  // connected sums mix components: not checked
    std::vector<std::string> types;
    std::vector<int> lk;
    for (const LinkPiece* p : path) {
      types.insert(types.end(), p->knots.begin(), p->knots.end());
      lk.insert(lk.end(), p->abs_linking.begin(), p->abs_linking.end());
    }
    for (int i = std::max(0, k - 1); i < splits; ++i) types.push_back("unknot");
    const std::size_t m = types.size();
    if (m != knots.size()) return false;
    lk.resize(m * (m - 1) / 2, 0);  // pairs in different parts are unlinked
    std::sort(lk.begin(), lk.end());
    return lk == abs_linking && same_knot_types(types, knots);
  }

  void record(std::vector<const LinkPiece*> path, int splits) {
    if (!possible(path, splits)) return;
    std::sort(path.begin(), path.end(), [](const LinkPiece* a, const LinkPiece* b) {
      return std::tie(a->crossings, a->text) < std::tie(b->crossings, b->text);
    });
    std::string text = describe(path, splits);
    if (std::find(found.begin(), found.end(), text) == found.end()) found.push_back(std::move(text));
  }

  static std::string describe(const std::vector<const LinkPiece*>& path, int splits) {
    const int k = static_cast<int>(path.size());
    const int sums = std::max(0, k - 1 - splits);  // the rest of the joins are splits
    std::string s = splits ? "split: " : "";
    for (int i = 0; i < k; ++i) s += (i == 0 ? "" : i <= sums ? " # " : " and ") + path[i]->text;
    for (int i = std::max(0, k - 1); i < splits; ++i) s += " and unknot";
    return s;
  }

  void search(std::uint64_t rest, int budget, std::size_t first, int splits, std::vector<const LinkPiece*>& path) {
    if (found.size() >= limit) return;
    const bool enough = path.size() >= 1 && (path.size() >= 2 || splits >= 1);
    if (rest == 1 && enough) record(path, splits);
    for (auto [lo, hi] = pieces.by_key.equal_range(rest); lo != hi; ++lo) {
      const LinkPiece& leaf = pieces.all[lo->second];
      if (leaf.crossings > budget || (path.empty() && splits == 0) || found.size() >= limit) continue;
      path.push_back(&leaf);
      record(path, splits);
      path.pop_back();
    }
    for (std::size_t i = first; i < pieces.all.size(); ++i) {
      const LinkPiece& p = pieces.all[i];
      if (p.crossings + 2 > budget) break;  // the rest needs a piece of at least 2 crossings
      path.push_back(&p);
      search(modp::mul(rest, p.inverse), budget - p.crossings, i, splits, path);
      path.pop_back();
    }
  }
};

std::string link_summary(const KnotIdentification& id) {
  std::string s = "link of " + std::to_string(id.components.size()) + " components: ";
  for (std::size_t i = 0; i < id.components.size(); ++i) s += (i ? ", " : "") + id.components[i].name;
  const auto& lk = id.invariants.linking;
  s += "; linking numbers";
  for (std::size_t i = 0; i < lk.size(); ++i)
    for (std::size_t j = i + 1; j < lk.size(); ++j)
      s += " lk(" + std::to_string(i) + "," + std::to_string(j) + ")=" + std::to_string(lk[i][j]);
  return s;
}

// What a table link must share with the link besides HOMFLY-PT: its components' knot types (up to
// mirror image) and the sorted |linking numbers| of its pairs of components.
struct LinkTraits {
  std::vector<std::string> knots;
  std::vector<int> abs_linking;
};

LinkTraits link_traits(const KnotIdentification& id) {
  LinkTraits t;
  for (const auto& k : id.components) t.knots.push_back(knot_type_up_to_mirror(k));
  const int m = id.invariants.components;
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j) t.abs_linking.push_back(std::abs(id.invariants.linking[i][j]));
  std::sort(t.abs_linking.begin(), t.abs_linking.end());
  return t;
}

std::string table_range(const LinkTable& links) {
  return "up to " + std::to_string(links.max_crossings()) + " crossings";
}

void identify_link(KnotIdentification& id, const KnotIndex& index, const LinkTable& links) {
  const KnotInvariants& inv = id.invariants;
  const int m = inv.components, c = inv.simplified_crossings;
  if (inv.homfly == unlink_homfly(m)) {
    id.proven = c == 0;
    id.link_name = "unlink of " + std::to_string(m) + " components";
    id.name = id.link_name + (c == 0 ? "" : " (by HOMFLY-PT)") + ": " + link_summary(id);
    return;
  }
  if (inv.simplified_pieces > 1) {  // Regina's simplification separated it: split, outside the table
    id.name = "split link, not in the table (which holds non-split links " + table_range(links) + "): " + link_summary(id);
    return;
  }
  const LinkTraits traits = link_traits(id);
  for (const LinkMatch& match : links.with_key(inv.fingerprint)) {
    const LinkTableEntry& e = *match.entry;
    if (e.components != m || e.abs_linking != traits.abs_linking || !same_knot_types(e.component_knots, traits.knots))
      continue;
    const Chirality ch = match.as_table && match.mirror ? Chirality::kUnknown
                         : match.mirror                 ? Chirality::kMirror
                                                        : Chirality::kAsTable;
    id.link_candidates.push_back({&e, ch, {}});
  }
  settle_link(id, index, links);
}

}  // namespace

void settle_link(KnotIdentification& id, const KnotIndex& index, const LinkTable& links) {
  const KnotInvariants& inv = id.invariants;
  const int m = inv.components, c = inv.simplified_crossings;
  std::erase_if(id.link_candidates, [](const LinkCandidate& l) { return l.entry == nullptr; });  // found again below
  id.proven = false;
  id.link_name.clear();
  const std::size_t table_candidates = id.link_candidates.size();
  if (table_candidates == 1 && c <= links.max_crossings()) {
    // Proven unless a split or composite link (outside the table) has the same invariants.
    const LinkTraits traits = link_traits(id);
    LinkPieceSearch search{link_pieces(index, links), traits.knots, traits.abs_linking, 4, {}};
    std::vector<const LinkPiece*> path;
    std::uint64_t rest = inv.fingerprint;
    for (int splits = 0; splits < m; ++splits) {
      search.search(rest, c, 0, splits, path);
      rest = modp::mul(rest, search.pieces.delta_inverse);
    }
    for (auto& other : search.found) id.link_candidates.push_back({nullptr, Chirality::kUnknown, std::move(other)});
    id.proven = search.found.empty();
  }
  if (table_candidates == 0) {
    id.name = "not in the table (" + table_range(links) + ")" +
              (c > links.max_crossings() ? ", " + std::to_string(c) + " crossings after simplification" : "") +
              ": " + link_summary(id);
    return;
  }
  if (id.link_candidates.size() == 1) {
    const LinkCandidate& only = id.link_candidates.front();
    id.link_name = only.entry->alias;
    id.name = only.text() + (only.entry->alias.empty() ? "" : " (" + only.entry->alias + ")");
    return;
  }
  id.name = "one of:";
  for (std::size_t i = 0; i < id.link_candidates.size(); ++i)
    id.name += (i ? ", " : " ") + id.link_candidates[i].text();
}

KnotIdentification identify_diagram(const KnotDiagram& diagram, const IdentifyOptions& options) {
  const KnotIndex& index = options.index ? *options.index : KnotIndex::shipped();
  KnotIdentification id;
  id.diagram = diagram;
  id.frame = options.frame;
  id.invariants = compute_invariants(diagram, options.engine);
  if (diagram.component_count() == 1) {
    identify_knot_invariants(id, index, options.prove_unknot, options.engine);
    return id;
  }
  id.kind = KnotKind::kLink;
  for (int i = 0; i < diagram.component_count(); ++i) {
    IdentifyOptions sub = options;
    sub.index = &index;
    id.components.push_back(identify_diagram(component_diagram(diagram, i), sub));
    id.components.back().frame = id.frame;
  }
  identify_link(id, index, options.links ? *options.links : LinkTable::shipped());
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
