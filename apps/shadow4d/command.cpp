#include "command.hpp"

#include <vector>

namespace s4d::cli {

namespace {
struct Entry {
  std::string name, description;
  CommandSetup setup;
};
std::vector<Entry>& registry() {
  static std::vector<Entry> entries;  // function-local: safe across translation units at init
  return entries;
}
}  // namespace

CommandRegistrar::CommandRegistrar(std::string name, std::string description, CommandSetup setup) {
  registry().push_back({std::move(name), std::move(description), std::move(setup)});
}

void add_registered_commands(CLI::App& app) {
  for (auto& e : registry()) e.setup(*app.add_subcommand(e.name, e.description));
}

}  // namespace s4d::cli
