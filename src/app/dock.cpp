#include "app/dock.hpp"

#include <imgui.h>
#include <imgui_internal.h>

#include <cstring>
#include <utility>

namespace s4d {

namespace {

constexpr ImGuiWindowFlags kColumnFlags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                          ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                          ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings;

const char* column_name(Side side) { return side == Side::kLeft ? "##left column" : "##right column"; }

}  // namespace

bool Dock::begin_column(Side side) {
  const Rect& r = side == Side::kLeft ? layout_.left : layout_.right;
  if (r.empty()) return false;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  ImGui::Begin(column_name(side), nullptr, kColumnFlags);
  return true;
}

bool Dock::begin(Side side, const char* name, bool* open, bool default_open) {
  if (!open || *open) wanted_now_[side == Side::kLeft ? 0 : 1] = true;
  if (side == Side::kLeft ? layout_.left_folded : layout_.right_folded) return false;
  if (open && !*open) return false;
  if (!begin_column(side)) return false;
  ImGui::SetNextItemOpen(default_open, ImGuiCond_Once);
  const bool shown = open ? ImGui::CollapsingHeader(name, open) : ImGui::CollapsingHeader(name);
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  headers_now_.push_back({name, Rect{a.x, a.y, b.x - a.x, b.y - a.y}, shown});
  if (!shown) {
    ImGui::End();
    return false;
  }
  ImGui::PushID(name);
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 8);  // room for the sliders' labels
  return true;
}

void Dock::end() {
  ImGui::PopItemWidth();
  ImGui::PopID();
  ImGui::Spacing();
  ImGui::End();
}

void Dock::draw_strips(bool& left_open, bool& right_open) {
  for (int i = 0; i < 2; ++i) wanted_last_[i] = std::exchange(wanted_now_[i], false);
  headers_last_ = std::exchange(headers_now_, {});
  for (Side side : {Side::kLeft, Side::kRight}) {
    bool& open = side == Side::kLeft ? left_open : right_open;
    if (!wanted_last_[side == Side::kLeft ? 0 : 1] && open) {  // nothing to show: a bare strip
      if (begin_column(side)) ImGui::End();
      continue;
    }
    if (!begin_column(side)) continue;
    const bool strip = side == Side::kLeft ? layout_.left_folded : layout_.right_folded;
    const char* label = side == Side::kLeft ? (open && !strip ? "<##fold left" : ">##fold left")
                                            : (open && !strip ? ">##fold right" : "<##fold right");
    // The fold button at the column's bottom corner, where no section is.
    const ImVec2 size(ImGui::GetFrameHeight(), ImGui::GetFrameHeight());
    const float x = side == Side::kLeft ? ImGui::GetWindowWidth() - size.x - ImGui::GetStyle().WindowPadding.x
                                        : ImGui::GetStyle().WindowPadding.x;
    ImGui::SetCursorPos(ImVec2(std::max(x, 2.0f), ImGui::GetWindowHeight() - size.y - ImGui::GetStyle().WindowPadding.y));
    if (ImGui::Button(label, size)) open = !open;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(open ? "fold this column away (View > Panels)" : "show this column's panels (View > Panels)");
    ImGui::End();
  }
}

void same_line_if_fits(float width) {
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  ImGui::SameLine();
  if (ImGui::GetCursorScreenPos().x + width > right) ImGui::NewLine();
}

void same_line_if_fits(const char* button_label) {
  const char* end = std::strstr(button_label, "##");
  same_line_if_fits(ImGui::CalcTextSize(button_label, end).x + 2 * ImGui::GetStyle().FramePadding.x);
}

std::vector<std::pair<std::string, Rect>> visible_windows() {
  std::vector<std::pair<std::string, Rect>> out;
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  for (const ImGuiWindow* w : g.Windows) {
    if (!w->Active || w->Hidden ||
        (w->Flags & (ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_Popup)))
      continue;
    std::string name = w->Name;
    if (name.rfind("##", 0) == 0) name = name.substr(2);
    if (const auto hash = name.find("##"); hash != std::string::npos) name = name.substr(0, hash);
    if (name == "Debug" || name.empty()) continue;
    out.emplace_back(name, Rect{w->Pos.x, w->Pos.y, w->Size.x, w->Size.y});
  }
  return out;
}

}  // namespace s4d
