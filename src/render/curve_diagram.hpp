// The flat drawings of curves (the paper's Fig. 1a and 1b): each curve object's image as the camera
// sees it, perspective included, cut into strands with a gap in the under strand at every crossing
// of the view for the 2½D crossing diagram, or whole for the plain shadow. Pure CPU, in screen
// coordinates: the renderer draws it as flat strips, diagram_export writes it as SVG and TikZ.
#pragma once
#include <vector>

#include "core/camera.hpp"
#include "view/view_crossings.hpp"
#include "io/scene.hpp"
#include "render/geometry.hpp"

namespace s4d {

// Screen coordinates: x right, y up, the centre of the view at 0 and its top and bottom edges at
// y = ±1 (its sides at x = ±aspect). Normalised device coordinates with the aspect taken out, so
// that lengths and angles are as they look.
struct DiagramStrand {
  int object = 0;        // index in scene.objects
  int run = 0;           // the component of the object's image it lies on (ScreenImage::image)
  bool closed = false;   // a whole closed component with no gap on it
  std::vector<Vec2> points;   // screen coordinates, in the order of the curve
  std::vector<double> depth;  // per point, 1/w, w its distance in front of the eye (larger: nearer)
  // Per point, the nearest of the object's drawn points (components in order, as drawn_curve
  // gives them): the point whose depth colours it.
  std::vector<int> anchor;
};

// Where the under strand is cut at a crossing.
struct DiagramGap {
  int object = 0;
  int crossing = 0;   // index in CurveDiagram::screen.crossings
  int run = 0;        // the run of the under strand
  Vec2 at = Vec2::Zero();                     // where the strands cross, screen coordinates
  Vec2 under_direction = Vec2::UnitX();       // unit, on the screen, along the curve
  Vec2 over_direction = Vec2::UnitY();
  double half_length = 0;  // the gap reaches this far either side of `at` along the under strand
};

struct CurveDiagram {
  double aspect = 1;      // width / height of the view
  double half_width = 0;  // of every strand, screen units
  std::vector<DiagramStrand> strands;
  std::vector<DiagramGap> gaps;  // one per crossing for the diagram, none for the plain shadow
  ScreenCrossings screen;        // the view's crossings and images, as screen_crossings found them
  // Gaps that overlap another (crossings closer than a gap's length along a strand): drawn as one
  // longer gap, which may then hide an over-pass lying between them.
  int merged_gaps = 0;
};

// A strand's half-width in screen units: `tube_radius` as it looks at the centre of the view
// (the camera's target), so that a flat curve is as thick as its tube.
double strand_half_width(const Camera& camera, double tube_radius);

// Screen coordinates of a point of shadow space (in front of the eye).
Vec2 screen_point(const Camera& camera, const Vec3& p);

// The pixel of a width × height image of the view at screen point s: x right from the left edge,
// y down from the top, pixel (i, j) covering [i, i+1] × [j, j+1].
Vec2 screen_to_pixels(const Vec2& s, double aspect, int width, int height);

// The curves of `scene` as `camera` sees them, as strands of half-width `half_width`: with
// `gaps`, the crossing diagram (each crossing's under strand cut either side of the over strand,
// with a clearance as wide as the strand); without, the plain shadow (whole components).
CurveDiagram curve_diagram(const Scene& scene, const Camera& camera, double half_width, bool gaps);

// A flat strip of constant screen width along one strand, for drawing without the camera: its
// positions are normalised device coordinates (x, y, and z the depth the curve has there, so that
// it is hidden by what is in front of it), normals +z, source the strand's anchors.
RenderMesh strand_strip_mesh(const DiagramStrand& strand, double half_width, double aspect,
                             const Camera& camera);

}  // namespace s4d
