// Where a point of the shadow space is on the window (pixels, y down), as the camera sees it.
#pragma once
#include <imgui.h>

#include "core/camera.hpp"

namespace s4d {

// False when the point is not finite or not in front of the eye.
inline bool to_screen(const Camera& camera, const Vec3& p, const Vec2& window, ImVec2& out) {
  if (!p.allFinite() || camera.view_depth(p) <= camera.near_plane) return false;
  const Vec2 n = camera.ndc(p);
  out = ImVec2(static_cast<float>((n.x() + 1) / 2 * window.x()), static_cast<float>((1 - n.y()) / 2 * window.y()));
  return true;
}

}  // namespace s4d
