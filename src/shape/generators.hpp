// The catalogue of generated objects. One registry serves the GUI's "Create" menu (sliders from
// ParamSpec), the CLI (`render clifford-torus:n=64`) and scene files ({"generator": ..., "params": ...}).
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "shape/shape.hpp"

namespace s4d {

struct ParamSpec {
  std::string name;
  double default_value = 0;
  double min = 0;
  double max = 0;
  bool integer = false;
  std::string help;
};

struct GeneratorInfo {
  std::string name;         // kebab-case, e.g. "spun-trefoil"
  std::string description;  // one line for menus and --help
  int dim = 4;              // ambient dimension of what it builds
  bool surface = true;      // surface or curve
  std::vector<ParamSpec> params;
};

using Params = std::map<std::string, double>;

// Every generator, in menu order.
const std::vector<GeneratorInfo>& generator_catalogue();
// nullptr if unknown.
const GeneratorInfo* find_generator(std::string_view name);

// Builds a generated shape. Missing params take their defaults; unknown names, unknown params,
// non-finite or out-of-range values throw s4d::Error with a sentence naming the culprit.
Shape generate(std::string_view name, const Params& params = {});

// Parses "name" or "name:key=value,key=value" (the CLI's object syntax).
struct GeneratorCall {
  std::string name;
  Params params;
};
GeneratorCall parse_generator_call(std::string_view text);

}  // namespace s4d
