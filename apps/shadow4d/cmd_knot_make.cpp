// `knot make`: a relaxed 3D curve of a knot or link of the table, or of a PD or DT code, named back;
// `--list` the names.
#include <chrono>
#include <iostream>
#include <memory>

#include "core/error.hpp"
#include "io/object_file.hpp"
#include "knot_commands.hpp"
#include "knots/diagram_codes.hpp"
#include "knots/knot_table.hpp"

namespace s4d::cli {

using nlohmann::json;

namespace {

struct MakeArgs {
  std::string name, out, pd, dt;
  bool list = false, json_out = false;
  DiagramEmbedding embed;
};

void make_knot(const MakeArgs& a) {
  if (a.list) {
    for (const auto& t : knot_table_names())
      std::cout << t.name << "\t" << t.crossings << "\t" << t.source << (t.alias.empty() ? "" : "\t" + t.alias)
                << "\n";
    return;
  }
  const int given = !a.name.empty() + !a.pd.empty() + !a.dt.empty();
  if (given != 1 || a.out.empty())
    throw Error("knot make needs one of a NAME, --pd CODE or --dt CODE, and --out FILE (or --list)");
  const auto t0 = std::chrono::steady_clock::now();
  // A code is drawn as the table draws its diagrams (table_knot's for a name).
  std::string what;
  Curve<3> c;
  if (!a.name.empty()) {
    what = table_knot(a.name).name;
    c = make_table_knot(a.name, a.embed);
  } else {
    what = a.pd.empty() ? "the DT code" : "the PD code";
    c = curve_from_diagram(a.pd.empty() ? diagram_from_dt(a.dt) : diagram_from_pd(a.pd), a.embed);
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  write_shape_file(c, a.out);
  const KnotNaming id = name_knot(c);
  if (a.json_out)
    std::cout << json{{"name", what}, {"points", c.point_count()}, {"milliseconds", ms},
                      {"identified", id.name()}, {"proven", id.proven()}}
                     .dump(2)
              << "\n";
  else
    std::cout << "made " << what << ": " << c.point_count() << " points in " << ms << " ms, identified as "
              << id.headline() << "; wrote " << a.out << "\n";
}

}  // namespace

void add_knot_make(CLI::App& knot) {
  auto a = std::make_shared<MakeArgs>();
  auto* make = knot.add_subcommand(
      "make", "a 3D curve of a knot or link from the table (3_1, 11n_34, T(2,5), L6a4, Hopf link, m3_1, ...) or of a "
      "PD or DT code");
  make->add_option("name", a->name, "knot name; 'NAME mirror', 'mNAME' or 'NAME*' for the mirror image");
  make->add_option("--pd", a->pd,
                   "instead of a name, a PD code as KnotInfo, KnotTheory or SnapPy write it: "
                   "\"[[1,5,2,4],[3,1,4,6],[5,3,6,2]]\", \"PD[X[1,5,2,4],...]\"");
  make->add_option("--dt", a->dt,
                   "instead of a name, a DT code of a knot: \"4 6 2\" or \"bca\" (a DT code does not say which "
                   "of a knot and its mirror image)");
  make->add_option("--out", a->out, "where to write the curve");
  make->add_option("--relax", a->embed.relax_iterations, "relaxation steps")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000000));
  make->add_flag("--list", a->list, "list the table's names (with crossings and source) instead");
  make->add_flag("--json", a->json_out, "machine-readable output");
  make->callback([a] { make_knot(*a); });
}

}  // namespace s4d::cli
