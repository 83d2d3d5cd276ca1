#include "app/layout.hpp"

#include <algorithm>
#include <cmath>

namespace s4d {

std::vector<std::pair<std::string, Rect>> Layout::panels() const {
  std::vector<std::pair<std::string, Rect>> out;
  for (const auto& [name, r] : {std::pair<const char*, const Rect&>{"menu", menu}, {"left column", left},
                                {"right column", right}, {"instruction", band}, {"status line", status},
                                {"start page", page}})
    if (!r.empty()) out.emplace_back(name, r);
  return out;
}

Layout compute_layout(const LayoutInput& in) {
  const float width = std::isfinite(in.width) ? std::max(in.width, 1.0f) : 1;
  const float height = std::isfinite(in.height) ? std::max(in.height, 1.0f) : 1;
  const float s = std::isfinite(in.scale) && in.scale > 0 ? std::clamp(in.scale, 0.5f, 4.0f) : 1;
  const float line = std::max(in.line_height, 1.0f);
  Layout l;
  l.menu = {0, 0, width, std::min(in.menu_height, height)};
  const float top = l.menu.bottom();
  l.status = {0, std::max(top, height - std::round(line + 6 * s)), width, 0};
  l.status.h = height - l.status.y;
  const float body = std::max(l.status.y - top, 0.0f);

  // Columns at their width, or strips; when the view would be too narrow, the right column then
  // the left give way down to their strips.
  float lw = in.left_open ? std::round(kLeftColumnWidth * s) : std::round(kStripWidth * s);
  float rw = in.right_open ? std::round(kRightColumnWidth * s) : std::round(kStripWidth * s);
  const float strip = std::round(kStripWidth * s);
  const float min_view = kMinViewShare * width;
  for (float* w : {&rw, &lw}) {
    const float excess = lw + rw + min_view - width;
    if (excess > 0) *w = std::max(strip, *w - excess);
  }
  if (lw + rw > width) lw = rw = std::floor(width / 2);  // a tiny window: the columns, no view
  l.left_folded = lw <= strip;
  l.right_folded = rw <= strip;
  l.left = {0, top, lw, body};
  l.right = {width - rw, top, rw, body};

  const float mid_x = lw, mid_w = std::max(width - lw - rw, 0.0f);
  float y = top;
  if (in.band_lines > 0) {
    const float band_h = std::min(std::round(in.band_lines * line + 10 * s), body / 3);
    l.band = {mid_x, y, mid_w, band_h};
    y += band_h;
  }
  const Rect middle{mid_x, y, mid_w, std::max(l.status.y - y, 0.0f)};
  if (in.start_page) l.page = middle;
  else l.view = middle;
  return l;
}

}  // namespace s4d
