// The user study's two exercises (paper section 6; issue 26, point 8), engine side: "are these
// the same knot?" answered with its reason, and "unknot it by one crossing change" checked for
// every crossing of a diagram. Both can take seconds on hard cases: call them off the UI thread.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/frame.hpp"
#include "knots/knot_info.hpp"
#include "shape/curve.hpp"

namespace s4d {

enum class SameAnswer { kSame, kDifferent, kCannotTell };
const char* same_answer_name(SameAnswer a);  // "same", "different", "cannot tell"

struct SameKnotAnswer {
  SameAnswer answer = SameAnswer::kCannotTell;
  bool mirror_images = false;  // the two are mirror images of each other (a chiral knot: different)
  std::string reason;          // one sentence: which invariant differs, or what both are (proven)
  KnotInfo a, b;
};

// Knots: same when both are proven to be the same table knot with the same chirality (or an
// amphichiral one); different when an invariant differs (components, linking numbers,
// determinant, Alexander, Jones, HOMFLY-PT, covers) or both are proven different knots; a chiral
// knot and its mirror image are different, and the reason says so. Links are compared by what
// does not depend on the orientation of their components. Throws Error for invalid curves.
SameKnotAnswer same_knot(const Curve<3>& a, const Curve<3>& b, const KnotInfoOptions& options = {});

// The user's answer to "are these the same knot?" judged by the tool's.
struct SameKnotJudgement {
  bool decided = false;  // the invariants decide (same or different); else the user cannot be judged
  bool right = false;    // the user's answer agrees with the decided one
  std::string text;      // "Right: they are different: ...", "Wrong: ...", "The tool cannot tell: ..."
};
SameKnotJudgement judge_same_answer(const SameKnotAnswer& tool, bool user_says_same);

// A pair for the exercise, from the table: the second is drawn turned, so that the two diagrams
// differ even when the knots are the same (mirror images, redrawings, look-alikes with equal
// Jones or Alexander polynomials).
struct SameKnotPair {
  std::string a, b;
  bool same = false;  // the truth, from the tables (the tests hold same_knot to it)
};
const std::vector<SameKnotPair>& same_knot_exercise_pairs();

// The pair `seed` picks (any seed; the same seed, the same pair) as two curves: the second turned
// by a rotation the seed picks and placed beside the first along x, apart by half their size.
struct SameKnotExercise {
  SameKnotPair names;
  Curve<3> a, b;
};
SameKnotExercise make_same_knot_exercise(unsigned seed);

// Moves `b` along x so that it starts beyond where `a` ends (by half the larger of their sizes),
// centred on a's middle in y and z: two knots side by side. Nothing moves when either is empty.
void place_beside(const Curve<3>& a, Curve<3>& b);

struct CrossingChangeResult {
  int label = 0;              // the crossing, 1-based as in the diagram's codes (`knot code`)
  Vec2 point = Vec2::Zero();  // where it is in the view's shadow coordinates
  bool unknots = false;       // changing it gives the unknot
  bool proven = true;         // that answer is proven (always, unless recognition was skipped)
  std::string result;         // the name of what the change gives ("unknot", "4_1", ...)
};

struct UnknottingReport {
  std::string knot;        // the name of the knot as drawn
  bool is_unknot = false;  // it already is the unknot (no change is needed)
  Frame<3> frame;          // the view used (a tiny turn of the one asked for when not generic)
  std::vector<CrossingChangeResult> crossings;  // one per crossing of the diagram, by label
  std::vector<int> unknotting;                  // labels of the crossings whose change unknots it
};

// For each crossing of the curve's diagram in `view` (nullopt: its own xy), whether changing
// that crossing alone gives the unknot: proven by simplification to no crossings, refuted by a
// non-trivial HOMFLY-PT polynomial, else decided by Regina's solid-torus recognition. Throws
// Error for invalid curves and for links (a crossing change of a knot is asked for).
UnknottingReport unknotting_crossings(const Curve<3>& curve,
                                      const std::optional<Frame<3>>& view = std::nullopt);

// Knots whose unknotting number is one, drawn by the table so that one crossing of their diagram
// in the curve's own view unknots them (the tests check each).
const std::vector<std::string>& unknotting_exercise_knots();
// The knot `seed` picks among them (any seed), as make_table_knot draws it.
std::string pick_unknotting_exercise(unsigned seed);

// The verdict on the user's choice of crossing `label` of report: whether that change unknots it
// and which crossings would have. Empty when the report has no such crossing.
std::string unknotting_verdict(const UnknottingReport& report, int label);

// The label of the crossing nearest `point` (shadow coordinates of report.frame), or 0 for none.
int nearest_crossing(const UnknottingReport& report, const Vec2& point);

}  // namespace s4d
