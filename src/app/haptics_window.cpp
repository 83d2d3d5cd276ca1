#include "app/haptics_window.hpp"

#include <imgui.h>

#include <algorithm>

#include "interact/session/session.hpp"

namespace s4d {

void HapticsWindow::draw(Session& session, Dock& dock) {
  if (!ui_.open || !dock.begin(Side::kLeft, "Haptics", &ui_.open)) return;
  if (!session.loop() || !session.snapshot()) {
    ImGui::TextWrapped("The haptic loop runs while a scene with surfaces is simulated; open one "
                       "(File > Open) to touch it with the mouse or a device.");
    dock.end();
    return;
  }
  // The backend list starts at the device in use.
  int count = 0;
  const char* const* names = haptics_panel_devices(&count);
  const std::string_view in_use = session.snapshot()->device_name;
  if (in_use != shown_device_) {
    shown_device_ = std::string(in_use);
    for (int i = 0; i < count; ++i)
      if (in_use == names[i]) ui_.device_choice = i;
  }
  draw_haptics_panel(ui_, *session.loop(), *session.snapshot());
  dock.end();
  if (!ui_.requested_device.empty()) {
    try {
      session.set_device(ui_.requested_device);
      ui_.error.clear();
    } catch (const std::exception& e) {
      ui_.error = e.what();
    }
    ui_.requested_device.clear();
  }
}

}  // namespace s4d
