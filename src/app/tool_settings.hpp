// The window's tool settings as one flat map of named numbers: what sessions save (so an autosave
// brings back the ribbon's width or the band's stiffness, not only the shapes) and what undo puts
// back (one slider drag is one step). Names are "group.setting"; unknown names are ignored, so a
// session of an older or newer window opens with what both know.
#pragma once
#include <map>
#include <string>

namespace s4d {

struct GuiModel;

using ToolSettings = std::map<std::string, double>;

ToolSettings tool_settings(const GuiModel& model);
// Applies every known, finite setting (clamped to its range); sends the live ones to the loop.
void apply_tool_settings(GuiModel& model, const ToolSettings& settings);

}  // namespace s4d
