// What the knot sub-commands share: the curve argument, and a name, its invariants and a
// diagram's codes printed for people or as JSON.
#include "knot_commands.hpp"

#include <iostream>

#include "knots/knot_index.hpp"
#include "knots/knot_invariants.hpp"

namespace s4d::cli {

using nlohmann::json;

void add_curve_args(CLI::App* s, KnotCurveArgs& c, bool with_view) {
  s->add_option("file", c.file, "curve file (.curve/.txt/.xyz/.vect), generator call, or scene (.json: its curves)")
      ->required();
  if (with_view) s->add_option("--rotate", c.view, "view rotation, e.g. xz=30,yz=10 (degrees)");
  s->add_flag("--json", c.json_out, "machine-readable output");
}

void add_fast_flag(CLI::App* s, bool& fast) {
  s->add_flag("--fast", fast,
              "skip the slow refinements (covers of the group, Reidemeister search, unknot recognition) for "
              "batch use; the name then says what was skipped");
}

void add_engine_option(CLI::App* s, std::string& engine) {
  s->add_option("--engine", engine,
                "knot engine: regina (the default where built with Regina) or own (the project's, as in the web "
                "page; no covers or unknot recognition, so such names stay not proven)")
      ->check(CLI::IsMember({"regina", "own"}));
}

KnotEngine engine_of(const std::string& option) {
  return option.empty() ? default_knot_engine() : parse_knot_engine(option);
}

namespace {

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

}  // namespace

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

void print_identification(const KnotIdentification& id, const std::string& indent, const std::string& headline) {
  std::cout << indent << (id.kind == KnotKind::kLink ? "link: " : "knot: ")
            << (headline.empty() ? id.headline() : headline) << "\n";
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

json naming_json(const KnotNaming& n) {
  json j = identification_json(n.identification);
  j["decided_by"] = n.decided_by;
  j["further_used"] = n.further_used;
  j["skipped"] = n.skipped;
  j["unavailable"] = n.unavailable;
  j["engine"] = engine_name(n.identification.invariants.engine);
  j["chirality"] = n.chirality();
  return j;
}

void print_naming(const KnotNaming& n) {
  print_identification(n.identification, "", n.headline());
  for (const auto& x : n.decided_by) std::cout << "decided by: " << x << "\n";
  for (const auto& x : n.further_used) std::cout << "further invariant tried: " << x << "\n";
  for (const auto& x : n.skipped) std::cout << "skipped (--fast): " << x << "\n";
  for (const auto& x : n.unavailable) std::cout << "unavailable without Regina: " << x << "\n";
}

json info_json(const KnotInfo& k) {
  return {{"name", k.name},
          {"proven", k.proven},
          {"chirality", k.chirality},
          {"candidates", k.candidates},
          {"decided_by", k.decided_by},
          {"further_used", k.further_used},
          {"skipped", k.skipped},
          {"unavailable", k.unavailable},
          {"engine", engine_name(k.identification.invariants.engine)},
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

json codes_json(const KnotDiagram& d, KnotEngine engine) {
  const ReginaCodes r = regina_codes(d, engine);
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

}  // namespace s4d::cli
