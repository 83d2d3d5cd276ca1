// Where the window's parts go: the menu bar on top, the panels in two side columns, the
// scenario's instruction in a band above the view, the status line at the bottom, and the 3D view
// in what is left. A pure function of the window's size and the UI scale, so that it can be
// tested without a window: the view never lies under a panel.
#pragma once
#include <string>
#include <vector>

namespace s4d {

struct Rect {
  float x = 0, y = 0, w = 0, h = 0;  // window pixels, y down
  float right() const { return x + w; }
  float bottom() const { return y + h; }
  bool contains(float px, float py) const { return px >= x && px <= right() && py >= y && py <= bottom(); }
  bool intersects(const Rect& o) const { return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom(); }
  bool empty() const { return !(w > 0 && h > 0); }
};

struct LayoutInput {
  float width = 1280, height = 800;  // the window, in pixels
  float scale = 1;                   // UI scale: the monitor's content scale times the user's setting
  float menu_height = 19;            // the menu bar's, as ImGui draws it at this scale
  float line_height = 17;            // one line of text with its spacing, at this scale
  int band_lines = 0;                // the instruction band's lines (0: no band)
  bool left_open = true, right_open = true;  // a closed column is a narrow strip with its button
  bool start_page = false;           // the start page takes the view's place
};

struct Layout {
  Rect menu, left, right, band, status, view;
  Rect page;  // the start page, when shown (the view is then empty)
  bool left_folded = false, right_folded = false;  // shown as strips (closed, or given way)
  // Every part a panel is drawn in (for the window's dump and the tests).
  std::vector<std::pair<std::string, Rect>> panels() const;
};

// Column widths at scale 1; a column gives way (down to its strip) so that the view keeps at
// least kMinViewShare of the width.
constexpr float kLeftColumnWidth = 300, kRightColumnWidth = 330, kStripWidth = 22, kMinViewShare = 0.4f;

Layout compute_layout(const LayoutInput& in);

}  // namespace s4d
