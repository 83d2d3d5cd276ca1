// The window's tools in one place: each declares its key, its menu entry and tooltip, and how
// the window reaches it. The Tools menu, the status line's buttons, the keys and the key card are
// generated from this list, so that adding a tool is its own file and one entry here.
#pragma once
#include <span>
#include <string>

namespace s4d {

class Tool;
struct GuiModel;
enum class ToolChoice;

struct ToolEntry {
  ToolChoice id;
  int key;               // GLFW key that chooses it
  const char* key_name;  // as shown ("T")
  const char* label;     // the status line's button and the menu's entry
  const char* menu;      // "Tools" or "Create"
  const char* tooltip;   // what it does, and its command-line twin
  Tool& (*get)(GuiModel&);
};

std::span<const ToolEntry> tool_entries();
const ToolEntry& tool_entry(ToolChoice id);

// The keys and mouse of the whole window (not of one tool), as the key card lists them.
struct KeyHelp {
  const char* keys;
  const char* what;
};
std::span<const KeyHelp> window_keys();

}  // namespace s4d
