// The haptics side of the window: owns the HapticLoop (started on demand with the chosen device and
// haptic scene), draws the Haptics panel and a "Haptic workspace" view where the mouse drives the
// mouse backend's target and the force is shown as an arrow, the proxy's lag and a colour.
#pragma once
#include <memory>
#include <string>

#include "app/haptics_panel.hpp"

namespace s4d {

class HapticsWindow {
 public:
  HapticsWindow() { ui_.open = false; }  // shown when the menu or --device asks for it
  ~HapticsWindow();
  // Starts the loop with a device spec ("mouse", "sim", "replay:FILE", ...); errors are shown in the
  // panel and leave the loop stopped.
  void start(const std::string& device_spec);
  void stop();
  bool running() const { return loop_ != nullptr; }
  // Draws the panel and the workspace view when open; a no-op when closed.
  void draw();
  bool& open() { return ui_.open; }

 private:
  void workspace_view(const HapticSnapshot& snap);

  std::unique_ptr<HapticLoop> loop_;
  HapticsPanelState ui_{};
  int scene_choice_ = 0;     // 0 = sticky plane, 1 = 4D cloth on a rubber band
  float depth_ = 0.0f;       // wheel depth of the mouse target, in [-1, 1]
  std::string start_error_;
  std::string device_spec_ = "mouse";  // what start() was last given, reused by Restart
};

}  // namespace s4d
