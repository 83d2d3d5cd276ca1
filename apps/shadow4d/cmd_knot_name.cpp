// `knot identify`, `knot info` and `knot code`: a curve's name, the live panel's information about
// it, and its diagram's codes in a view.
#include <chrono>
#include <iostream>
#include <memory>

#include "knot_commands.hpp"
#include "knot_input.hpp"
#include "knots/diagram_codes.hpp"
#include "knots/knot_invariants.hpp"

namespace s4d::cli {

using nlohmann::json;

void add_knot_identify(CLI::App& knot) {
  struct Args {
    KnotCurveArgs curve;
    bool fast = false;
    std::string engine;
  };
  auto a = std::make_shared<Args>();
  auto* identify = knot.add_subcommand("identify", "name the knot or link of a curve, and say what decided it");
  add_curve_args(identify, a->curve);
  add_fast_flag(identify, a->fast);
  add_engine_option(identify, a->engine);
  identify->callback([a] {
    NamingOptions o;
    o.frame = parse_view(a->curve.view);
    o.fast = a->fast;
    o.engine = engine_of(a->engine);
    const auto t0 = std::chrono::steady_clock::now();
    const KnotNaming n = name_knot(load_knot_curve(a->curve.file), o);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (a->curve.json_out) {
      json j = naming_json(n);
      j["milliseconds"] = ms;
      std::cout << j.dump(2) << "\n";
    } else {
      print_naming(n);
    }
  });
}

void add_knot_code(CLI::App& knot) {
  struct Args {
    KnotCurveArgs curve;
    bool pd = false, dt = false;
    std::string engine;
  };
  auto a = std::make_shared<Args>();
  auto* code = knot.add_subcommand("code", "Gauss, PD and DT codes of a curve's diagram in a view");
  add_curve_args(code, a->curve);
  code->add_flag("--pd", a->pd, "only the PD code, as `knot make --pd` reads it: [[1,5,2,4],...]");
  code->add_flag("--dt", a->dt, "only the DT code (knots), as `knot make --dt` reads it: 4 6 2");
  add_engine_option(code, a->engine);
  code->callback([a] {
    Frame<3> used;
    const KnotDiagram d = diagram_from_curve(load_knot_curve(a->curve.file), parse_view(a->curve.view), {}, &used);
    if (a->pd || a->dt) {
      if (a->pd) std::cout << pd_list(d) << "\n";
      if (a->dt) std::cout << dt_code(d) << "\n";
      return;
    }
    const json j = codes_json(d, engine_of(a->engine));
    if (a->curve.json_out) {
      std::cout << j.dump(2) << "\n";
      return;
    }
    for (const auto& [k, v] : j.items())
      std::cout << k << ": " << (v.is_string() ? v.get<std::string>() : v.dump()) << "\n";
  });
}

namespace {

void print_info(const KnotInfo& k) {
  std::cout << "name: " << k.headline << "\n";
  if (!k.chirality.empty()) std::cout << "chirality: " << k.chirality << "\n";
  if (k.candidates.size() > 1) {
    std::cout << "candidates:";
    for (const auto& x : k.candidates) std::cout << " " << x << ";";
    std::cout << "\n";
  }
  for (const auto& x : k.decided_by) std::cout << "decided by: " << x << "\n";
  for (const auto& x : k.further_used) std::cout << "further invariant tried: " << x << "\n";
  for (const auto& x : k.skipped) std::cout << "skipped (--fast): " << x << "\n";
  for (const auto& x : k.unavailable) std::cout << "unavailable without Regina: " << x << "\n";
  std::cout << "crossings: " << k.view_crossings << " in this view, " << k.simplified_crossings
            << " after simplification\n"
            << "Gauss code: " << k.gauss_code << "\n"
            << "writhe: " << k.writhe << "\n";
  if (k.components > 1) std::cout << "linking numbers: " << json(k.linking).dump() << "\n";
  std::cout << "Alexander: " << k.alexander << "\nJones: " << k.jones << "\nHOMFLY-PT: " << k.homfly
            << "\ndeterminant: " << k.determinant << "\n(" << k.milliseconds << " ms)\n";
}

}  // namespace

void add_knot_info(CLI::App& knot) {
  struct Args {
    KnotCurveArgs curve;
    bool fast = false;
    std::string engine;
  };
  auto a = std::make_shared<Args>();
  auto* info = knot.add_subcommand("info", "the live information panel of a curve in a view");
  add_curve_args(info, a->curve);
  add_fast_flag(info, a->fast);
  add_engine_option(info, a->engine);
  info->callback([a] {
    KnotInfoOptions o;
    o.fast = a->fast;
    o.engine = engine_of(a->engine);
    const Curve<3> c = load_knot_curve(a->curve.file);
    const KnotInfo k =
        knot_info(c, a->curve.view.empty() ? std::nullopt : std::optional(parse_view(a->curve.view)), o);
    if (a->curve.json_out) {
      std::cout << info_json(k).dump(2) << "\n";
      return;
    }
    print_info(k);
  });
}

}  // namespace s4d::cli
