// The panels' places: each panel is a collapsible section of the left or the right column, so
// that no panel ever floats over the 3D view. The columns are ImGui windows placed each frame
// where the layout says; a panel appends its section to its column (ImGui lets a window be begun
// several times a frame).
#pragma once
#include <string>
#include <vector>

#include "app/layout.hpp"

namespace s4d {

enum class Side { kLeft, kRight };

class Dock {
 public:
  // This frame's layout, before any panel is drawn.
  void place(const Layout& layout) { layout_ = layout; }
  const Layout& layout() const { return layout_; }

  // Begins the panel `name` as a section of its column; true when its contents are to be drawn,
  // and then end() must follow. `open`, when given, adds a close button to the section (a panel
  // the user asked for, such as History). A closed column shows only its strip: false.
  bool begin(Side side, const char* name, bool* open = nullptr, bool default_open = true);
  void end();

  // The columns' strips: the button that opens or closes each column. Drawn once a frame, after
  // the panels.
  void draw_strips(bool& left_open, bool& right_open);
  // The sections' headers drawn this frame (the dump's `sections`: what a person clicks to open one).
  struct Header {
    std::string name;
    Rect rect;
    bool open = false;
  };
  const std::vector<Header>& headers() const { return headers_last_; }
  // Whether a panel asked for a place in the column last frame: an empty column folds to its strip.
  bool wanted(Side side) const { return wanted_last_[side == Side::kLeft ? 0 : 1]; }

 private:
  bool begin_column(Side side);
  Layout layout_;
  bool wanted_now_[2] = {false, false}, wanted_last_[2] = {true, true};
  std::vector<Header> headers_now_, headers_last_;
};

// For panels laid out in a column: whether the next item of `width` pixels still fits on the
// current line (then it goes on it).
void same_line_if_fits(float width);
// ... for a button with this label.
void same_line_if_fits(const char* button_label);

// The window's ImGui windows as they are drawn this frame (for the dump): name and rectangle.
std::vector<std::pair<std::string, Rect>> visible_windows();

}  // namespace s4d
