// What the panels' files share: one change of a tool setting recorded as one undoable step.
#pragma once
#include <imgui.h>

#include <string>

#include "app/panels.hpp"

namespace s4d::panel_detail {

// One change of a tool setting (a whole slider drag) is one undoable step holding the value before
// it: on the frame an edit starts, `swap` puts the old value in place for the record, then back.
// (The hand's parameters need no swap: the snapshot shows the old value until the loop has the
// new one.)
template <typename Swap>
void record_tool_setting(GuiModel& model, const std::string& label, Swap swap) {
  if (!ImGui::IsItemActivated()) return;
  swap();
  model.session.record(label);
  swap();
}

}  // namespace s4d::panel_detail
