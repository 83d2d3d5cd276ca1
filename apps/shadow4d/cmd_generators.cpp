// `shadow4d generators`: lists every generated object with its parameters (the CLI's catalogue).
#include <iostream>

#include "command.hpp"
#include "shape/generators.hpp"

namespace s4d::cli {
namespace {

const CommandRegistrar kGenerators(
    "generators", "list the objects shadow4d can generate and their parameters", [](CLI::App& sub) {
      sub.callback([] {
        for (const auto& g : generator_catalogue()) {
          std::cout << g.name << "  (" << (g.surface ? "surface" : "curve") << " in R^" << g.dim
                    << ")  " << g.description << "\n";
          for (const auto& p : g.params)
            std::cout << "    " << p.name << " = " << p.default_value << "  [" << p.min << ", "
                      << p.max << "]" << (p.integer ? " integer" : "") << "  " << p.help << "\n";
        }
        std::cout << "\nUse as NAME or NAME:key=value,key=value, e.g. spun-trefoil:n=48\n";
      });
    });

}  // namespace
}  // namespace s4d::cli
