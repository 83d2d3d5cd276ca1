// Pure CPU geometry for the renderer: projection of R^4 surfaces to their 3D shadow, vertex
// normals, tubes around polylines, bounding spheres. No OpenGL here, so all of it is unit-tested.
#pragma once
#include <cstdint>
#include <vector>

#include "core/frame.hpp"
#include "core/vec.hpp"
#include "shape/surface.hpp"

namespace s4d {

// A triangle mesh ready for upload. `source[v]` names the point whose depth colours vertex v:
// the vertex itself for surfaces, the centreline point of its ring for tubes (so a tube's
// cross-section has one colour, like a strand of a knot diagram).
struct RenderMesh {
  std::vector<Vec3> positions;         // nv × 3
  std::vector<Vec3> normals;           // nv × 3, unit length
  std::vector<int> source;             // nv, index into the object's anchor points
  std::vector<std::uint32_t> indices;  // 3 nt, counter-clockwise seen from the normal side

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
};

// The 3D shadow of an R^4 surface under `frame`: positions are the first three view
// coordinates, depth[i] the fourth (w, larger = nearer the 4D viewer).
struct ProjectedSurface {
  std::vector<Vec3> positions;  // nv × 3
  std::vector<double> depth;    // nv, 4D depth w
};
ProjectedSurface project_surface(const Surface<4>& s, const Frame<4>& frame);

// Area-weighted vertex normals of a 3D triangle mesh (counter-clockwise triangles give normals
// on the side they face). A vertex with no usable area (a pinch point of a projected surface,
// an unused vertex) gets the normal of any neighbour, else +z, so every normal is unit length.
// Triangles with out-of-range indices throw s4d::Error.
std::vector<Vec3> vertex_normals(const std::vector<Vec3>& positions,
                                 const std::vector<Triangle>& triangles);

// Builds a RenderMesh from a 3D surface (positions + triangles): source[v] = v.
RenderMesh surface_mesh(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles);

struct TubeOptions {
  double radius = 0.03;  // scene units
  int sides = 12;        // vertices around the tube, >= 3
};

// A tube around a polyline in R^3. Frames are rotation-minimising (double reflection, Wang et
// al. 2008) so the tube does not twist; on a closed curve the leftover holonomy angle is spread
// evenly over the arc length so the last ring meets the first without a seam. Open curves get
// flat caps. Repeated points are skipped; a polyline with fewer than two distinct points gives an
// empty mesh. `source` indices are offset by `first_source` (the point's index in the caller's
// anchor list). Vertices: n·sides (closed) or n·sides + 2(sides+1) (open), n distinct points.
RenderMesh tube_mesh(const std::vector<Vec3>& points, bool closed, const TubeOptions& options,
                     int first_source = 0);

// A UV sphere (`rings` latitude bands, `sides` around, >= 3 each) centred at `centre`: the beads
// that mark points (pinch points of a shadow). Outward normals; source 0 everywhere.
RenderMesh sphere_mesh(const Vec3& centre, double radius, int rings = 6, int sides = 10);

// Appends `part` to `mesh` (indices and sources shifted).
void append_mesh(RenderMesh& mesh, const RenderMesh& part, int source_offset);


}  // namespace s4d
