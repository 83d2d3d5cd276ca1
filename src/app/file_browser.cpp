#include "app/file_browser.hpp"

#include <imgui.h>

#include <algorithm>

namespace s4d {

namespace fs = std::filesystem;

FileBrowser::FileBrowser(std::string title, std::vector<std::string> extensions, bool save)
    : title_(std::move(title)), extensions_(std::move(extensions)), save_(save) {}

void FileBrowser::open(const fs::path& folder) {
  std::error_code ec;
  folder_ = fs::is_directory(folder, ec) ? fs::absolute(folder, ec) : fs::current_path(ec);
  want_open_ = true;
  refresh();
}

void FileBrowser::refresh() {
  entries_.clear();
  error_.clear();
  std::error_code ec;
  for (fs::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec)) {
    const auto& e = *it;
    if (e.path().filename().string().starts_with(".")) continue;
    if (e.is_directory(ec)) {
      entries_.push_back(e);
      continue;
    }
    std::string ext = e.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (std::find(extensions_.begin(), extensions_.end(), ext) != extensions_.end())
      entries_.push_back(e);
  }
  if (ec) error_ = "cannot list " + folder_.string() + ": " + ec.message();
  std::sort(entries_.begin(), entries_.end(), [](const auto& a, const auto& b) {
    std::error_code e1, e2;
    const bool da = a.is_directory(e1), db = b.is_directory(e2);
    return da != db ? da : a.path().filename() < b.path().filename();
  });
}

std::optional<fs::path> FileBrowser::draw() {
  if (want_open_) {
    ImGui::OpenPopup(title_.c_str());
    want_open_ = false;
  }
  std::optional<fs::path> chosen;
  ImGui::SetNextWindowSize(ImVec2(560, 420), ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal(title_.c_str(), nullptr)) return chosen;
  ImGui::TextUnformatted(folder_.string().c_str());
  if (ImGui::Button("Up") && folder_.has_parent_path()) {
    folder_ = folder_.parent_path();
    refresh();
  }
  if (!error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error_.c_str());
  ImGui::BeginChild("entries", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 2), true);
  fs::path go_into;
  for (const auto& e : entries_) {
    std::error_code ec;
    const bool dir = e.is_directory(ec);
    const std::string label = e.path().filename().string() + (dir ? "/" : "");
    if (ImGui::Selectable(label.c_str(), false, ImGuiSelectableFlags_AllowDoubleClick)) {
      if (dir) {
        go_into = e.path();
      } else {
        std::snprintf(name_, sizeof name_, "%s", e.path().filename().string().c_str());
        if (ImGui::IsMouseDoubleClicked(0) && !save_) chosen = e.path();
      }
    }
  }
  ImGui::EndChild();
  if (!go_into.empty()) {
    folder_ = go_into;
    refresh();
  }
  // The name field has the keys as the dialog appears (type a name, Enter saves or opens).
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  const bool entered = ImGui::InputText("file", name_, sizeof name_, ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button(save_ ? "Save" : "Open") || entered) && name_[0]) {
    const fs::path p(name_);
    chosen = p.is_absolute() ? p : folder_ / p;
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
  if (chosen) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return chosen;
}

}  // namespace s4d
