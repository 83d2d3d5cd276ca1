// A small ImGui file browser: a folder listing filtered by the extensions shadow4d reads, plus a
// path field, so a user can open or save without a native dialog.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace s4d {

class FileBrowser {
 public:
  // `title` is the ImGui popup name; `save` shows a file-name field and a Save button.
  FileBrowser(std::string title, std::vector<std::string> extensions, bool save);

  void open(const std::filesystem::path& folder);
  // Draws the popup if open; returns the chosen path once.
  std::optional<std::filesystem::path> draw();

 private:
  void refresh();

  std::string title_;
  std::vector<std::string> extensions_;
  bool save_;
  bool want_open_ = false;
  std::filesystem::path folder_;
  std::vector<std::filesystem::directory_entry> entries_;
  char name_[512] = {};
  std::string error_;
};

}  // namespace s4d
