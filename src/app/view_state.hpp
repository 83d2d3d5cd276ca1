// ViewState: what the mouse and the view panel control — the 3D trackball, the zoom, and the six
// 4D rotation angles (xy xz xw yz yw zw) applied on top of the scene's own frame.
#pragma once
#include <array>

#include "io/scene.hpp"

namespace s4d {

enum class DragMode {
  kTrackball,  // plain drag: turn the 3D view
  kRotateW,    // shift-drag: horizontal turns xw, vertical turns yw
  kRotateZW,   // ctrl-drag: horizontal turns zw
};

class ViewState {
 public:
  // Starts from the scene's frame and view; slider angles start at zero.
  void reset(const Scene& scene);

  // A first view of a bare R^4 object (no scene file to say how to look at it): straight along
  // w its shadow is folded onto itself, so the sliders start turned (xw 30°, zw 20°) — visibly,
  // and "Reset 4D rotation" returns to the plain projection.
  void turn_to_generic_view();

  // A mouse drag of (dx, dy) pixels in a viewport of the given height.
  void drag(DragMode mode, double dx, double dy, double viewport_height);
  // Mouse wheel: positive moves closer.
  void scroll(double steps);
  // Middle-drag, right-drag and the arrow keys: the picture moves by (dx, dy) in units of the
  // view's ball radius (x right, y up on the screen). Kept in those units, so that it survives a
  // zoom; the view's centre moves the other way along the trackball's axes (pan_offset).
  void pan_by(double dx, double dy);
  const Vec2& pan() const { return pan_; }
  // Where the view's centre is moved to by the pan, in shadow space, for a ball of `radius`.
  Vec3 pan_offset(double radius) const;
  // F, View > Frame all: zoom 1 and no pan (the caller fits the ball to the objects).
  void unzoom() {
    zoom_ = 1;
    pan_ = Vec2::Zero();
  }

  // Degrees, in the order of all_planes(4): xy, xz, xw, yz, yw, zw. Kept within [-180, 180].
  std::array<float, 6>& plane_angles() { return angles_; }
  const std::array<float, 6>& plane_angles() const { return angles_; }

  // The 4D perspective: the eye's distance along w, 0 for the orthographic shadow (the default).
  // set_perspective throws Error for a bad distance (Frame::perspective_error) and changes nothing.
  double perspective() const { return perspective_; }
  void set_perspective(double d) {
    if (d != 0) Frame<4>().set_perspective(d);  // the check, with its sentence
    perspective_ = d;
  }

  // Writes the composed 4D frame (with the perspective), trackball and zoom into the scene for drawing.
  void apply_to(Scene& scene) const;
  Frame<4> composed_frame() const;
  // For undo: the trackball and the zoom as they are, and put back.
  const Eigen::Quaterniond& trackball() const { return trackball_; }
  double zoom() const { return zoom_; }
  // For sessions: the frame the angles turn from (the scene's, as opened).
  const Frame<4>& base_frame() const { return base_frame_; }
  void set_base_frame(const Frame<4>& base) { base_frame_ = base; }
  void set(const std::array<float, 6>& angles, const Eigen::Quaterniond& trackball, double zoom) {
    angles_ = angles;
    trackball_ = trackball;
    zoom_ = zoom;
  }

 private:
  Frame<4> base_frame_;
  std::array<float, 6> angles_{};
  Eigen::Quaterniond trackball_ = Eigen::Quaterniond::Identity();
  double zoom_ = 1;
  Vec2 pan_ = Vec2::Zero();
  double perspective_ = 0;
};

}  // namespace s4d
