// The window's first page when it is started with no file: the paper's examples as cards (a small
// picture, the figure, one line; a click opens it), the knot exercises, a sketch on an empty scene,
// the recent sessions and files, and the mouse and keys. It takes the 3D view's place.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "io/recent_files.hpp"

namespace s4d {

struct GuiModel;
class Panels;

class StartPage {
 public:
  StartPage() = default;
  ~StartPage();
  StartPage(const StartPage&) = delete;
  StartPage& operator=(const StartPage&) = delete;

  // Reads the scenarios' folder (names, figures, summaries) and the recent list.
  void load(const std::filesystem::path& scenarios, const RecentFiles& recent);
  // Draws the page in model.layout.page; its choices open documents or start tools on the model.
  // The examples' cards (name, rectangle) go to model.start_cards for the window's dump.
  void draw(GuiModel& model);

 private:
  struct Example {
    std::filesystem::path file;
    std::string name, figure, summary, error;
    unsigned texture = 0;  // its picture, drawn the first time the page is shown
    bool drawn = false;
  };
  void draw_examples(GuiModel& model);
  void draw_starts(GuiModel& model);
  void draw_picture(Example& e);

  std::vector<Example> examples_;
  std::vector<std::filesystem::path> recent_;
};

}  // namespace s4d
