// The `shadow4d knot` sub-commands, one function each adding itself to `knot` (cmd_knot_*.cpp),
// and what they share: the curve they read and the way they print a name.
#pragma once
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "knots/knot_diagram.hpp"
#include "knots/knot_identify.hpp"
#include "knots/knot_info.hpp"

namespace s4d::cli {

// The arguments most sub-commands take: a curve (file, generator call or scene), a view of it.
struct KnotCurveArgs {
  std::string file, view;
  bool json_out = false;
};
void add_curve_args(CLI::App* sub, KnotCurveArgs& args, bool with_view = true);

nlohmann::json identification_json(const KnotIdentification& id);
void print_identification(const KnotIdentification& id, const std::string& indent = "");
nlohmann::json info_json(const KnotInfo& k);
nlohmann::json codes_json(const KnotDiagram& d);

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
// cmd_knot_sketch.cpp
void add_knot_sketch(CLI::App& knot);

}  // namespace s4d::cli
