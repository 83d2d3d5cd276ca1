// Sub-command registry: each cmd_*.cpp registers its own CLI11 sub-command at static-init time,
// so adding a command never means editing main.cpp.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace s4d::cli {

// `setup` adds options to `sub` and sets its callback. The callback reports failure by throwing
// s4d::Error (printed as "shadow4d: <message>", exit code 1).
using CommandSetup = std::function<void(CLI::App& sub)>;

struct CommandRegistrar {
  CommandRegistrar(std::string name, std::string description, CommandSetup setup);
};

// Thrown by a command to end the program with a given exit code after printing its report
// (e.g. `check` exits 2 when it finds true intersections).
struct ExitStatus {
  int code = 0;
};

// Adds every registered command to `app` (called once by main).
void add_registered_commands(CLI::App& app);

}  // namespace s4d::cli
