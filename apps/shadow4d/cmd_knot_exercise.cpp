// The user study's exercises headless (the window's "New pair" and "New knot"): `knot exercise`
// makes one, `knot compare` and `knot unknotting` answer and judge it.
#include <iostream>
#include <memory>
#include <optional>

#include "core/error.hpp"
#include "io/object_file.hpp"
#include "knot_commands.hpp"
#include "knot_input.hpp"
#include "knots/knot_exercises.hpp"
#include "knots/knot_table.hpp"

namespace s4d::cli {

using nlohmann::json;

void add_knot_compare(CLI::App& knot) {
  struct Args {
    KnotCurveArgs curve;
    std::string file_b, user_answer;
  };
  auto a = std::make_shared<Args>();
  auto* compare = knot.add_subcommand("compare", "are two curves the same knot? (the user-study exercise)");
  add_curve_args(compare, a->curve, false);
  compare->add_option("other", a->file_b, "the second curve")->required();
  compare->add_option("--answer", a->user_answer, "your answer, judged by the invariants: same or different")
      ->check(CLI::IsMember({"same", "different"}));
  compare->callback([a] {
    const auto r = same_knot(load_knot_curve(a->curve.file), load_knot_curve(a->file_b));
    std::optional<SameKnotJudgement> judged;
    if (!a->user_answer.empty()) judged = judge_same_answer(r, a->user_answer == "same");
    if (a->curve.json_out) {
      json j{{"answer", same_answer_name(r.answer)},
             {"mirror_images", r.mirror_images},
             {"reason", r.reason},
             {"a", info_json(r.a)},
             {"b", info_json(r.b)}};
      if (judged) j["judgement"] = {{"decided", judged->decided}, {"right", judged->right}, {"text", judged->text}};
      std::cout << j.dump(2) << "\n";
    } else if (judged) {
      std::cout << judged->text << "\n";
    } else {
      std::cout << same_answer_name(r.answer) << ": " << r.reason << "\n";
    }
  });
}

namespace {

void print_unknotting(const UnknottingReport& r, bool as_json) {
  if (as_json) {
    json cs = json::array();
    for (const auto& x : r.crossings)
      cs.push_back({{"label", x.label},
                    {"x", x.point.x()},
                    {"y", x.point.y()},
                    {"unknots", x.unknots},
                    {"result", x.result}});
    std::cout << json{{"knot", r.knot}, {"is_unknot", r.is_unknot}, {"crossings", cs}, {"unknotting", r.unknotting}}
                     .dump(2)
              << "\n";
    return;
  }
  std::cout << "knot: " << r.knot << "\n";
  for (const auto& x : r.crossings)
    std::cout << "crossing " << x.label << ": "
              << (x.unknots ? "unknots it" : "does not unknot it (gives " + x.result + ")") << "\n";
  std::cout << r.unknotting.size() << " of " << r.crossings.size() << " crossing changes unknot it\n";
}

}  // namespace

void add_knot_unknotting(CLI::App& knot) {
  struct Args {
    KnotCurveArgs curve;
    int try_crossing = 0;
  };
  auto a = std::make_shared<Args>();
  auto* unknotting = knot.add_subcommand(
      "unknotting", "for each crossing of the diagram in a view, whether changing it unknots the knot");
  add_curve_args(unknotting, a->curve);
  unknotting->add_option("--try", a->try_crossing,
                         "the exercise: only the verdict on changing this crossing (labels as in `knot code`)")
      ->check(CLI::PositiveNumber);
  unknotting->callback([a] {
    const Curve<3> c = load_knot_curve(a->curve.file);
    const UnknottingReport r =
        unknotting_crossings(c, a->curve.view.empty() ? std::nullopt : std::optional(parse_view(a->curve.view)));
    if (a->try_crossing > 0) {
      const std::string verdict = unknotting_verdict(r, a->try_crossing);
      if (verdict.empty())
        throw Error("the diagram has no crossing " + std::to_string(a->try_crossing) + " (it has " +
                    std::to_string(r.crossings.size()) + ")");
      std::cout << verdict << "\n";
      return;
    }
    print_unknotting(r, a->curve.json_out);
  });
}

namespace {

struct ExerciseArgs {
  std::string kind, out, out_b;
  unsigned seed = 1;
  bool reveal = false;
};

void make_exercise(const ExerciseArgs& a) {
  if (a.kind == "same") {
    if (a.out_b.empty()) throw Error("knot exercise same needs --out-b for knot B");
    const SameKnotExercise e = make_same_knot_exercise(a.seed);
    write_shape_file(e.a, a.out);
    write_shape_file(e.b, a.out_b);
    std::cout << "knot A -> " << a.out << ", knot B -> " << a.out_b
              << " (beside it, turned). Are they the same knot? Answer with: shadow4d knot compare " << a.out << " "
              << a.out_b << " --answer same|different\n";
    if (a.reveal) std::cout << "knot A is " << e.names.a << ", knot B is " << e.names.b << "\n";
    return;
  }
  const std::string name = pick_unknotting_exercise(a.seed);
  const Curve<3> c = make_table_knot(name);
  write_shape_file(c, a.out);
  const KnotDiagram d = diagram_from_curve(c, Frame<3>());
  std::cout << "a knot of unknotting number one -> " << a.out << " (" << d.crossing_count()
            << " crossings in its own view; Gauss code " << d.gauss_code()
            << "). Which crossing's change unknots it? Answer with: shadow4d knot unknotting " << a.out
            << " --try N\n";
  if (a.reveal) std::cout << "it is " << name << "\n";
}

}  // namespace

void add_knot_exercise(CLI::App& knot) {
  auto a = std::make_shared<ExerciseArgs>();
  auto* exercise = knot.add_subcommand(
      "exercise", "make an exercise: same (a pair for `knot compare --answer`) or unknot (a knot of "
                  "unknotting number one for `knot unknotting --try N`)");
  exercise->add_option("kind", a->kind, "same or unknot")->required()->check(CLI::IsMember({"same", "unknot"}));
  exercise->add_option("--seed", a->seed, "which exercise (the same seed, the same exercise)")->capture_default_str();
  exercise->add_option("--out", a->out, "where to write the knot (same: knot A)")->required();
  exercise->add_option("--out-b", a->out_b, "same: where to write knot B");
  exercise->add_flag("--reveal", a->reveal, "say which table knots they are");
  exercise->callback([a] { make_exercise(*a); });
}

}  // namespace s4d::cli
