// Picking in the 3D shadow: every sheet of the scene's surfaces that a view ray crosses, nearest
// the eye first. The shadow folds sheets far apart in w onto each other, so one cursor position
// can mean several places of the surface; the grab tool takes the first and Tab the next.
#pragma once
#include <vector>

#include "core/camera.hpp"
#include "io/scene.hpp"

namespace s4d {

struct SheetHit {
  int object = -1;    // index in scene.objects
  int triangle = -1;  // of that object's surface
  int vertex = -1;    // the object's vertex nearest the hit (local index)
  Vec3 point = Vec3::Zero();  // shadow space
  double distance = 0;        // along the ray from its origin
  double w = 0;               // 4D depth of the surface there (0 for objects of R^3)
  bool strand = false;        // a curve's strand (pick_strands), not a surface's sheet
};

// The hits of the ray origin + t·dir (t > 0) on the surfaces of `scene` as drawn: objects of
// R^4 by their shadow through scene.frame, those of R^3 as they are. One hit per sheet: where
// the ray passes through an edge or a vertex the neighbouring triangles' hits are merged.
std::vector<SheetHit> pick_sheets(const Scene& scene, const Vec3& origin, const Vec3& dir);

// The strands of the scene's curves passing within `pixels` of `cursor` (window pixels, y down, in
// a window of `window` pixels) as `camera` draws them, nearest the eye first: one hit per strand
// (a run of segments along a component), at its point nearest the cursor. `vertex` is the curve's
// point nearest that (its index over the components in order), `triangle` the segment's index
// there, `w` the 4D depth of a curve of R^4 (0 in R^3). At a crossing two strands are under the
// cursor: the grab tool takes the nearer, Tab the other.
std::vector<SheetHit> pick_strands(const Scene& scene, const Camera& camera, const Vec2& cursor, const Vec2& window,
                                   double pixels);

}  // namespace s4d
