// The sub-commands that change a curve and name what it became: `knot relax`, `knot flip` (one
// crossing), `knot resample`, `knot smooth-depth`, and the diagram toolbar's `knot mirror`,
// `knot reverse` and `knot delete-component`.
#include <chrono>
#include <functional>
#include <iostream>
#include <memory>

#include "io/object_file.hpp"
#include "knot_commands.hpp"
#include "knot_input.hpp"
#include "knots/curve_edits.hpp"
#include "knots/depth_edit.hpp"
#include "knots/relax.hpp"
#include "knots/resample.hpp"

namespace s4d::cli {

using nlohmann::json;

namespace {

struct RelaxArgs {
  KnotCurveArgs curve;
  std::string out;
  int iterations = 2000;
};

void relax_knot(const RelaxArgs& a) {
  const Curve<3> c = load_knot_curve(a.curve.file);
  RelaxModel m;
  RelaxData d;
  relax_setup(c, m, d);
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < a.iterations; ++i) relax_step(m, d);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Curve<3> out = relax_curve(m, d);
  write_shape_file(out, a.out);
  const KnotNaming before = name_knot(c), after = name_knot(out);
  if (a.curve.json_out) {
    std::cout << json{{"iterations", a.iterations}, {"seconds", s}, {"limited_steps", d.limited_steps},
                      {"before", before.name()}, {"after", after.name()},
                      {"crossings_before", before.identification.invariants.diagram_crossings},
                      {"crossings_after", after.identification.invariants.diagram_crossings}}
                     .dump(2)
              << "\n";
  } else {
    std::cout << "relaxed " << a.iterations << " steps in " << s << " s (" << a.iterations / s << " it/s); knot "
              << before.name() << " -> " << after.name() << "; fewest crossings " << before.identification.invariants.diagram_crossings
              << " -> " << after.identification.invariants.diagram_crossings << "\nwrote " << a.out << "\n";
  }
}

}  // namespace

void add_knot_relax(CLI::App& knot) {
  auto a = std::make_shared<RelaxArgs>();
  auto* relax = knot.add_subcommand("relax", "knot-energy relaxation that never passes through itself");
  add_curve_args(relax, a->curve, false);
  relax->add_option("--out", a->out, "where to write the relaxed curve")->required();
  relax->add_option("--iterations", a->iterations, "relaxation steps")->check(CLI::Range(1, 10000000));
  relax->callback([a] { relax_knot(*a); });
}

void add_knot_flip(CLI::App& knot) {
  struct Args {
    KnotCurveArgs curve;
    int crossing = 0;
    std::string out;
  };
  auto a = std::make_shared<Args>();
  auto* flip = knot.add_subcommand("flip", "change one crossing (over <-> under) and name the result");
  add_curve_args(flip, a->curve);
  flip->add_option("--crossing", a->crossing, "crossing label as in `knot code` (1-based)")->required();
  flip->add_option("--out", a->out, "where to write the changed curve");
  flip->callback([a] {
    const Curve<3> c = load_knot_curve(a->curve.file);
    const Frame<3> view = parse_view(a->curve.view);
    const Curve<3> changed = flip_crossing(c, view, a->crossing);
    if (!a->out.empty()) write_shape_file(changed, a->out);
    NamingOptions o;
    o.frame = view;
    const KnotNaming before = name_knot(c, o), after = name_knot(changed, o);
    if (a->curve.json_out) {
      std::cout << json{{"crossing", a->crossing}, {"before", naming_json(before)},
                        {"after", naming_json(after)}}
                       .dump(2)
                << "\n";
    } else {
      std::cout << "crossing " << a->crossing << " changed: " << before.name() << " -> " << after.name() << "\n";
      if (!a->out.empty()) std::cout << "wrote " << a->out << "\n";
    }
  });
}

void add_knot_resample(CLI::App& knot) {
  struct Args {
    KnotCurveArgs curve;
    std::string out;
    int points = 0;
  };
  auto a = std::make_shared<Args>();
  auto* resample = knot.add_subcommand("resample", "nearly equal segments, never passing through itself");
  add_curve_args(resample, a->curve, false);
  resample->add_option("--points", a->points, "total number of points")->required()->check(CLI::Range(3, 10000000));
  resample->add_option("--out", a->out, "where to write the curve")->required();
  resample->callback([a] {
    ResampleStats st;
    const Curve<3> out = resample_curve_to_count(load_knot_curve(a->curve.file), a->points, &st);
    write_shape_file(out, a->out);
    if (a->curve.json_out)
      std::cout << json{{"points", out.point_count()}, {"moves", st.moves}, {"refused", st.refused}}.dump(2) << "\n";
    else
      std::cout << "resampled to " << out.point_count() << " points (" << st.refused
                << " chords refused to avoid a pass-through); wrote " << a->out << "\n";
  });
}

// Depth smoothing after over/under choices (paper 4.2): the shadow and every choice stay.
void add_knot_smooth_depth(CLI::App& knot) {
  struct Args {
    KnotCurveArgs curve;
    std::string out;
    DepthSmoothing smoothing;
  };
  auto a = std::make_shared<Args>();
  auto* depth = knot.add_subcommand("smooth-depth", "smooth the depth of a curve, keeping its diagram");
  add_curve_args(depth, a->curve);
  depth->add_option("--out", a->out, "where to write the curve")->required();
  depth->add_option("--iterations", a->smoothing.iterations, "smoothing passes")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  depth->add_option("--clearance", a->smoothing.clearance, "depth gap kept at crossings, x curve size")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  depth->callback([a] {
    const Curve<3> c = load_knot_curve(a->curve.file);
    const Frame<3> view = parse_view(a->curve.view);
    const Curve<3> out = smooth_depth(c, view, a->smoothing);
    write_shape_file(out, a->out);
    NamingOptions o;
    o.frame = view;
    const KnotNaming before = name_knot(c, o), after = name_knot(out, o);
    if (a->curve.json_out)
      std::cout << json{{"before", naming_json(before)}, {"after", naming_json(after)}}.dump(2)
                << "\n";
    else
      std::cout << "depth smoothed: " << before.name() << " -> " << after.name() << "; wrote " << a->out << "\n";
  });
}

namespace {

// The toolbar's edits: the curve changed, written, and named before and after.
struct ToolbarArgs {
  KnotCurveArgs curve;
  std::string out;
  int component = 0;  // 1-based, as the Knot panel numbers them
};

void toolbar_edit(const ToolbarArgs& a, const char* what, const std::function<Curve<3>(const Curve<3>&)>& edit) {
  const Curve<3> c = load_knot_curve(a.curve.file);
  const Curve<3> changed = edit(c);
  write_shape_file(changed, a.out);
  const KnotNaming before = name_knot(c), after = name_knot(changed);
  if (a.curve.json_out) {
    std::cout << json{{"edit", what}, {"before", naming_json(before)}, {"after", naming_json(after)}}.dump(2) << "\n";
    return;
  }
  std::cout << what << ": " << before.headline() << " -> " << after.headline() << "; wrote " << a.out << "\n";
}

CLI::App* add_toolbar_command(CLI::App& knot, const char* name, const char* help, ToolbarArgs& a,
                              bool with_component) {
  auto* sub = knot.add_subcommand(name, help);
  add_curve_args(sub, a.curve, false);
  sub->add_option("--out", a.out, "where to write the changed curve")->required();
  if (with_component)
    sub->add_option("--component", a.component, "which component, from 1 (as `knot info` and the Knot panel count)")
        ->required()
        ->check(CLI::PositiveNumber);
  return sub;
}

}  // namespace

void add_knot_mirror(CLI::App& knot) {
  auto a = std::make_shared<ToolbarArgs>();
  add_toolbar_command(knot, "mirror", "the mirror image of a knot or link (every crossing changed)", *a, false)
      ->callback([a] { toolbar_edit(*a, "mirrored", mirrored_curve); });
}

void add_knot_reverse(CLI::App& knot) {
  auto a = std::make_shared<ToolbarArgs>();
  add_toolbar_command(knot, "reverse", "run one component of a knot or link the other way round", *a, true)
      ->callback([a] {
        toolbar_edit(*a, "reversed a component", [&](const Curve<3>& c) { return with_component_reversed(c, a->component - 1); });
      });
}

void add_knot_delete_component(CLI::App& knot) {
  auto a = std::make_shared<ToolbarArgs>();
  add_toolbar_command(knot, "delete-component", "leave one component of a link out", *a, true)->callback([a] {
    toolbar_edit(*a, "deleted a component", [&](const Curve<3>& c) { return with_component_deleted(c, a->component - 1); });
  });
}

}  // namespace s4d::cli
