// The Haptics panel of the window for the session's loop: the device (switched through the
// session, which maps it onto the view), the loop's period and safety statistics, the hand's
// parameters. There is one simulation, the one in the view; its device cursor is drawn there.
#pragma once
#include <string>

#include "app/dock.hpp"
#include "app/haptics_panel.hpp"

namespace s4d {

class Session;

class HapticsWindow {
 public:
  HapticsWindow() { ui_.open = false; }  // shown when the menu or --device asks for it
  // Draws the panel, a section of the left column, when open; a no-op when closed.
  void draw(Session& session, Dock& dock);
  bool& open() { return ui_.open; }

 private:
  HapticsPanelState ui_{};
  std::string shown_device_;  // the device the backend list was last set to
};

}  // namespace s4d
