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
      {"knot identify", "shadow4d knot identify torus-knot:p=3,q=4"},
      {"knot code", "shadow4d knot code scenes/trefoil-knot.json --rotate xz=30"},
      {"knot compare", "shadow4d knot compare torus-knot:p=2,q=3 \"torus-knot:p=2,q=3,mirror=1\""},
      {"knot info", "shadow4d knot info scenes/trefoil-knot.json"},
      {"knot unknotting", "shadow4d knot unknotting scenes/trefoil-knot.json"},
      {"knot make", "shadow4d knot make 7_4 --out k.curve   (knot make --list: the names; knot make --pd "
                    "\"[[1,5,2,4],[3,1,4,6],[5,3,6,2]]\" --out k.curve)"},
      {"knot mirror", "shadow4d knot mirror k.curve --out mirror.curve"},
      {"knot reverse", "shadow4d knot reverse link.curve --component 2 --out reversed.curve"},
      {"knot delete-component", "shadow4d knot delete-component link.curve --component 2 --out rest.curve"},
      {"knot relax", "shadow4d knot relax k.curve --out relaxed.curve"},
      {"knot flip", "shadow4d knot flip scenes/trefoil-knot.json --crossing 1 --out unknot.curve"},
      {"knot resample", "shadow4d knot resample k.curve --points 200 --out k200.curve"},
      {"knot sketch", "shadow4d knot sketch stroke.txt --knot --out k.curve   (or --device replay:hand.traj)"},
      {"knot smooth-depth", "shadow4d knot smooth-depth k.curve --out smooth.curve"},
      {"session info", "shadow4d session info ~/.local/state/shadow4d/autosave.s4d"},
      {"session run", "shadow4d session run scenes/cloth.json --seconds 10 --autosave work.s4d --restore"},
  };
  return m;
}

constexpr const char* kExitCodes =
    "Exit codes: 0 done; 1 an error (the message says what was wrong and what to do); 2 found what you asked "
    "about (check: true intersections; soak: something that must never happen); 3 a scenario missed its outcome "
    "(run).";

}  // namespace

namespace {

// The example of `path` ("knot" or "knot make") and the exit codes, under its --help, and the same
// for each of its own sub-commands.
void add_footers(CLI::App& app, const std::string& path) {
  const auto it = examples().find(path);
  app.footer((it == examples().end() ? std::string() : "Example: " + it->second + "\n") + kExitCodes);
  for (CLI::App* sub : app.get_subcommands({})) add_footers(*sub, path + " " + sub->get_name());
}

}  // namespace

void add_registered_commands(CLI::App& app) {
  for (auto& e : registry()) {
    CLI::App* sub = app.add_subcommand(e.name, e.description);
    e.setup(*sub);
    add_footers(*sub, e.name);
  }
  app.footer(kExitCodes);
}

}  // namespace s4d::cli
