// The haptics panel: [SECTION] device, [SECTION] loop statistics, [SECTION] safety, [SECTION] parameters.
#include "app/haptics_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "core/error.hpp"
#include "haptics/device_spec.hpp"

namespace s4d {
namespace {

constexpr const char* kDevices[] = {"mouse", "sim", "spacenav", "openhaptics", "replay"};

}  // namespace

const char* const* haptics_panel_devices(int* count) {
  *count = static_cast<int>(std::size(kDevices));
  return kDevices;
}

Vec3 pointer_to_workspace(const DeviceCapabilities& caps, double nx, double ny, double depth) {
  const Vec3 n(std::clamp(nx, -1.0, 1.0), std::clamp(ny, -1.0, 1.0), std::clamp(depth, -1.0, 1.0));
  const Vec3 half = 0.5 * (caps.workspace_max - caps.workspace_min);
  return caps.workspace_centre() + n.cwiseProduct(half);
}

ForceArrow force_arrow(const HapticSnapshot& snap, double metres_per_newton) {
  ForceArrow a;
  a.from = snap.device.position;
  a.to = a.from + metres_per_newton * snap.force_output;
  a.anchor = snap.tool.anchor;
  a.target = snap.device.target;
  a.engaged = snap.tool.engaged;
  const double limit = snap.caps.max_force > 0 ? snap.caps.max_force : 1.0;
  const float f = static_cast<float>(std::clamp(snap.force_output.norm() / limit, 0.0, 1.0));
  a.rgba = {f, 1.0f - f, 0.1f, 1.0f};
  return a;
}

void draw_haptics_panel(HapticsPanelState& ui, HapticLoop& loop, const HapticSnapshot& snap) {
  if (!ui.open) return;

  // [SECTION] device
  ImGui::Text("Device: %s (%s)", snap.device_name, snap.device_connected ? "connected" : "DISCONNECTED");
  ImGui::Combo("backend", &ui.device_choice, kDevices, static_cast<int>(std::size(kDevices)));
  if (ui.device_choice == 4) ImGui::InputText("file", ui.replay_file.data(), ui.replay_file.size());
  if (ImGui::Button("Switch device")) {
    ui.requested_device = kDevices[ui.device_choice];
    if (ui.device_choice == 4) ui.requested_device += std::string(":") + ui.replay_file.data();
  }
  if (!ui.error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", ui.error.c_str());
  ImGui::Text("peak %.2f N, continuous %.2f N, stiffness %.2f N/mm", snap.caps.max_force,
              snap.caps.max_continuous_force, snap.caps.max_stiffness * 1e-3);
  ImGui::Text("position (%.1f, %.1f, %.1f) mm, buttons %u", 1e3 * snap.device.position.x(),
              1e3 * snap.device.position.y(), 1e3 * snap.device.position.z(), snap.device.buttons);

  // [SECTION] loop statistics
  ImGui::Separator();
  const PeriodSummary& p = snap.period;
  ImGui::Text("%s loop at %.0f Hz, %s", snap.running ? "running" : "stopped", 1e6 / p.nominal_us,
              snap.realtime ? "real-time priority" : "normal priority");
  ImGui::Text("period p50 %.0f  p99 %.0f  p99.9 %.0f  max %.0f us", p.p50_us, p.p99_us, p.p999_us, p.max_us);
  ImGui::Text("missed deadlines %llu, over 2 ms %llu", static_cast<unsigned long long>(p.missed),
              static_cast<unsigned long long>(p.over_2ms));
  ImGui::Text("tick work p99 %.0f us, max %.0f us", snap.work.p99_us, snap.work.max_us);
  if (snap.recent_count > 0) {
    char overlay[48];
    std::snprintf(overlay, sizeof overlay, "last %d periods (us)", snap.recent_count);
    const float nominal = static_cast<float>(p.nominal_us);
    ImGui::PlotLines("##periods", snap.recent_periods_us.data(), snap.recent_count, 0, overlay, 0.0f,
                     2.5f * nominal, ImVec2(0, 60));
  }
  if (ImGui::Button("Reset statistics")) loop.reset_stats();

  // [SECTION] safety
  ImGui::Separator();
  ImGui::Text("force %.2f N (max %.2f N), safety: %s, gain %.2f", snap.force_output.norm(),
              snap.max_force_output, safety_phase_name(snap.safety_phase), snap.safety_gain);
  ImGui::Text("clamped %llu, rate-limited %llu, non-finite %llu",
              static_cast<unsigned long long>(snap.safety.clamped),
              static_cast<unsigned long long>(snap.safety.rate_limited),
              static_cast<unsigned long long>(snap.safety.nonfinite));
  ImGui::SliderFloat("arrow m/N", &ui.arrow_scale, 0.001f, 0.05f, "%.3f");

  // [SECTION] parameters
  ImGui::Separator();
  for (int i = 0; i < snap.param_count; ++i) {
    const SceneParam& sp = snap.params[i];
    double v = sp.value;
    char label[64];
    std::snprintf(label, sizeof label, "%s %s##p%d", sp.name, sp.unit, i);
    if (ImGui::SliderScalar(label, ImGuiDataType_Double, &v, &sp.min, &sp.max, "%.3g")) loop.set_param(i, v);
  }
}

}  // namespace s4d
