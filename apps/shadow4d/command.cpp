#include "command.hpp"

#include <map>

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

namespace {

// One example a command, shown under its --help (and run by no test: the README's are).
const std::map<std::string, std::string>& examples() {
  static const std::map<std::string, std::string> m{
      {"check", "shadow4d check clifford-torus --rotate xw=30,yw=20"},
      {"demo", "shadow4d demo --out demo-output"},
      {"explore", "shadow4d explore clifford-torus --rotate xw=30,yw=20 --through \"-1,0,0;1,0,0\" --wav passes.wav; "
                  "a knot, traced once round: shadow4d explore scenes/trefoil-knot.json --wav crossings.wav"},
      {"generators", "shadow4d generators"},
      {"haptics", "shadow4d haptics --device sim --scene cloth --seconds 2"},
      {"knot", "shadow4d knot identify torus-knot:p=3,q=4   (and: knot make 7_4 --out k.curve)"},
      {"render", "shadow4d render scenes/spun-trefoil.json --out pic.png --intersections"},
      {"run", "shadow4d run scenarios/spun-trefoil-tighten.json --out run-out"},
      {"session", "shadow4d session info ~/.local/state/shadow4d/autosave.s4d"},
      {"sketch-ribbon", "shadow4d sketch-ribbon scenes/sphere-and-ribbon.json stroke.txt --out threaded.json"},
      {"soak", "shadow4d soak --minutes 30"},
  };
  return m;
}

constexpr const char* kExitCodes =
    "Exit codes: 0 done; 1 an error (the message says what was wrong and what to do); 2 found what you asked "
    "about (check: true intersections; soak: something that must never happen); 3 a scenario missed its outcome "
    "(run).";

}  // namespace

void add_registered_commands(CLI::App& app) {
  for (auto& e : registry()) {
    CLI::App* sub = app.add_subcommand(e.name, e.description);
    e.setup(*sub);
    const auto it = examples().find(e.name);
    sub->footer((it == examples().end() ? std::string() : "Example: " + it->second + "\n") + kExitCodes);
  }
  app.footer(kExitCodes);
}

}  // namespace s4d::cli
