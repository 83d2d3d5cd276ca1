// The `shadow4d knot` sub-commands, one function each adding itself to `knot` (cmd_knot_*.cpp),
// and what they share: the curve they read and the way they print a name.
#pragma once
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "knots/knot_diagram.hpp"
#include "knots/knot_identify.hpp"
#include "knots/knot_info.hpp"
#include "knots/knot_naming.hpp"

namespace s4d::cli {

// The arguments most sub-commands take: a curve (file, generator call or scene), a view of it.
struct KnotCurveArgs {
  std::string file, view;
  bool json_out = false;
};
void add_curve_args(CLI::App* sub, KnotCurveArgs& args, bool with_view = true);
// --fast: the naming skips its slow refinements (and says so).
void add_fast_flag(CLI::App* sub, bool& fast);
// --engine regina|own: who computes the invariants (the default: Regina where the build has it).
void add_engine_option(CLI::App* sub, std::string& engine);
KnotEngine engine_of(const std::string& option);

nlohmann::json identification_json(const KnotIdentification& id);
// `headline`: the name line ("" for id.headline()).
void print_identification(const KnotIdentification& id, const std::string& indent = "",
                          const std::string& headline = "");
// The one naming (knot_naming.hpp): the identification, what decided it, what was tried or skipped.
nlohmann::json naming_json(const KnotNaming& n);
void print_naming(const KnotNaming& n);
nlohmann::json info_json(const KnotInfo& k);
nlohmann::json codes_json(const KnotDiagram& d, KnotEngine engine = default_knot_engine());

// cmd_knot_name.cpp
void add_knot_identify(CLI::App& knot);
void add_knot_code(CLI::App& knot);
void add_knot_info(CLI::App& knot);
// cmd_knot_exercise.cpp
void add_knot_compare(CLI::App& knot);
void add_knot_unknotting(CLI::App& knot);
void add_knot_exercise(CLI::App& knot);
// cmd_knot_make.cpp
void add_knot_make(CLI::App& knot);
// cmd_knot_edit.cpp
void add_knot_relax(CLI::App& knot);
void add_knot_flip(CLI::App& knot);
void add_knot_resample(CLI::App& knot);
void add_knot_smooth_depth(CLI::App& knot);
void add_knot_mirror(CLI::App& knot);
void add_knot_reverse(CLI::App& knot);
void add_knot_delete_component(CLI::App& knot);
// cmd_knot_sketch.cpp
void add_knot_sketch(CLI::App& knot);

}  // namespace s4d::cli
