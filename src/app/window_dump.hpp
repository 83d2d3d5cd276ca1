// The input file's `dump`: the window's state as JSON, for scripted tests and for checking a run
// from outside (the simulation's status, the checks, every vertex and where it is on the screen,
// the panels' readouts, the tools' settings and the history), and where the view and the panels are.
#pragma once
#include <string>

#include "app/hint_markers.hpp"
#include "app/knot_panels.hpp"
#include "app/panels.hpp"
#include "app/slice_panel.hpp"
#include "core/camera.hpp"

namespace s4d {

// Writes the dump to `path`; a failure to write shows as the window's error.
void dump_state(GuiModel& model, const KnotPanels& knots, const SlicePanel& slice, const HintMarkers& hints,
                const std::string& path,
                const Camera& camera, int window_frame);

}  // namespace s4d
