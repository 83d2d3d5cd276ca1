// Where a point of the shadow space is on the window (pixels, y down), as the camera sees it in
// the 3D view's rectangle.
#pragma once
#include <imgui.h>

#include "app/layout.hpp"
#include "core/camera.hpp"

namespace s4d {

// False when the point is not finite or not in front of the eye.
inline bool to_screen(const Camera& camera, const Vec3& p, const Rect& view, ImVec2& out) {
  if (!p.allFinite() || camera.view_depth(p) <= camera.near_plane) return false;
  const Vec2 n = camera.ndc(p);
  out = ImVec2(view.x + static_cast<float>((n.x() + 1) / 2 * view.w), view.y + static_cast<float>((1 - n.y()) / 2 * view.h));
  return true;
}

}  // namespace s4d
