// The exercises: comparison by invariants from the cheapest that can differ to the proofs, and
// crossing changes tried one at a time on the combinatorial diagram.
#include "knots/knot_exercises.hpp"

#include <algorithm>
#include <limits>
#include <random>

#include "core/error.hpp"
#include "knots/knot_table.hpp"

namespace s4d {

const char* same_answer_name(SameAnswer a) {
  switch (a) {
    case SameAnswer::kSame:
      return "same";
    case SameAnswer::kDifferent:
      return "different";
    case SameAnswer::kCannotTell:
      return "cannot tell";
  }
  return "cannot tell";
}

namespace {

std::vector<int> abs_linking(const KnotInfo& k) {
  std::vector<int> out;
  for (std::size_t i = 0; i < k.linking.size(); ++i)
    for (std::size_t j = i + 1; j < k.linking.size(); ++j) out.push_back(std::abs(k.linking[i][j]));
  std::sort(out.begin(), out.end());
  return out;
}

// A prime or composite knot proven to be one table answer: its factors as (entry, chirality).
const KnotFactorisation* proven_answer(const KnotInfo& k) {
  const auto& id = k.identification;
  if (!id.proven || id.candidates.size() != 1) return nullptr;
  return &id.candidates[0];
}

std::string proof_words(const KnotInfo& k) {
  if (k.decided_by.empty()) return "";
  std::string s = " (by ";
  for (std::size_t i = 0; i < k.decided_by.size(); ++i) s += (i ? "; " : "") + k.decided_by[i];
  return s + ")";
}

bool chirality_matters(Chirality c) { return c == Chirality::kAsTable || c == Chirality::kMirror; }

SameKnotAnswer compare_links(SameKnotAnswer r) {
  const KnotInfo &a = r.a, &b = r.b;
  if (abs_linking(a) != abs_linking(b)) {
    r.answer = SameAnswer::kDifferent;
    r.reason = "their linking numbers differ (up to the orientation of the components)";
    return r;
  }
  if (a.determinant != b.determinant) {
    r.answer = SameAnswer::kDifferent;
    r.reason = "their determinants differ (" + std::to_string(a.determinant) + " and " +
               std::to_string(b.determinant) + ")";
    return r;
  }
  std::vector<std::string> ca, cb;
  for (const auto& c : a.identification.components) ca.push_back(c.name);
  for (const auto& c : b.identification.components) cb.push_back(c.name);
  std::sort(ca.begin(), ca.end());
  std::sort(cb.begin(), cb.end());
  bool components_proven = true;
  for (const auto* l : {&a, &b})
    for (const auto& c : l->identification.components) components_proven = components_proven && c.proven;
  if (ca != cb && components_proven) {
    r.answer = SameAnswer::kDifferent;
    r.reason = "their components are different knots";
    return r;
  }
  if (a.simplified_crossings == 0 && b.simplified_crossings == 0) {
    r.answer = SameAnswer::kSame;
    r.reason =
        "both are the unlink of " + std::to_string(a.components) + " components (proven by simplification)";
    return r;
  }
  r.answer = SameAnswer::kCannotTell;
  r.reason =
      "the invariants that do not depend on the orientation of the components agree; that does not decide";
  return r;
}

}  // namespace

SameKnotAnswer same_knot(const Curve<3>& ca, const Curve<3>& cb, const KnotInfoOptions& options) {
  SameKnotAnswer r;
  r.a = knot_info(ca, std::nullopt, options);
  r.b = knot_info(cb, std::nullopt, options);
  const KnotInfo &a = r.a, &b = r.b;
  const KnotInvariants &ia = a.identification.invariants, &ib = b.identification.invariants;
  if (a.components != b.components) {
    r.answer = SameAnswer::kDifferent;
    r.reason = "the first has " + std::to_string(a.components) + " component(s), the second " +
               std::to_string(b.components);
    return r;
  }
  if (a.components > 1) return compare_links(std::move(r));

  r.mirror_images = ia.homfly == ib.homfly.mirror_alpha();
  const auto* pa = proven_answer(a);
  const auto* pb = proven_answer(b);
  const bool unknot_a = a.identification.kind == KnotKind::kUnknot && a.proven;
  const bool unknot_b = b.identification.kind == KnotKind::kUnknot && b.proven;
  if (unknot_a && unknot_b) {
    r.answer = SameAnswer::kSame;
    r.mirror_images = true;
    r.reason = "both are the unknot" + proof_words(a);
    return r;
  }
  // Both proven table answers: same or different by name and chirality.
  if (pa && pb) {
    bool same_entries = pa->size() == pb->size();
    for (std::size_t i = 0; same_entries && i < pa->size(); ++i)
      same_entries = (*pa)[i].entry == (*pb)[i].entry;
    if (same_entries) {
      bool same = true;
      for (std::size_t i = 0; i < pa->size(); ++i)
        if (chirality_matters((*pa)[i].chirality) && (*pa)[i].chirality != (*pb)[i].chirality) same = false;
      bool unknown = false;
      for (const auto& f : *pa) unknown = unknown || f.chirality == Chirality::kUnknown;
      if (!same) {
        r.answer = SameAnswer::kDifferent;
        r.reason =
            "one is " + a.name + ", the other " + b.name + ": " +
            (pa->size() == 1 ? pa->front().entry->display_name() + " is chiral and these are mirror images"
                             : std::string("their factors differ in chirality")) +
            " (HOMFLY-PT tells them apart)";
        return r;
      }
      if (!unknown) {
        r.answer = SameAnswer::kSame;
        r.reason = "both are " + a.name + ", proven" + proof_words(a);
        return r;
      }
      r.answer = SameAnswer::kCannotTell;
      r.reason = "both are " + pa->front().entry->display_name() +
                 ", but whether they are the same or mirror images cannot be told: its HOMFLY-PT polynomial "
                 "is symmetric";
      return r;
    }
  }
  // Invariants, cheapest first: any difference proves they are different knots.
  struct Check {
    const char* what;
    bool differ;
    std::string va, vb;
  };
  const Check checks[] = {
      {"determinants", ia.determinant != ib.determinant, std::to_string(ia.determinant),
       std::to_string(ib.determinant)},
      {"Alexander polynomials", !(ia.alexander == ib.alexander), a.alexander, b.alexander},
      {"Jones polynomials", !(ia.jones == ib.jones), a.jones, b.jones},
      {"HOMFLY-PT polynomials", !(ia.homfly == ib.homfly), a.homfly, b.homfly},
  };
  for (const Check& c : checks)
    if (c.differ) {
      r.answer = SameAnswer::kDifferent;
      r.reason = std::string("their ") + c.what + " differ (" + c.va + " and " + c.vb + ")";
      if (pa && pb) r.reason = "one is " + a.name + ", the other " + b.name + ": " + r.reason;
      if (r.mirror_images)
        r.reason +=
            "; they are the HOMFLY-PT of mirror images: a chiral knot and its mirror image are different "
            "knots";
      return r;
    }
  // Same polynomials: the further invariants may have split the candidates.
  std::vector<std::string> shared;
  for (const auto& x : a.candidates)
    if (std::find(b.candidates.begin(), b.candidates.end(), x) != b.candidates.end()) shared.push_back(x);
  if (shared.empty() && !a.candidates.empty() && !b.candidates.empty() &&
      a.identification.invariants.simplified_crossings <= 14 &&
      b.identification.invariants.simplified_crossings <= 14) {
    r.answer = SameAnswer::kDifferent;
    r.reason = "their polynomials agree, but no knot is a candidate for both (first: " + a.name +
               "; second: " + b.name + ")" + proof_words(a);
    return r;
  }
  r.answer = SameAnswer::kCannotTell;
  r.reason = "they share every invariant computed (HOMFLY-PT, Jones, Alexander" +
             std::string(a.further_used.empty() ? "" : ", and the further invariants") +
             "), which does not decide: " + "both may be any of " +
             std::to_string(std::max<std::size_t>(shared.size(), 1)) + " knot(s)";
  return r;
}

UnknottingReport unknotting_crossings(const Curve<3>& curve, const std::optional<Frame<3>>& view) {
  UnknottingReport r;
  Frame<3> used;
  const KnotDiagram d = diagram_from_curve(curve, view.value_or(Frame<3>()), {}, &used);
  if (d.component_count() != 1)
    throw Error("the unknotting exercise needs a knot; this curve has " +
                std::to_string(d.component_count()) + " components");
  r.frame = used;
  NamingOptions o;
  o.frame = used;
  const KnotNaming knot = name_diagram(d, o);
  r.knot = knot.name();
  r.is_unknot = knot.identification.kind == KnotKind::kUnknot && knot.proven();
  for (int k = 0; k < d.crossing_count(); ++k) {
    CrossingChangeResult c;
    c.label = k + 1;
    c.point = d.crossings[k].point;
    // Named as everywhere else: an unknot by its invariants is proven (or refuted) by recognition.
    const KnotNaming after = name_diagram(d.with_crossing_changed(k), o);
    c.unknots = after.identification.kind == KnotKind::kUnknot && after.proven();
    c.proven = after.identification.kind != KnotKind::kUnknot || after.proven();
    c.result = after.name();
    if (c.unknots) r.unknotting.push_back(c.label);
    r.crossings.push_back(std::move(c));
  }
  return r;
}

SameKnotJudgement judge_same_answer(const SameKnotAnswer& tool, bool user_says_same) {
  SameKnotJudgement j;
  if (tool.answer == SameAnswer::kCannotTell) {
    j.text = "The tool cannot tell either: " + tool.reason + ".";
    return j;
  }
  j.decided = true;
  const bool same = tool.answer == SameAnswer::kSame;
  j.right = same == user_says_same;
  j.text = std::string(j.right ? "Right" : "Wrong") + ": they are " + (same ? "the same knot" : "different") +
           " (" + tool.reason + ").";
  return j;
}

const std::vector<SameKnotPair>& same_knot_exercise_pairs() {
  // Mirror images of chiral and of amphichiral knots, redrawings, and look-alikes: 5_1 and 10_132
  // share their Jones polynomial, 6_1 and 9_46 their Alexander polynomial.
  static const std::vector<SameKnotPair> pairs = {
      {"3_1", "3_1 mirror", false}, {"3_1", "3_1", true},          {"4_1", "4_1 mirror", true},
      {"5_1", "5_2", false},        {"5_2", "5_2 mirror", false},  {"5_1", "10_132", false},
      {"6_1", "9_46", false},       {"6_2", "6_2", true},          {"6_3", "6_3 mirror", true},
      {"7_4", "7_4 mirror", false}, {"7_7", "7_6", false},         {"8_3", "8_3 mirror", true},
  };
  return pairs;
}

void place_beside(const Curve<3>& a, Curve<3>& b) {
  auto box = [](const Curve<3>& c) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const auto& pl : c.components)
      for (const Vec3& p : pl.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    return std::pair{lo, hi};
  };
  const auto [alo, ahi] = box(a);
  const auto [blo, bhi] = box(b);
  if (!alo.allFinite() || !ahi.allFinite() || !blo.allFinite() || !bhi.allFinite()) return;
  const double gap = 0.5 * std::max((ahi - alo).maxCoeff(), (bhi - blo).maxCoeff());
  Vec3 shift = 0.5 * (alo + ahi) - 0.5 * (blo + bhi);
  shift.x() = ahi.x() + gap - blo.x();
  for (auto& pl : b.components)
    for (Vec3& p : pl.points) p += shift;
}

SameKnotExercise make_same_knot_exercise(unsigned seed) {
  std::mt19937 rng(seed);
  const auto& pairs = same_knot_exercise_pairs();
  SameKnotExercise e;
  e.names = pairs[std::uniform_int_distribution<std::size_t>(0, pairs.size() - 1)(rng)];
  e.a = make_table_knot(e.names.a);
  e.b = make_table_knot(e.names.b);
  // A turn away from the table's own picture, so that the same knot is drawn otherwise.
  std::normal_distribution<double> g;
  const Mat<3> turn = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
  for (auto& pl : e.b.components)
    for (Vec3& p : pl.points) p = turn * p;
  place_beside(e.a, e.b);
  return e;
}

const std::vector<std::string>& unknotting_exercise_knots() {
  static const std::vector<std::string> knots = {"3_1", "4_1", "5_2", "6_1", "6_2", "6_3",
                                                 "7_2", "7_6", "7_7", "8_1"};
  return knots;
}

std::string pick_unknotting_exercise(unsigned seed) {
  std::mt19937 rng(seed);
  const auto& knots = unknotting_exercise_knots();
  const std::string name = knots[std::uniform_int_distribution<std::size_t>(0, knots.size() - 1)(rng)];
  return std::bernoulli_distribution(0.5)(rng) ? name + " mirror" : name;
}

std::string unknotting_verdict(const UnknottingReport& r, int label) {
  std::string others;
  for (int l : r.unknotting) others += (others.empty() ? "" : ", ") + std::to_string(l);
  for (const CrossingChangeResult& c : r.crossings) {
    if (c.label != label) continue;
    return std::string(c.unknots ? "Yes: " : "No: ") + "changing crossing " + std::to_string(label) + " of " +
           r.knot + " gives " + c.result + ". " +
           (r.is_unknot            ? "It is the unknot already."
            : r.unknotting.empty() ? "No single change of this diagram unknots it."
                                   : "The crossings whose change unknots it: " + others + ".");
  }
  return {};
}

int nearest_crossing(const UnknottingReport& report, const Vec2& point) {
  int best = 0;
  double best_d = 0;
  for (const auto& c : report.crossings) {
    const double dd = (c.point - point).squaredNorm();
    if (best == 0 || dd < best_d) {
      best = c.label;
      best_d = dd;
    }
  }
  return best;
}

}  // namespace s4d
