// The window's input routing (window_routing.cpp): the keys, the mouse on the view, the status line.
#pragma once
#include "app/window_input.hpp"
#include "core/vec.hpp"
#include "interact/tools/tool.hpp"

namespace s4d {

struct GuiModel;
class KnotPanels;

// Who the held buttons belong to, across frames.
struct Routing {
  bool tool_drag = false;  // the left button belongs to the tool until it is released
  bool view_drag = false;  // ... or to the view
  bool right_down = false, right_panned = false;  // a right press is a click unless it drags
  Vec2 right_at = Vec2::Zero();
  bool middle_pan = false;
};

// One frame's keys and mouse: to the window, the active tool or the view; sounds of exploring.
void route_input(GuiModel& model, Routing& r, const WindowInput& in, const ToolInput& ti, KnotPanels& knots);
// The status line: the tools (the active one lit), then the last message cut to fit.
void status_line(GuiModel& model);

}  // namespace s4d
