// `shadow4d knot identify|info|code|compare|unknotting|make|relax|flip|resample|sketch|smooth-depth`:
// the knot engine from the command line, with --json for scripts. Curves come from any curve file,
// generator call or scene.
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <sstream>

#include "command.hpp"
#include "knot_input.hpp"
#include "core/error.hpp"
#include "core/plane.hpp"
#include "io/object_file.hpp"
#include "io/scene.hpp"
#include "knots/depth_edit.hpp"
#include "knots/dynadraw.hpp"
#include "knots/knot_curve.hpp"
#include "knots/knot_exercises.hpp"
#include "knots/knot_identify.hpp"
#include "knots/knot_info.hpp"
#include "knots/knot_table.hpp"
#include "knots/relax.hpp"
#include "knots/resample.hpp"
#include "knots/sketch.hpp"
#include "haptics/device_spec.hpp"
#include "haptics/replay_device.hpp"
#include "haptics/simulated_arm.hpp"
#include "interact/touch_sketch_run.hpp"

namespace s4d::cli {
namespace {

using nlohmann::json;

// [SECTION] input


// [SECTION] output

json factor_json(const KnotFactor& f) {
  return {{"name", f.entry->display_name()},
          {"rolfsen", f.entry->rolfsen_name},
          {"dt", f.entry->dt_name},
          {"regina", f.entry->regina_name},
          {"crossings", f.entry->crossings},
          {"chirality", chirality_name(f.chirality)}};
}

json invariants_json(const KnotInvariants& v) {
  return {{"components", v.components},
          {"diagram_crossings", v.diagram_crossings},
          {"simplified_crossings", v.simplified_crossings},
          {"writhe", v.writhe},
          {"linking_numbers", v.linking},
          {"homfly_pt", v.homfly_text()},
          {"jones", v.jones_text()},
          {"alexander", v.alexander_text()},
          {"determinant", v.determinant}};
}

json identification_json(const KnotIdentification& id) {
  json j = {{"kind", kind_name(id.kind)},
            {"name", id.name},
            {"proven", id.proven},
            {"invariants", invariants_json(id.invariants)}};
  json cands = json::array();
  for (const auto& f : id.candidates) {
    json factors = json::array();
    for (const auto& k : f) factors.push_back(factor_json(k));
    cands.push_back({{"text", factorisation_text(f)}, {"factors", factors}});
  }
  j["candidates"] = cands;
  if (id.kind == KnotKind::kLink) {
    j["link_name"] = id.link_name;
    json links = json::array();
    for (const auto& l : id.link_candidates)
      links.push_back({{"text", l.text()},
                       {"table_name", l.entry ? l.entry->name : ""},
                       {"chirality", l.entry ? chirality_name(l.chirality) : ""}});
    j["link_candidates"] = links;
    json comps = json::array();
    for (const auto& c : id.components) comps.push_back(identification_json(c));
    j["components"] = comps;
  }
  return j;
}

void print_identification(const KnotIdentification& id, const std::string& indent = "") {
  std::cout << indent << (id.kind == KnotKind::kLink ? "link: " : "knot: ") << id.headline() << "\n";
  const auto& v = id.invariants;
  if (id.link_candidates.size() > 1) {
    std::cout << indent << "candidates (the invariants cannot decide):\n";
    for (const auto& l : id.link_candidates) std::cout << indent << "  " << l.text() << "\n";
  }
  if (id.candidates.size() > 1) {
    std::cout << indent << "candidates (the invariants cannot decide):\n";
    for (const auto& f : id.candidates) std::cout << indent << "  " << factorisation_text(f) << "\n";
  }
  for (const auto& f : id.candidates)
    for (const auto& k : f)
      if (k.chirality == Chirality::kUnknown) {
        std::cout << indent << "chirality of " << k.entry->display_name()
                  << ": unknown (HOMFLY-PT is symmetric)\n";
        break;
      }
  std::cout << indent << "crossings: " << v.diagram_crossings << " in this view, "
            << v.simplified_crossings << " after simplification\n"
            << indent << "HOMFLY-PT: " << v.homfly_text() << "\n"
            << indent << "Jones: " << v.jones_text() << "\n"
            << indent << "Alexander: " << v.alexander_text() << "\n"
            << indent << "determinant: " << v.determinant << "\n";
  if (id.kind == KnotKind::kLink)
    for (std::size_t i = 0; i < id.components.size(); ++i)
      std::cout << indent << "component " << i << ": " << id.components[i].name << "\n";
}

json info_json(const KnotInfo& k) {
  return {{"name", k.name},
          {"proven", k.proven},
          {"chirality", k.chirality},
          {"candidates", k.candidates},
          {"decided_by", k.decided_by},
          {"further_used", k.further_used},
          {"view_crossings", k.view_crossings},
          {"simplified_crossings", k.simplified_crossings},
          {"gauss", k.gauss_code},
          {"signed_gauss", k.signed_gauss_code},
          {"writhe", k.writhe},
          {"components", k.components},
          {"linking_numbers", k.linking},
          {"alexander", k.alexander},
          {"jones", k.jones},
          {"homfly_pt", k.homfly},
          {"determinant", k.determinant},
          {"milliseconds", k.milliseconds}};
}

json codes_json(const KnotDiagram& d) {
  const ReginaCodes r = regina_codes(d);
  return {{"crossings", d.crossing_count()},
          {"components", d.component_count()},
          {"writhe", d.writhe()},
          {"linking_numbers", d.linking_numbers()},
          {"gauss", d.gauss_code()},
          {"extended_gauss", d.extended_gauss_code()},
          {"signed_gauss", d.signed_gauss_code()},
          {"regina_gauss", r.gauss},
          {"oriented_gauss", r.oriented_gauss},
          {"pd", d.pd_code()},
          {"dt", r.dt},
          {"dt_alpha", r.dt_alpha}};
}

// [SECTION] sketch by touch

// `knot sketch --device replay:T | sim [FILE]`: the touch sketch through the loop, headless.
void sketch_by_touch(const std::string& device_spec, const std::string& stroke, const std::string& out,
                     const std::string& record, double dt, bool as_json) {
  const DeviceSpec spec = parse_device_spec(device_spec);
  TouchSketchOptions o;
  o.record = record;
  std::unique_ptr<Device> device;
  std::vector<HandSample> hand;
  if (spec.kind == DeviceSpec::Kind::replay) {
    if (!stroke.empty()) throw Error("knot sketch --device replay:FILE takes no stroke file (the trajectory is the hand)");
    Trajectory t = read_trajectory(spec.file);
    o.plane_z = sketch_plane_of_setup(t.header.setup, t.header.caps.workspace_centre().z());
    const bool compare = t.header.scene == "curve-sketch";
    device = std::make_unique<ReplayDevice>(std::move(t), compare);
  } else if (spec.kind == DeviceSpec::Kind::sim) {
    if (stroke.empty()) throw Error("knot sketch --device sim needs a stroke FILE for the hand to follow");
    auto arm = std::make_unique<SimulatedArm>();
    const DeviceCapabilities& caps = arm->capabilities();
    const Vec3 half = 0.5 * (caps.workspace_max - caps.workspace_min);
    o.plane_z = caps.workspace_centre().z();
    const Curve<3> raw = load_knot_curve(stroke);
    hand = hand_from_stroke(raw.components[0].points, dt, 1000, caps.workspace_centre(),
                            0.8 * Vec2(half.x(), half.y()));
    device = std::move(arm);
  } else {
    throw Error("knot sketch --device takes replay:FILE or sim (the window sketches with the mouse and the others)");
  }
  const TouchSketchResult r = run_touch_sketch(std::move(device), hand, o);
  Curve<3> curve = r.link.curve;
  constexpr double kUnit = 0.05;  // m of the device per unit written
  for (Polyline<3>& p : curve.components)
    for (Vec3& q : p.points) q /= kUnit;
  if (!out.empty()) write_shape_file(curve, out);
  const KnotIdentification id = identify_knot(curve);
  if (as_json) {
    std::cout << json{{"components", curve.components.size()}, {"points", curve.point_count()},
                      {"crossings", r.link.crossings}, {"gauss", r.gauss}, {"name", id.name},
                      {"proven", id.proven}, {"ticks", r.ticks},
                      {"crossings_refused", r.strokes.status.crossings_refused},
                      {"blocked_ticks", r.strokes.status.blocked_ticks},
                      {"max_repulsion", r.strokes.status.max_repulsion}, {"max_force", r.max_force},
                      {"replay_mismatches", r.replay_mismatches}, {"disconnected_ticks", r.disconnected_ticks}}
                     .dump(2)
              << "\n";
    return;
  }
  std::cout << "sketched by touch (" << device_spec << ", " << r.ticks << " ticks): " << curve.components.size()
            << " component(s), " << r.link.crossings << " crossing(s)\n"
            << "Gauss code: " << (r.gauss.empty() ? "(no crossings)" : r.gauss) << "\n"
            << "name: " << id.headline() << "\n"
            << "strands refused without a choice: " << r.strokes.status.crossings_refused
            << ", largest repulsion " << r.strokes.status.max_repulsion << " N, largest force sent " << r.max_force
            << " N\n";
  if (r.disconnected_ticks) std::cout << "device gone for " << r.disconnected_ticks << " ticks (nothing lost)\n";
  if (!out.empty()) std::cout << "wrote " << out << "\n";
  if (!record.empty()) std::cout << "recorded " << record << " (replay: shadow4d knot sketch --device replay:" << record << ")\n";
}

// [SECTION] sub-commands

struct Common {
  std::string file, view;
  bool json_out = false;
};

void add_common(CLI::App* s, Common& c, bool with_view = true) {
  s->add_option("file", c.file, "curve file (.curve/.txt/.xyz/.vect), generator call, or scene (.json: its curves)")
      ->required();
  if (with_view) s->add_option("--rotate", c.view, "view rotation, e.g. xz=30,yz=10 (degrees)");
  s->add_flag("--json", c.json_out, "machine-readable output");
}

void setup(CLI::App& knot) {
  knot.require_subcommand(1);

  static Common idc;
  static bool prove = false;
  auto* identify = knot.add_subcommand("identify", "name the knot or link of a curve");
  add_common(identify, idc);
  identify->add_flag("--prove-unknot", prove, "when only invariants say unknot, prove it (slow)");
  identify->callback([] {
    IdentifyOptions o;
    o.frame = parse_view(idc.view);
    o.prove_unknot = prove;
    const auto t0 = std::chrono::steady_clock::now();
    const auto id = identify_knot(load_knot_curve(idc.file), o);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (idc.json_out) {
      json j = identification_json(id);
      j["milliseconds"] = ms;
      std::cout << j.dump(2) << "\n";
    } else {
      print_identification(id);
    }
  });

  static Common cc;
  auto* code = knot.add_subcommand("code", "Gauss, PD and DT codes of a curve's diagram in a view");
  add_common(code, cc);
  code->callback([] {
    Frame<3> used;
    const KnotDiagram d = diagram_from_curve(load_knot_curve(cc.file), parse_view(cc.view), {}, &used);
    const json j = codes_json(d);
    if (cc.json_out) {
      std::cout << j.dump(2) << "\n";
      return;
    }
    for (const auto& [k, v] : j.items())
      std::cout << k << ": " << (v.is_string() ? v.get<std::string>() : v.dump()) << "\n";
  });

  static Common ca;
  static std::string file_b, user_answer;
  auto* compare = knot.add_subcommand("compare", "are two curves the same knot? (the user-study exercise)");
  add_common(compare, ca, false);
  compare->add_option("other", file_b, "the second curve")->required();
  compare->add_option("--answer", user_answer, "your answer, judged by the invariants: same or different")
      ->check(CLI::IsMember({"same", "different"}));
  compare->callback([] {
    const auto r = same_knot(load_knot_curve(ca.file), load_knot_curve(file_b));
    std::optional<SameKnotJudgement> judged;
    if (!user_answer.empty()) judged = judge_same_answer(r, user_answer == "same");
    if (ca.json_out) {
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

  static Common ic;
  static bool no_refine = false;
  auto* info = knot.add_subcommand("info", "the live information panel of a curve in a view");
  add_common(info, ic);
  info->add_flag("--no-refine", no_refine, "skip the further invariants (covers, Reidemeister search)");
  info->callback([] {
    KnotInfoOptions o;
    o.refine = !no_refine;
    const Curve<3> c = load_knot_curve(ic.file);
    const KnotInfo k = knot_info(c, ic.view.empty() ? std::nullopt : std::optional(parse_view(ic.view)), o);
    if (ic.json_out) {
      std::cout << info_json(k).dump(2) << "\n";
      return;
    }
    std::cout << "name: " << k.name << (k.proven ? "" : "  [not proven]") << "\n";
    if (!k.chirality.empty()) std::cout << "chirality: " << k.chirality << "\n";
    if (k.candidates.size() > 1) {
      std::cout << "candidates:";
      for (const auto& x : k.candidates) std::cout << " " << x << ";";
      std::cout << "\n";
    }
    for (const auto& x : k.decided_by) std::cout << "decided by: " << x << "\n";
    for (const auto& x : k.further_used) std::cout << "further invariant tried: " << x << "\n";
    std::cout << "crossings: " << k.view_crossings << " in this view, " << k.simplified_crossings
              << " after simplification\n"
              << "Gauss code: " << k.gauss_code << "\n"
              << "writhe: " << k.writhe << "\n";
    if (k.components > 1) std::cout << "linking numbers: " << json(k.linking).dump() << "\n";
    std::cout << "Alexander: " << k.alexander << "\nJones: " << k.jones << "\nHOMFLY-PT: " << k.homfly
              << "\ndeterminant: " << k.determinant << "\n(" << k.milliseconds << " ms)\n";
  });

  static Common uc;
  static int try_crossing = 0;
  auto* unknotting = knot.add_subcommand(
      "unknotting", "for each crossing of the diagram in a view, whether changing it unknots the knot");
  add_common(unknotting, uc);
  unknotting->add_option("--try", try_crossing,
                         "the exercise: only the verdict on changing this crossing (labels as in `knot code`)")
      ->check(CLI::PositiveNumber);
  unknotting->callback([] {
    const Curve<3> c = load_knot_curve(uc.file);
    const UnknottingReport r =
        unknotting_crossings(c, uc.view.empty() ? std::nullopt : std::optional(parse_view(uc.view)));
    if (try_crossing > 0) {
      const std::string verdict = unknotting_verdict(r, try_crossing);
      if (verdict.empty())
        throw Error("the diagram has no crossing " + std::to_string(try_crossing) + " (it has " +
                    std::to_string(r.crossings.size()) + ")");
      std::cout << verdict << "\n";
      return;
    }
    if (uc.json_out) {
      json cs = json::array();
      for (const auto& x : r.crossings)
        cs.push_back({{"label", x.label},
                      {"x", x.point.x()},
                      {"y", x.point.y()},
                      {"unknots", x.unknots},
                      {"result", x.result}});
      std::cout << json{{"knot", r.knot},
                        {"is_unknot", r.is_unknot},
                        {"crossings", cs},
                        {"unknotting", r.unknotting}}
                       .dump(2)
                << "\n";
      return;
    }
    std::cout << "knot: " << r.knot << "\n";
    for (const auto& x : r.crossings)
      std::cout << "crossing " << x.label << ": "
                << (x.unknots ? "unknots it" : "does not unknot it (gives " + x.result + ")") << "\n";
    std::cout << r.unknotting.size() << " of " << r.crossings.size() << " crossing changes unknot it\n";
  });

  // The user-study exercises, headless: the GUI's "New pair" and "New knot".
  static std::string exercise_kind, exercise_out, exercise_out_b;
  static unsigned exercise_seed = 1;
  static bool exercise_reveal = false;
  auto* exercise = knot.add_subcommand(
      "exercise", "make an exercise: same (a pair for `knot compare --answer`) or unknot (a knot of "
                  "unknotting number one for `knot unknotting --try N`)");
  exercise->add_option("kind", exercise_kind, "same or unknot")
      ->required()
      ->check(CLI::IsMember({"same", "unknot"}));
  exercise->add_option("--seed", exercise_seed, "which exercise (the same seed, the same exercise)")->capture_default_str();
  exercise->add_option("--out", exercise_out, "where to write the knot (same: knot A)")->required();
  exercise->add_option("--out-b", exercise_out_b, "same: where to write knot B");
  exercise->add_flag("--reveal", exercise_reveal, "say which table knots they are");
  exercise->callback([] {
    if (exercise_kind == "same") {
      if (exercise_out_b.empty()) throw Error("knot exercise same needs --out-b for knot B");
      const SameKnotExercise e = make_same_knot_exercise(exercise_seed);
      write_shape_file(e.a, exercise_out);
      write_shape_file(e.b, exercise_out_b);
      std::cout << "knot A -> " << exercise_out << ", knot B -> " << exercise_out_b
                << " (beside it, turned). Are they the same knot? Answer with: shadow4d knot compare "
                << exercise_out << " " << exercise_out_b << " --answer same|different\n";
      if (exercise_reveal) std::cout << "knot A is " << e.names.a << ", knot B is " << e.names.b << "\n";
      return;
    }
    const std::string name = pick_unknotting_exercise(exercise_seed);
    const Curve<3> c = make_table_knot(name);
    write_shape_file(c, exercise_out);
    const KnotDiagram d = diagram_from_curve(c, Frame<3>());
    std::cout << "a knot of unknotting number one -> " << exercise_out << " (" << d.crossing_count()
              << " crossings in its own view; Gauss code " << d.gauss_code()
              << "). Which crossing's change unknots it? Answer with: shadow4d knot unknotting " << exercise_out
              << " --try N\n";
    if (exercise_reveal) std::cout << "it is " << name << "\n";
  });

  static std::string make_name, make_out;
  static bool make_list = false, make_json = false;
  static DiagramEmbedding embed;
  auto* make = knot.add_subcommand(
      "make", "a 3D curve of a knot or link from the table (3_1, 11n_34, T(2,5), L6a4, Hopf link, m3_1, ...)");
  make->add_option("name", make_name, "knot name; 'NAME mirror', 'mNAME' or 'NAME*' for the mirror image");
  make->add_option("--out", make_out, "where to write the curve");
  make->add_option("--relax", embed.relax_iterations, "relaxation steps")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000000));
  make->add_flag("--list", make_list, "list the table's names (with crossings and source) instead");
  make->add_flag("--json", make_json, "machine-readable output");
  make->callback([] {
    if (make_list) {
      for (const auto& t : knot_table_names())
        std::cout << t.name << "\t" << t.crossings << "\t" << t.source << (t.alias.empty() ? "" : "\t" + t.alias)
                  << "\n";
      return;
    }
    if (make_name.empty() || make_out.empty())
      throw Error("knot make needs a NAME and --out FILE (or --list)");
    const auto t0 = std::chrono::steady_clock::now();
    const Curve<3> c = make_table_knot(make_name, embed);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    write_shape_file(c, make_out);
    const KnotIdentification id = identify_knot(c);
    if (make_json)
      std::cout << json{{"name", table_knot(make_name).name},
                        {"points", c.point_count()},
                        {"milliseconds", ms},
                        {"identified", id.name},
                        {"proven", id.proven}}
                       .dump(2)
                << "\n";
    else
      std::cout << "made " << table_knot(make_name).name << ": " << c.point_count() << " points in " << ms
                << " ms, identified as " << id.headline() << "; wrote " << make_out << "\n";
  });

  static Common rc;
  static std::string relax_out;
  static int iterations = 2000;
  auto* relaxc = knot.add_subcommand("relax", "knot-energy relaxation that never passes through itself");
  add_common(relaxc, rc, false);
  relaxc->add_option("--out", relax_out, "where to write the relaxed curve")->required();
  relaxc->add_option("--iterations", iterations, "relaxation steps")->check(CLI::Range(1, 10000000));
  relaxc->callback([] {
    const Curve<3> c = load_knot_curve(rc.file);
    RelaxModel m;
    RelaxData d;
    relax_setup(c, m, d);
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < iterations; ++i) relax_step(m, d);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const Curve<3> out = relax_curve(m, d);
    write_shape_file(out, relax_out);
    const auto before = identify_knot(c), after = identify_knot(out);
    if (rc.json_out) {
      std::cout << json{{"iterations", iterations}, {"seconds", s}, {"limited_steps", d.limited_steps},
                        {"before", before.name}, {"after", after.name},
                        {"crossings_before", before.invariants.diagram_crossings},
                        {"crossings_after", after.invariants.diagram_crossings}}
                       .dump(2)
                << "\n";
    } else {
      std::cout << "relaxed " << iterations << " steps in " << s << " s (" << iterations / s
                << " it/s); knot " << before.name << " -> " << after.name << "; fewest crossings "
                << before.invariants.diagram_crossings << " -> " << after.invariants.diagram_crossings
                << "\nwrote " << relax_out << "\n";
    }
  });

  static Common fc;
  static int crossing = 0;
  static std::string flip_out;
  auto* flip = knot.add_subcommand("flip", "change one crossing (over <-> under) and name the result");
  add_common(flip, fc);
  flip->add_option("--crossing", crossing, "crossing label as in `knot code` (1-based)")->required();
  flip->add_option("--out", flip_out, "where to write the changed curve");
  flip->callback([] {
    const Curve<3> c = load_knot_curve(fc.file);
    const Frame<3> view = parse_view(fc.view);
    const Curve<3> changed = flip_crossing(c, view, crossing);
    if (!flip_out.empty()) write_shape_file(changed, flip_out);
    IdentifyOptions o;
    o.frame = view;
    const auto before = identify_knot(c, o), after = identify_knot(changed, o);
    if (fc.json_out) {
      std::cout << json{{"crossing", crossing}, {"before", identification_json(before)},
                        {"after", identification_json(after)}}
                       .dump(2)
                << "\n";
    } else {
      std::cout << "crossing " << crossing << " changed: " << before.name << " -> " << after.name << "\n";
      if (!flip_out.empty()) std::cout << "wrote " << flip_out << "\n";
    }
  });

  static Common sc;
  static std::string resample_out;
  static int points = 0;
  auto* resample = knot.add_subcommand("resample", "nearly equal segments, never passing through itself");
  add_common(resample, sc, false);
  resample->add_option("--points", points, "total number of points")
      ->required()
      ->check(CLI::Range(3, 10000000));
  resample->add_option("--out", resample_out, "where to write the curve")->required();
  resample->callback([] {
    ResampleStats st;
    const Curve<3> out = resample_curve_to_count(load_knot_curve(sc.file), points, &st);
    write_shape_file(out, resample_out);
    if (sc.json_out)
      std::cout << json{{"points", out.point_count()}, {"moves", st.moves}, {"refused", st.refused}}.dump(2)
                << "\n";
    else
      std::cout << "resampled to " << out.point_count() << " points (" << st.refused
                << " chords refused to avoid a pass-through); wrote " << resample_out << "\n";
  });

  // A sketched stroke (cursor samples, one per line, as the GUI's sketch tool or a tablet records
  // them) smoothed the way the sketching tool does it, or with --knot made into its knot, so a
  // sketch can be reproduced and inspected headless.
  static std::string sketch_in, sketch_out;
  static double sketch_dt = 1.0 / 120.0;
  static DynadrawParams pen;
  static bool sketch_json = false;
  auto* sketch = knot.add_subcommand("sketch", "smooth a raw sketched stroke with Dynadraw (Haeberli)");
  sketch->add_option("file", sketch_in, "stroke: a curve file of cursor samples (with --device sim: the hand's path)");
  sketch->add_option("--out", sketch_out, "where to write the smoothed curve (the knot, with --knot or --device)");
  static std::string sketch_device, sketch_record;
  sketch->add_option("--device", sketch_device,
                     "sketch by touch through the haptic loop: replay:TRAJECTORY (a recorded device), or sim "
                     "(the simulated arm's hand follows FILE: x y u, u = 0 draw, 1 cross under, 2 cross over, "
                     "-1 pen up); the knot is written in units of 5 cm of the device");
  sketch->add_option("--record", sketch_record, "with --device: record the device trajectory (for replay:FILE)");
  sketch->add_option("--dt", sketch_dt, "seconds between samples")
      ->capture_default_str()
      ->check(CLI::Range(1e-5, 1.0));
  sketch->add_option("--mass", pen.mass, "pen mass, kg")->capture_default_str()->check(CLI::Range(1e-6, 1e6));
  sketch->add_option("--stiffness", pen.stiffness, "spring to the cursor, N/m")
      ->capture_default_str()
      ->check(CLI::Range(1e-6, 1e9));
  sketch->add_option("--damping", pen.damping, "drag, N s/m")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e9));
  sketch->add_flag("--json", sketch_json, "machine-readable output");
  static bool sketch_knot = false;
  sketch->add_flag("--knot", sketch_knot,
                   "make the closed knot the GUI's sketch tool makes: samples are x y u, u = 1 where "
                   "the stroke passes under (the modifier held), 0 where it passes over");
  sketch->callback([] {
    if (!sketch_device.empty()) {
      sketch_by_touch(sketch_device, sketch_in, sketch_out, sketch_record, sketch_dt, sketch_json);
      return;
    }
    if (sketch_in.empty() || sketch_out.empty()) throw Error("knot sketch needs a stroke FILE and --out (or --device)");
    const Curve<3> raw = load_knot_curve(sketch_in);
    if (sketch_knot) {
      SketchOptions o;
      o.pen = pen;
      const SketchedKnot k = knot_from_sketch(stroke_from_curve(raw, sketch_dt), o);
      write_shape_file(k.curve, sketch_out);
      const KnotIdentification id = identify_knot(k.curve);
      if (sketch_json)
        std::cout << json{{"points", k.curve.point_count()}, {"crossings", k.crossings},
                          {"gauss", diagram_from_curve(k.curve, Frame<3>()).gauss_code()},
                          {"name", id.name}, {"proven", id.proven}}.dump(2) << "\n";
      else
        std::cout << "sketched a knot of " << k.curve.point_count() << " points, " << k.crossings
                  << " crossing(s): " << id.headline() << "; wrote " << sketch_out << "\n";
      return;
    }
    Curve<3> smooth;
    for (const auto& comp : raw.components) {
      Polyline<3> p;
      p.closed = comp.closed;
      p.points = dynadraw_stroke<3>(comp.points, sketch_dt, pen, /*settle_steps=*/0);
      smooth.components.push_back(std::move(p));
    }
    write_shape_file(smooth, sketch_out);
    if (sketch_json)
      std::cout << json{{"points", smooth.point_count()}, {"length_before", raw.length()},
                        {"length_after", smooth.length()}}.dump(2) << "\n";
    else
      std::cout << "smoothed " << smooth.point_count() << " samples: length " << raw.length() << " -> "
                << smooth.length() << "; wrote " << sketch_out << "\n";
  });

  // Depth smoothing after over/under choices (paper 4.2): the shadow and every choice stay.
  static Common dc;
  static std::string depth_out;
  static DepthSmoothing ds;
  auto* depth = knot.add_subcommand("smooth-depth", "smooth the depth of a curve, keeping its diagram");
  add_common(depth, dc);
  depth->add_option("--out", depth_out, "where to write the curve")->required();
  depth->add_option("--iterations", ds.iterations, "smoothing passes")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  depth->add_option("--clearance", ds.clearance, "depth gap kept at crossings, x curve size")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  depth->callback([] {
    const Curve<3> c = load_knot_curve(dc.file);
    const Frame<3> view = parse_view(dc.view);
    const Curve<3> out = smooth_depth(c, view, ds);
    write_shape_file(out, depth_out);
    IdentifyOptions o;
    o.frame = view;
    const auto before = identify_knot(c, o), after = identify_knot(out, o);
    if (dc.json_out)
      std::cout << json{{"before", identification_json(before)}, {"after", identification_json(after)}}
                       .dump(2)
                << "\n";
    else
      std::cout << "depth smoothed: " << before.name << " -> " << after.name << "; wrote " << depth_out
                << "\n";
  });
}

const CommandRegistrar kKnot(
    "knot",
    "knot engine: identify, info, code, compare, unknotting, exercise, make, relax, flip, resample, sketch, "
    "smooth-depth",
    setup);

}  // namespace
}  // namespace s4d::cli
