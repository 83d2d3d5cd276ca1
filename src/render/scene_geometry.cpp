// Builds the per-frame draw data of a scene: projection, tubes, camera fit, depth colour.
#include "render/scene_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

#include "core/error.hpp"
#include "knots/knot_diagram.hpp"
#include "proximity/shadow_crossings.hpp"
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
    sum.add(r);
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
      const Vec3 along = (s.p1 - s.p0).norm() > 0 ? Vec3((s.p1 - s.p0).normalized()) : Vec3::UnitX();
      add({s.meet - bead.radius * along, s.meet + bead.radius * along}, bead, kTrueIntersectionColour,
          false);
    }
  };
  sum.surfaces = static_cast<int>(surfaces.size());
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    draw(shadow_intersections(*surfaces[i], scene.frame));
    for (std::size_t j = i + 1; j < surfaces.size(); ++j)
      draw(shadow_intersections(*surfaces[i], *surfaces[j], scene.frame));
  }
  d.mesh.source.assign(d.mesh.vertex_count(), 0);
  sum.computed = true;
  return d;
}

// The line of IntersectionSummary::gauss_codes for one curve's image: the knot engine's diagram
// of it, seen as the shadow it is.
std::string gauss_code_line(const Scene& scene, const ScreenImage& im) {
  std::string line = "Gauss code of '" + scene.objects[im.object].name + "' in this view: ";
  if (!im.whole) return line + "none (part of it is behind the eye)";
  try {
    const KnotDiagram diagram = diagram_from_curve(im.image, Frame<3>());
    return line + (diagram.crossing_count() > 0 ? diagram.gauss_code() : "no crossings");
  } catch (const Error& e) {
    return line + "none (" + e.what() + ")";
  }
}

// For each crossing of the curves' image, a dot on the near side of the over strand's tube
// (radius `tube`), facing the eye, added to `d` (the overlay); the crossings and each curve's
// Gauss code in this view go to `sum`.
void add_crossings(const Scene& scene, const Camera& camera, double tube, DrawObject& d,
                        IntersectionSummary& sum) {
  for (const SceneObject& obj : scene.objects) sum.curve_objects += !is_surface(obj.shape);
  if (sum.curve_objects == 0) return;
  const ScreenCrossings screen = screen_crossings(scene, camera);
  const std::vector<ScreenCrossing>& found = screen.crossings;
  sum.crossings = static_cast<int>(found.size());
  sum.crossing_non_generic = screen.non_generic;
  sum.crossing_behind_eye = screen.behind_eye;
  for (const ScreenImage& im : screen.images) sum.gauss_codes.push_back(gauss_code_line(scene, im));
  TubeOptions dot;
  dot.radius = 0.7 * tube;
  dot.sides = 16;
  for (const ScreenCrossing& c : found) {
    // A short tube along the line of sight reads as a round dot whatever the strand's direction.
    const Vec3 toward = camera.eye() - c.over;
    const Vec3 along = toward.norm() > 0 ? Vec3(toward.normalized()) : Vec3::UnitZ();
    // The dot must clear both tubes wherever it covers them. Along the line of sight, a tube whose
    // axis is inclined by θ to the screen rises r / cos θ + ρ tan θ in front of its axis point
    // within ρ of it on the screen (ρ the dot's radius); a dot at the over tube's plain radius
    // showed as a crescent on an inclined strand, or under a close under strand. θ is capped at
    // 74°: a strand seen almost end on would put the dot far out.
    auto rise = [&](const Vec3& direction) {
      const double sin_t = std::min(std::abs(direction.dot(along)), 0.96);
      const double cos_t = std::sqrt(1 - sin_t * sin_t);
      return (tube + dot.radius * sin_t) / cos_t;
    };
    const double under_rise = rise(c.under_direction) - (c.over - c.under).dot(along);
    const double clear = std::max(rise(c.over_direction), under_rise) + 0.1 * tube;
    // Shrunk as much as it came nearer the eye, so that every dot looks the same size.
    TubeOptions near = dot;
    const double eye_distance = toward.norm();
    if (eye_distance > 2 * clear) near.radius *= (eye_distance - clear) / eye_distance;
    const Vec3 front = c.over + clear * along;
    append_mesh(d.mesh, tube_mesh({front, front + 0.2 * tube * along}, false, near), 0);
  }
  d.colours.resize(d.mesh.vertex_count(), kCrossingColour);
  d.depth.resize(d.mesh.vertex_count(), 0.0);
  d.mesh.source.assign(d.mesh.vertex_count(), 0);
}

}  // namespace

std::vector<Polyline<3>> drawn_curve(const Shape& shape, const Frame<4>& frame,
                                     std::vector<std::vector<double>>* w) {
  if (const auto* c3 = std::get_if<Curve<3>>(&shape)) return c3->components;
  std::vector<Polyline<3>> drawn;
  if (const auto* c4 = std::get_if<Curve<4>>(&shape))
    for (const auto& poly : c4->components) {
      Polyline<3> p{{}, poly.closed};
      if (w) w->emplace_back();
      for (const Vec4& q : poly.points) {
        const Vec4 v = frame.to_view(q);
        p.points.push_back(v.head<3>());
        if (w) w->back().push_back(v[3]);
      }
      drawn.push_back(std::move(p));
    }
  return drawn;
}

ScreenCrossings screen_crossings(const Scene& scene, const Camera& camera) {
  // The perspective image of a segment is a segment: under the projective map
  // (x, y, z) -> (x, y, 1) / w, w the distance in front of the eye, the camera's image becomes an
  // orthographic shadow with depth 1/w (larger = nearer), as shadow_crossings<3> wants it. Only
  // points in front of the near plane have an image: each curve is cut into the runs of those.
  const Mat4 view = camera.view();
  ScreenCrossings out;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (is_surface(scene.objects[i].shape)) continue;
    const std::vector<Polyline<3>> drawn = drawn_curve(scene.objects[i].shape, scene.frame);
    Curve<3> image, seen;  // the image's runs, and the same runs where they are drawn
    bool visible_all = true;
    for (const Polyline<3>& poly : drawn) {
      const std::size_t n = poly.points.size();
      std::vector<Vec3> eye(n);
      std::vector<bool> visible(n);
      std::size_t hidden = 0;
      for (std::size_t k = 0; k < n; ++k) {
        eye[k] = (view * poly.points[k].homogeneous()).head<3>();
        visible[k] = -eye[k].z() >= camera.near_plane && eye[k].allFinite();
        hidden += !visible[k];
      }
      auto image_of = [](const Vec3& e) { return Vec3(-e.x() / e.z(), -e.y() / e.z(), -1 / e.z()); };
      out.behind_eye += static_cast<int>(hidden);
      visible_all = visible_all && hidden == 0;
      if (hidden == 0) {
        Polyline<3> img{{}, poly.closed};
        for (const Vec3& e : eye) img.points.push_back(image_of(e));
        image.components.push_back(std::move(img));
        seen.components.push_back(poly);
        continue;
      }
      // Open runs of what the camera sees: a segment that crosses the near plane is cut there
      // (w is affine along it). A closed curve is walked from a hidden point, so that a run passing
      // its last point stays whole.
      Polyline<3> run_img{{}, false}, run_seen{{}, false};
      auto flush = [&] {
        if (run_img.points.size() >= 2) {
          image.components.push_back(std::move(run_img));
          seen.components.push_back(std::move(run_seen));
        }
        run_img = Polyline<3>{{}, false};
        run_seen = Polyline<3>{{}, false};
      };
      auto add_cut = [&](std::size_t in, std::size_t out_k) {  // in visible, out_k hidden
        const double w_in = -eye[in].z(), w_out = -eye[out_k].z();
        if (!std::isfinite(w_out) || !eye[out_k].allFinite()) return;
        const double t = (w_in - camera.near_plane) / (w_in - w_out);
        run_img.points.push_back(image_of(eye[in] + t * (eye[out_k] - eye[in])));
        run_seen.points.push_back(poly.points[in] + t * (poly.points[out_k] - poly.points[in]));
      };
      std::size_t first = 0;
      if (poly.closed)
        while (visible[first]) ++first;
      // A closed curve comes back to its first (hidden) point, to cut the segment leading to it.
      const std::size_t steps = poly.closed ? n + 1 : n;
      for (std::size_t j = 0; j < steps; ++j) {
        const std::size_t k = poly.closed ? (first + j) % n : j;
        const bool has_prev = j > 0;
        const std::size_t prev = poly.closed ? (first + j + n - 1) % n : j - 1;
        if (visible[k]) {
          if (has_prev && !visible[prev]) add_cut(k, prev);
          run_img.points.push_back(image_of(eye[k]));
          run_seen.points.push_back(poly.points[k]);
        } else if (has_prev && visible[prev]) {
          add_cut(prev, k);
          flush();
        }
      }
      flush();
    }
    const ShadowCrossingResult<3> r = shadow_crossings<3>(image, Frame<3>());
    out.images.push_back({static_cast<int>(i), image, visible_all});
    out.non_generic += r.non_generic;
    // The point of the drawn segment at image parameter t: perspective-correct, through 1/w.
    // Also the segment's unit direction.
    auto on_strand = [&](const SegmentRef& s, double t, Vec3& direction) {
      const auto& poly = seen.components[s.component];
      const auto& img = image.components[s.component];
      const std::size_t k = static_cast<std::size_t>(s.segment), next = (k + 1) % poly.points.size();
      const double inv0 = img.points[k].z(), inv1 = img.points[next].z();
      const double u = t * inv1 / ((1 - t) * inv0 + t * inv1);
      const Vec3 along = poly.points[next] - poly.points[k];
      if (along.norm() > 0) direction = along.normalized();
      return Vec3(poly.points[k] + u * along);
    };
    for (const ShadowCrossing<3>& c : r.crossings) {
      ScreenCrossing s;
      s.object = static_cast<int>(i);
      Vec3 da = Vec3::UnitX(), db = Vec3::UnitX();
      const Vec3 pa = on_strand(c.a, c.ta, da), pb = on_strand(c.b, c.tb, db);
      const bool a_over = c.a_over();
      s.over = a_over ? pa : pb;
      s.under = a_over ? pb : pa;
      s.over_direction = a_over ? da : db;
      s.under_direction = a_over ? db : da;
      if (visible_all) {  // the runs are the curve's own components
        s.over_at = a_over ? c.a : c.b;
        s.under_at = a_over ? c.b : c.a;
      }
      out.crossings.push_back(s);
    }
  }
  return out;
}

std::string intersection_text(const IntersectionSummary& s) {
  std::ostringstream o;
  if (s.surfaces > 0 || s.curve_objects == 0) o << counts_text(s);
  if (s.curve_objects > 0) {
    if (s.surfaces > 0) o << "; ";
    o << s.crossings << " crossing(s) of the curves in this view";
    if (s.crossing_non_generic > 0) o << " (not a regular diagram here: turn it)";
    if (s.crossing_behind_eye > 0) o << " (part of a curve is behind the eye and not counted)";
  }
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
  const BoundingSphere framed = view.fit_radius > 0 ? BoundingSphere{view.fit_centre, view.fit_radius} : g.bounds;
  g.camera = make_camera(framed, view.trackball, view.distance, view.fov_deg, aspect, view.zoom);

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
  if (view.intersections) {
    // Half the curves' tube radius: the curves lie on the sheets and should not hide them.
    g.overlays.push_back(intersection_overlay(scene, 0.5 * radius, g.intersections));
    add_crossings(scene, g.camera, radius, g.overlays.back(), g.intersections);
  }
  return g;
}

}  // namespace s4d
