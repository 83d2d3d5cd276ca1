// `shadow4d knot identify|info|code|compare|unknotting|exercise|make|relax|flip|resample|sketch|
// smooth-depth|mirror|reverse|delete-component`: the knot engine from the command line, with --json for scripts. Curves come from
// any curve file, generator call or scene. Each sub-command lives in a cmd_knot_*.cpp by what it
// does (knot_commands.hpp).
#include "command.hpp"
#include "knot_commands.hpp"

namespace s4d::cli {
namespace {

void setup(CLI::App& knot) {
  knot.require_subcommand(1);
  add_knot_identify(knot);
  add_knot_code(knot);
  add_knot_compare(knot);
  add_knot_info(knot);
  add_knot_unknotting(knot);
  add_knot_exercise(knot);
  add_knot_make(knot);
  add_knot_relax(knot);
  add_knot_flip(knot);
  add_knot_resample(knot);
  add_knot_sketch(knot);
  add_knot_smooth_depth(knot);
  add_knot_mirror(knot);
  add_knot_reverse(knot);
  add_knot_delete_component(knot);
}

const CommandRegistrar kKnot(
    "knot",
    "knot engine: identify, info, code, compare, unknotting, exercise, make, relax, flip, resample, sketch, "
    "smooth-depth, mirror, reverse, delete-component",
    setup);

}  // namespace
}  // namespace s4d::cli
