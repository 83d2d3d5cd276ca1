// The crossing diagram of a view as a picture for papers and slides: SVG (a browser shows it) and
// TikZ (\draw commands for LaTeX). Headless: only the CPU geometry, no OpenGL.
#pragma once
#include <string>

#include "io/scene.hpp"
#include "render/curve_diagram.hpp"

namespace s4d {

// The crossing diagram of the scene's view as a width × height picture of it shows it: the camera
// build_scene_geometry fits at that aspect (the one render uses), the strands with their gaps.
// Throws s4d::Error unless both sizes are positive.
CurveDiagram view_diagram(const Scene& scene, int width, int height);

// The diagram as an SVG document of width × height pixels: one <path> per strand (a closed
// component without gaps ends in Z), in pixel coordinates of the view (x right, y down), as wide
// as drawn, with butt ends at the gaps, one colour per component (in the order of the objects and
// their components) on white. `scene` names the objects.
std::string diagram_svg(const CurveDiagram& diagram, const Scene& scene, int width, int height);

// The diagram as a tikzpicture: one \draw per strand, coordinates in the pixels of the view with
// y up (x = pixel, y = height - pixel), scaled by the picture's x and y units so that it is
// `width_cm` wide; the same colours as diagram_svg, defined with \definecolor.
std::string diagram_tikz(const CurveDiagram& diagram, const Scene& scene, int width, int height,
                         double width_cm = 10);

// Writes the diagram of the view to `path`: TikZ for .tex, SVG otherwise (".svg" is appended to a
// path with neither); returns the path written. Throws s4d::Error when the scene has no curves.
std::string export_diagram(const Scene& scene, const std::string& path, int width, int height);

// True when the scene has a curve object (the curve display modes and the diagram apply).
bool has_curves(const Scene& scene);

// The colour of component `index` (counted over all curve objects, in order) in the pictures.
Vec3f diagram_colour(int index);

}  // namespace s4d
