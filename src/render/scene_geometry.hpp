// Everything the renderer draws for one frame, computed on the CPU from a Scene: meshes in the
// 3D shadow space, the camera, and per-vertex depth colours. Pure data, testable without GL.
#pragma once
#include <string>
#include <vector>

#include "io/scene.hpp"
#include "proximity/shadow_crossings.hpp"
#include "proximity/shadow_intersections.hpp"
#include "core/camera.hpp"
#include "view/view_crossings.hpp"
#include "render/curve_diagram.hpp"
#include "render/geometry.hpp"

namespace s4d {

// Sides of curve tubes: enough for smooth silhouettes at GUI sizes.
inline constexpr int kTubeSides = 16;

struct DrawObject {
  RenderMesh mesh;
  std::vector<Vec3f> colours;  // nv × 3, linear RGB in [0, 1]
  std::vector<double> depth;   // nv, the depth that chose the colour (w for R^4, view depth for R^3)
  bool surface = true;         // surfaces get the wireframe overlay; tubes do not
  bool lit = true;             // false: drawn in its colours as they are (the above-below marks)
  // The flat strands of a curve in the shadow and diagram modes: positions are normalised device
  // coordinates (curve_diagram's strips), drawn unlit without the camera's matrices.
  bool screen = false;
  int dim = 4;                 // ambient dimension of the source object
};

struct DepthRange {
  double lo = 0, hi = 0;
  bool empty() const { return !(hi >= lo); }
};

// Colours of the intersection curves of the shadow (view.intersections): where the two sheets
// are apart in w the crossing is only in the shadow; where their depths agree the surface truly
// meets itself in R^4 (the paper's depth test), marked again by a bead.
inline const Vec3f kShadowOnlyColour{1.0f, 0.82f, 0.10f};
inline const Vec3f kTrueIntersectionColour{1.0f, 0.10f, 0.85f};
// The above-below marks beside each curve (the paper's Fig. 8c): a line on the sheet nearer in w
// (above: red, the coolwarm map's near end) and on the farther (below: blue, its far end). Drawn
// unlit and brighter than the map's ends, so that a red line still shows on a sheet that is
// itself red. They add to the yellow curve rather than replace it: the curve is where the sheets
// cross, what the counts and the pinch beads refer to, and what pairs the red line with the blue
// one when several crossings are close.
inline const Vec3f kAboveColour{1.0f, 0.13f, 0.10f};
inline const Vec3f kBelowColour{0.15f, 0.42f, 1.0f};
// The bead where a curve ends inside the surface: a pinch point of the shadow (Fig. 12).
inline const Vec3f kPinchPointColour{0.20f, 0.90f, 0.35f};
// The dot on the over strand at each crossing of a curve's image (view.intersections).
inline const Vec3f kCrossingColour{0.95f, 0.95f, 0.95f};
// The slice of the R^4 surfaces by w = c (view.slice): amber, apart from the depth colours and
// the yellow of the intersection curves.
inline const Vec3f kSliceColour{1.0f, 0.55f, 0.0f};
// The surfaces' opacity as drawn: view.opacity, at most kSliceFadeOpacity while a faded slice shows.
double drawn_opacity(const ViewSettings& view);

// What the drawn intersection curves are, summed over the R^4 surfaces (each with itself and
// each pair): for the view panel and the render command.
struct IntersectionSummary : ShadowCurveCounts {  // true_points: the beads drawn
  bool computed = false;  // view.intersections was on
  int surfaces = 0;       // R^4 surfaces looked at
  // Where the curves end: inside the surface (a pinch point of the shadow, beaded; a generic
  // view of a closed surface has an even number), or on a surface's border (where a sheet
  // stops); and nodes where three or more curve pieces meet (a non-generic view of the mesh).
  int pinch_points = 0;
  std::vector<Vec3> pinch_at;  // where they are, shadow space
  int border_ends = 0;
  int branch_points = 0;
  // The curves' image on the screen (their diagram in this view).
  int curve_objects = 0;
  int crossings = 0;
  int crossing_non_generic = 0;  // spots where the image is not a regular diagram
  int crossing_behind_eye = 0;   // curve points the camera cannot see (behind or at the eye)
  // Per curve object, the Gauss code of its diagram in this view, a line each: "Gauss code of
  // 'trefoil' in this view: 1, -2, 3, -1, 2, -3", or why it has none (part of it behind the eye,
  // an open curve, touching strands).
  std::vector<std::string> gauss_codes;
};

// "3 curve(s), total length 1.2: 2 shadow-only, 1 true (2 true point(s)); 4 pinch point(s)", the
// ends on a border and branch points when there are any, and a note when the view is not
// generic; for curves, "3 crossing(s) of the curves in this view". Only the parts the scene has.
std::string intersection_text(const IntersectionSummary& s);

struct SceneGeometry {
  std::vector<DrawObject> objects;  // one per scene object, in order (empty meshes kept)
  // Drawn over the objects when view.intersections is on: the shadow's intersection curves with
  // their beads and the curves' crossing dots, then (when there are R^4 surfaces) the
  // above-below marks, unlit.
  std::vector<DrawObject> overlays;
  IntersectionSummary intersections;
  int slice_components = -1;        // curves of the drawn slice (view.slice), -1 when not drawn
  // The strands the flat curve modes draw (view.curve_mode shadow or diagram; empty for tubes).
  CurveDiagram diagram;
  BoundingSphere bounds;            // of every drawn vertex (for flat curves, of their tubes)
  Camera camera;
  // w over all R^4 objects together, so colours compare across objects; view depth over all R^3
  // objects together. Empty (hi < lo) when the scene has no object of that dimension.
  DepthRange w_range{1, 0};
  DepthRange view_range{1, 0};
};

// Projects R^4 objects with scene.frame (shadow = first three view coordinates), keeps R^3
// objects as they are, turns curves into tubes of radius view.tube_radius (or, in the shadow and
// diagram curve modes, into flat strands as wide on the screen, with gaps for the diagram, each
// strand vertex's source its nearest curve point: see curve_diagram.hpp), fits the camera
// (aspect = width / height), and colours vertices: blue = far, red = near, by w for R^4 objects
// and by distance from the camera for R^3 ones. With depth colour off, each object gets its own
// colour or a neutral grey. With view.intersections, adds the intersection curves of the R^4
// surfaces' shadow as thin tubes with their above-below marks and pinch-point beads, and a dot on
// the over strand of each crossing of the curves' image (overlays). Throws s4d::Error on a mesh
// with out-of-range triangle indices.
SceneGeometry build_scene_geometry(const Scene& scene, double aspect);

// The colour of an object when depth colouring is off (or the map is kGrey).
Vec3f plain_colour(const SceneObject& object);

}  // namespace s4d
