// The knot diagram of the view: the crossings of every curve object's image as a camera sees it
// (perspective included), which the renderer marks with dots and the crossing change edits.
#pragma once
#include <vector>

#include "core/camera.hpp"
#include "io/scene.hpp"
#include "proximity/shadow_crossings.hpp"

namespace s4d {

// A crossing of a curve's image on the screen: the point of each strand there, in shadow space
// (where the curve is drawn), the over strand nearer the eye, and each strand's unit direction.
struct ScreenCrossing {
  int object = 0;  // index in scene.objects
  Vec3 over, under;
  Vec3 over_direction = Vec3::UnitX(), under_direction = Vec3::UnitX();
  // Where each strand is on the curve (component and segment) when the whole curve is in front
  // of the eye; component -1 otherwise.
  SegmentRef over_at{-1, -1}, under_at{-1, -1};
};

// A curve object's image on the screen as an orthographic shadow: (x, y) on the screen, depth 1/w
// (w the distance in front of the eye, so larger is nearer), the camera's perspective included.
// Cut into open runs where part of it is behind the eye (`whole` false).
struct ScreenImage {
  int object = 0;  // index in scene.objects
  Curve<3> image;
  bool whole = true;
};

struct ScreenCrossings {
  std::vector<ScreenCrossing> crossings;
  std::vector<ScreenImage> images;  // one per curve object
  int non_generic = 0;      // spots where the image is not a regular diagram (a crossing at a
                            // vertex, overlapping strands): turning the view a little clears them
  int behind_eye = 0;       // curve points closer to the eye than the near plane, or behind it:
                            // the curve is cut there, and only what the camera sees is counted
};

// A curve object's components where they are drawn (shadow space): a curve of R^3 as it is, one
// of R^4 through the frame, with each point's w of the view in `w` when given. Empty for surfaces.
std::vector<Polyline<3>> drawn_curve(const Shape& shape, const Frame<4>& frame,
                                     std::vector<std::vector<double>>* w = nullptr);

// The crossings of the image of every curve object as `camera` sees it (curves in R^4 by their
// shadow through scene.frame): the knot diagram of the view, perspective included.
ScreenCrossings screen_crossings(const Scene& scene, const Camera& camera);

}  // namespace s4d
