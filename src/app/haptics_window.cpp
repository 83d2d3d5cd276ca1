#include "app/haptics_window.hpp"

#include <imgui.h>

#include <algorithm>

#include "core/error.hpp"
#include "haptics/device_spec.hpp"
#include "haptics/haptic_session.hpp"

namespace s4d {

namespace {

constexpr const char* kScenes[] = {"plane", "cloth"};

ImU32 colour(const std::array<float, 4>& c) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], c[3]));
}

// Maps two device axes (a, b) of the workspace box to a canvas rectangle, b pointing up.
struct Canvas {
  ImVec2 origin, size;
  Vec3 lo, hi;
  int a, b;
  ImVec2 to_screen(const Vec3& p) const {
    const double u = (p[a] - lo[a]) / std::max(hi[a] - lo[a], 1e-9);
    const double v = (p[b] - lo[b]) / std::max(hi[b] - lo[b], 1e-9);
    return ImVec2(origin.x + static_cast<float>(u) * size.x, origin.y + static_cast<float>(1 - v) * size.y);
  }
};

void draw_canvas(const Canvas& c, const HapticSnapshot& snap, const ForceArrow& arrow) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(c.origin, ImVec2(c.origin.x + c.size.x, c.origin.y + c.size.y),
                    IM_COL32(22, 24, 30, 255));
  dl->AddRect(c.origin, ImVec2(c.origin.x + c.size.x, c.origin.y + c.size.y), IM_COL32(90, 90, 100, 255));
  const int d = snap.point_dimension;
  for (std::size_t i = 0; d >= 3 && i + d <= snap.points.size(); i += d) {
    const Vec3 p(snap.points[i], snap.points[i + 1], snap.points[i + 2]);
    dl->AddCircleFilled(c.to_screen(p), 1.5f, IM_COL32(150, 160, 190, 200));
  }
  if (arrow.engaged)
    dl->AddLine(c.to_screen(arrow.from), c.to_screen(arrow.anchor), IM_COL32(230, 200, 60, 255), 1.5f);
  dl->AddCircle(c.to_screen(arrow.target), 6.0f, IM_COL32(200, 200, 200, 255), 16, 1.5f);  // the hand
  dl->AddLine(c.to_screen(arrow.target), c.to_screen(arrow.from), IM_COL32(200, 200, 200, 120));  // lag
  dl->AddCircleFilled(c.to_screen(arrow.from), 5.0f, colour(arrow.rgba));  // the proxy
  dl->AddLine(c.to_screen(arrow.from), c.to_screen(arrow.to), colour(arrow.rgba), 3.0f);
}

}  // namespace

HapticsWindow::~HapticsWindow() { stop(); }

void HapticsWindow::start(const std::string& device_spec) {
  stop();
  device_spec_ = device_spec;
  int count = 0;
  const char* const* names = haptics_panel_devices(&count);
  const std::string kind = device_spec.substr(0, device_spec.find(':'));
  for (int i = 0; i < count; ++i)
    if (kind == names[i]) ui_.device_choice = i;
  try {
    SceneChoice choice;
    choice.name = kScenes[scene_choice_];
    loop_ =
        std::make_unique<HapticLoop>(make_device(parse_device_spec(device_spec)), make_haptic_scene(choice));
    loop_->start();
    start_error_.clear();
    ui_.open = true;
  } catch (const std::exception& e) {
    loop_.reset();
    start_error_ = e.what();
    ui_.open = true;
  }
}

void HapticsWindow::stop() {
  if (loop_) loop_->stop();
  loop_.reset();
}

void HapticsWindow::draw() {
  if (!ui_.open) return;
  if (!loop_) {
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - 390, 30), ImGuiCond_FirstUseEver);
    ImGui::Begin("Haptics", &ui_.open);
    ImGui::TextWrapped("The haptic loop is stopped.");
    if (!start_error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", start_error_.c_str());
    ImGui::Combo("scene", &scene_choice_, kScenes, static_cast<int>(std::size(kScenes)));
    if (ImGui::Button("Start with the mouse")) start("mouse");
    ImGui::SameLine();
    if (ImGui::Button("Start with the simulated arm")) start("sim");
    ImGui::End();
    return;
  }
  const HapticSnapshot& snap = loop_->snapshot();  // the one read of this frame
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 390, 30), ImGuiCond_FirstUseEver);
  draw_haptics_panel(ui_, *loop_, snap);
  workspace_view(snap);
  if (!ui_.open) stop();  // closing the panel stops the loop and releases the device
}

void HapticsWindow::workspace_view(const HapticSnapshot& snap) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 430, display.y - 310), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(420, 300), ImGuiCond_FirstUseEver);
  ImGui::Begin("Haptic workspace");
  ImGui::Combo("scene", &scene_choice_, kScenes, static_cast<int>(std::size(kScenes)));
  ImGui::SameLine();
  if (ImGui::Button("Restart")) {
    start(device_spec_);
    ImGui::End();
    return;
  }
  ImGui::TextDisabled("drag in the top view to move the hand; wheel: depth (z)");
  const ForceArrow arrow = force_arrow(snap, ui_.arrow_scale);
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float side = std::max(60.0f, std::min(avail.x * 0.62f, avail.y));
  Canvas top{ImGui::GetCursorScreenPos(),
             ImVec2(side, side),
             snap.caps.workspace_min,
             snap.caps.workspace_max,
             0,
             1};
  Canvas front{ImVec2(top.origin.x + side + 8, top.origin.y),
               ImVec2(std::max(40.0f, avail.x - side - 8), side),
               snap.caps.workspace_min,
               snap.caps.workspace_max,
               0,
               2};
  draw_canvas(top, snap, arrow);
  draw_canvas(front, snap, arrow);
  ImGui::InvisibleButton("workspace", top.size);
  const bool hovered = ImGui::IsItemHovered();
  if (hovered && ImGui::GetIO().MouseWheel != 0)
    depth_ = std::clamp(depth_ + 0.05f * ImGui::GetIO().MouseWheel, -1.0f, 1.0f);
  if (ImGui::IsItemActive()) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const double nx = 2.0 * (m.x - top.origin.x) / top.size.x - 1.0;
    const double ny = 1.0 - 2.0 * (m.y - top.origin.y) / top.size.y;
    loop_->set_pointer(
        pointer_to_workspace(snap.caps, std::clamp(nx, -1.0, 1.0), std::clamp(ny, -1.0, 1.0), depth_), 1u);
  } else if (hovered) {
    loop_->set_pointer(arrow.target, 0u);
  }
  ImGui::End();
}

}  // namespace s4d
