// Builds the per-frame draw data of a scene: projection, tubes, camera fit, depth colour.
#include "render/scene_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <type_traits>

#include "proximity/shadow_intersections.hpp"

namespace s4d {

namespace {

// The geometry of one object before colouring: anchors are the points whose depth chooses the
// colour (mesh.source indexes them); w is their 4D depth for R^4 objects.
struct Built {
  RenderMesh mesh;
  std::vector<Vec3> anchors;
  std::vector<double> w;
  bool surface = true;
  int dim = 4;
};

Built build_curve(const std::vector<std::vector<Vec3>>& comps, const std::vector<bool>& closed,
                  std::vector<double> w, double radius, int dim) {
  Built b;
  b.surface = false;
  b.dim = dim;
  b.w = std::move(w);
  TubeOptions opt;
  opt.radius = radius;
  opt.sides = kTubeSides;
  for (std::size_t c = 0; c < comps.size(); ++c) {
    const int first = static_cast<int>(b.anchors.size());
    append_mesh(b.mesh, tube_mesh(comps[c], closed[c], opt, first), 0);
    b.anchors.insert(b.anchors.end(), comps[c].begin(), comps[c].end());
  }
  return b;
}

Built build_object(const Shape& shape, const Frame<4>& frame, double radius) {
  return std::visit(
      [&](const auto& s) -> Built {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Surface<4>>) {
          ProjectedSurface p = project_surface(s, frame);
          Built b;
          b.mesh = surface_mesh(p.positions, s.triangles);
          b.anchors = std::move(p.positions);
          b.w = std::move(p.depth);
          return b;
        } else if constexpr (std::is_same_v<T, Surface<3>>) {
          Built b;
          b.dim = 3;
          b.mesh = surface_mesh(s.vertices, s.triangles);
          b.anchors = s.vertices;
          return b;
        } else {
          std::vector<std::vector<Vec3>> comps;
          std::vector<bool> closed;
          std::vector<double> w;
          for (const auto& poly : s.components) {
            std::vector<Vec3> pts;
            pts.reserve(poly.points.size());
            for (const auto& q : poly.points) {
              if constexpr (T::kDim == 4) {
                const Vec4 v = frame.to_view(q);
                pts.push_back(v.template head<3>());
                w.push_back(v[3]);
              } else {
                pts.push_back(q);
              }
            }
            comps.push_back(std::move(pts));
            closed.push_back(poly.closed);
          }
          return build_curve(comps, closed, std::move(w), radius, T::kDim);
        }
      },
      shape);
}

void extend(DepthRange& r, double d) {
  if (!std::isfinite(d)) return;
  if (r.empty()) {
    r.lo = r.hi = d;
  } else {
    r.lo = std::min(r.lo, d);
    r.hi = std::max(r.hi, d);
  }
}

// One overlay for the intersection curves of every R^4 surface with itself and with each other:
// thin tubes along their strokes, in each segment's class's colour, and a bead where the sheets
// truly meet.
DrawObject intersection_overlay(const Scene& scene, double radius, IntersectionSummary& sum) {
  std::vector<const Surface<4>*> surfaces;
  for (const SceneObject& obj : scene.objects)
    if (const auto* s = std::get_if<Surface<4>>(&obj.shape)) surfaces.push_back(s);
  DrawObject d;
  d.surface = false;
  TubeOptions line;
  line.radius = radius;
  line.sides = 8;
  TubeOptions bead = line;
  bead.radius = 2.5 * radius;
  auto add = [&](const std::vector<Vec3>& pts, const TubeOptions& opt, const Vec3f& colour,
                 bool closed) {
    append_mesh(d.mesh, tube_mesh(pts, closed, opt), 0);
    d.colours.resize(d.mesh.vertex_count(), colour);
    d.depth.resize(d.mesh.vertex_count(), 0.0);
  };
  auto draw = [&](const ShadowIntersections& r) {
    sum.curves += static_cast<int>(r.curves.size());
    sum.shadow_only_curves += r.shadow_only_curves;
    sum.true_curves += r.true_curves;
    sum.coplanar_pairs += r.coplanar_pairs;
    sum.length += r.total_length;
    // One smooth tube per run of a stroke's segments of one class (a tube per segment would
    // show a cap at every joint).
    for (const ShadowStroke& k : r.strokes) {
      const int n = static_cast<int>(k.segments.size());
      for (int first = 0; first < n;) {
        const bool is_true = r.segments[k.segments[first]].true_intersection;
        int last = first;
        while (last + 1 < n && r.segments[k.segments[last + 1]].true_intersection == is_true) ++last;
        const bool loop = k.closed && first == 0 && last == n - 1;
        std::vector<Vec3> pts(k.points.begin() + first, k.points.begin() + last + 2);
        if (loop) pts.pop_back();  // tube_mesh closes it
        add(pts, line, is_true ? kTrueIntersectionColour : kShadowOnlyColour, loop);
        first = last + 1;
      }
    }
    for (const ShadowSegment& s : r.segments) {
      if (!s.true_intersection) continue;
      ++sum.true_points;
      const Vec3 along = (s.p1 - s.p0).norm() > 0 ? Vec3((s.p1 - s.p0).normalized()) : Vec3::UnitX();
      add({s.meet - bead.radius * along, s.meet + bead.radius * along}, bead, kTrueIntersectionColour,
          false);
    }
  };
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    draw(shadow_intersections(*surfaces[i], scene.frame));
    for (std::size_t j = i + 1; j < surfaces.size(); ++j)
      draw(shadow_intersections(*surfaces[i], *surfaces[j], scene.frame));
  }
  d.mesh.source.assign(d.mesh.vertex_count(), 0);
  sum.computed = true;
  return d;
}

}  // namespace

std::string intersection_text(const IntersectionSummary& s) {
  std::ostringstream o;
  o << s.curves << " curve(s), total length " << std::setprecision(4) << s.length << ": "
    << s.shadow_only_curves << " shadow-only, " << s.true_curves << " true (" << s.true_points
    << " true point(s))";
  if (s.coplanar_pairs > 0) o << "; the view is not generic (sheets overlap in area): turn it";
  return o.str();
}

Vec3f plain_colour(const SceneObject& object) {
  if (object.colour && object.colour->allFinite()) return object.colour->cwiseMax(0.f).cwiseMin(1.f);
  return map_colour(ColourMap::kGrey, 0.5);
}

SceneGeometry build_scene_geometry(const Scene& scene, double aspect) {
  SceneGeometry g;
  const ViewSettings& view = scene.view;
  const double radius =
      view.tube_radius > 0 && std::isfinite(view.tube_radius) ? view.tube_radius : 0.03;

  std::vector<Built> built;
  built.reserve(scene.objects.size());
  std::vector<Vec3> all_points;
  for (const SceneObject& obj : scene.objects) {
    built.push_back(build_object(obj.shape, scene.frame, radius));
    const auto& pos = built.back().mesh.positions;
    all_points.insert(all_points.end(), pos.begin(), pos.end());
  }
  g.bounds = bounding_sphere(all_points);
  g.camera = make_camera(g.bounds, view.trackball, view.distance, view.fov_deg, aspect, view.zoom);

  // Depth per anchor: w for R^4 objects; for R^3 ones the distance in front of the camera.
  std::vector<std::vector<double>> anchor_depth(built.size());
  for (std::size_t i = 0; i < built.size(); ++i) {
    Built& b = built[i];
    if (b.dim == 4) {
      anchor_depth[i] = b.w;
      for (double w : b.w) extend(g.w_range, w);
    } else {
      anchor_depth[i].reserve(b.anchors.size());
      for (const Vec3& p : b.anchors) {
        anchor_depth[i].push_back(g.camera.view_depth(p));
        extend(g.view_range, anchor_depth[i].back());
      }
    }
  }

  const bool depth_colour = view.depth_colour && view.colour_map != ColourMap::kGrey;
  g.objects.reserve(built.size());
  for (std::size_t i = 0; i < built.size(); ++i) {
    DrawObject d;
    d.surface = built[i].surface;
    d.dim = built[i].dim;
    d.mesh = std::move(built[i].mesh);
    const std::size_t nv = d.mesh.vertex_count();
    d.depth.resize(nv);
    d.colours.resize(nv);
    const Vec3f plain = plain_colour(scene.objects[i]);
    for (std::size_t v = 0; v < nv; ++v) {
      const double depth = anchor_depth[i][d.mesh.source[v]];
      d.depth[v] = depth;
      if (!depth_colour) {
        d.colours[v] = plain;
      } else if (d.dim == 4) {
        // Frame<4>: larger w is nearer the 4D viewer, so it maps towards red.
        d.colours[v] = map_colour(view.colour_map, normalise_depth(depth, g.w_range.lo, g.w_range.hi));
      } else {
        // View depth grows away from the eye: near (small) maps to red.
        d.colours[v] = map_colour(view.colour_map,
                                  1.0 - normalise_depth(depth, g.view_range.lo, g.view_range.hi));
      }
    }
    g.objects.push_back(std::move(d));
  }
  // Half the curves' tube radius: the curves lie on the sheets and should not hide them.
  if (view.intersections) g.overlays.push_back(intersection_overlay(scene, 0.5 * radius, g.intersections));
  return g;
}

}  // namespace s4d
