// Builds the per-frame draw data of a scene: projection, tubes, camera fit, depth colour.
#include "render/scene_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <type_traits>

#include "core/error.hpp"
#include "knots/knot_diagram.hpp"
#include "proximity/shadow_crossings.hpp"
#include "proximity/shadow_intersections.hpp"
#include "view/scene_slice.hpp"

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

// A curve as a tube, or (`tube` false: the flat curve modes, whose strands need the camera) only
// its points.
Built build_curve(const std::vector<std::vector<Vec3>>& comps, const std::vector<bool>& closed,
                  std::vector<double> w, double radius, int dim, bool tube) {
  Built b;
  b.surface = false;
  b.dim = dim;
  b.w = std::move(w);
  TubeOptions opt;
  opt.radius = radius;
  opt.sides = kTubeSides;
  for (std::size_t c = 0; c < comps.size(); ++c) {
    const int first = static_cast<int>(b.anchors.size());
    if (tube) append_mesh(b.mesh, tube_mesh(comps[c], closed[c], opt, first), 0);
    b.anchors.insert(b.anchors.end(), comps[c].begin(), comps[c].end());
  }
  return b;
}

Built build_object(const Shape& shape, const Frame<4>& frame, double radius, bool tube) {
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
                pts.push_back(frame.project(v));
                w.push_back(v[3]);
              } else {
                pts.push_back(q);
              }
            }
            comps.push_back(std::move(pts));
            closed.push_back(poly.closed);
          }
          return build_curve(comps, closed, std::move(w), radius, T::kDim, tube);
        }
      },
      shape);
}

// The ball that frames `points` and tubes of `radius` around `centreline`: bounding_sphere's box
// centre and farthest point, a centreline point counting as its tube's farthest, `radius` beyond
// it. Within a few hundredths of the radius of the tube mesh's own sphere (its rings are polygons
// inside the round tube): the flat curve modes frame the view with it instead of building tubes
// they do not draw, and the picture does not visibly move when the mode changes.
BoundingSphere framing_sphere(const std::vector<Vec3>& points, const std::vector<Vec3>& centreline, double radius) {
  if (centreline.empty()) return bounding_sphere(points);
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = Vec3::Constant(-HUGE_VAL);
  for (const Vec3& p : points)
    if (p.allFinite()) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  for (const Vec3& p : centreline)
    if (p.allFinite()) {
      lo = lo.cwiseMin(p - Vec3::Constant(radius));
      hi = hi.cwiseMax(p + Vec3::Constant(radius));
    }
  BoundingSphere s;
  if (!(lo.x() <= hi.x())) return s;
  s.centre = 0.5 * (lo + hi);
  double r = 0;
  for (const Vec3& p : points)
    if (p.allFinite()) r = std::max(r, (p - s.centre).norm());
  for (const Vec3& p : centreline)
    if (p.allFinite()) r = std::max(r, (p - s.centre).norm() + radius);
  s.radius = r;
  return s;
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

// The sizes of what view.intersections draws along the shadow's curves, from the curves' tube
// radius: the marks sit beside the tube on each sheet with a clear gap, thinner than it so that
// the four of them do not merge into one band at a glance.
struct OverlaySizes {
  double line;    // the curve's tube
  double mark;    // the above-below lines' tubes
  double offset;  // from the curve to a mark's axis, within the sheet
  double bead;    // pinch points
};
OverlaySizes overlay_sizes(double line) { return {line, 0.7 * line, 3.0 * line, 3.0 * line}; }

// The corners of triangle t of `s` in the shadow.
std::array<Vec3, 3> shadow_triangle(const Surface<4>& s, int t, const Frame<4>& frame) {
  const Triangle& tri = s.triangles[static_cast<std::size_t>(t)];
  return {frame.shadow(s.vertices[tri[0]]), frame.shadow(s.vertices[tri[1]]), frame.shadow(s.vertices[tri[2]])};
}

// Barycentric coordinates of p (in, or near, the plane of x) in triangle x; the centre's when x
// has no area (a point on none of its edges).
std::array<double, 3> barycentric(const std::array<Vec3, 3>& x, const Vec3& p) {
  const Vec3 e1 = x[1] - x[0], e2 = x[2] - x[0], q = p - x[0];
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
  const double det = d11 * d22 - d12 * d12;
  if (!(det > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  const double b1 = (d22 * e1.dot(q) - d12 * e2.dot(q)) / det;
  const double b2 = (d11 * e2.dot(q) - d12 * e1.dot(q)) / det;
  return {1 - b1 - b2, b1, b2};
}

// The edges of a surface that belong to one triangle only (its border), as (low, high) vertex
// pairs, sorted for binary search.
std::vector<std::pair<int, int>> border_edges(const Surface<4>& s) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * s.triangles.size());
  for (const Triangle& t : s.triangles)
    for (int k = 0; k < 3; ++k) edges.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<int, int>> border;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) border.push_back(edges[i]);
    i = j;
  }
  return border;
}

// One pair of sheets' intersections (a surface with itself, or two surfaces) with what the marks
// and beads need of each: the two surfaces (the same one for self-intersections), lazily their
// borders.
struct SheetPair {
  const ShadowIntersections& r;
  const Surface<4>& sa;
  const Surface<4>& sb;
  const Frame<4>& frame;
  std::optional<std::vector<std::pair<int, int>>> border_a, border_b;

  // Is p, an end of a segment, on an edge of triangle t of `s` that is the surface's border?
  bool on_border(const Surface<4>& s, std::optional<std::vector<std::pair<int, int>>>& border, int t,
                 const Vec3& p) {
    const std::array<Vec3, 3> x = shadow_triangle(s, t, frame);
    const std::array<double, 3> b = barycentric(x, p);
    const Triangle& tri = s.triangles[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k) {
      if (std::abs(b[k]) > 1e-7) continue;  // p is on the edge opposite corner k
      if (!border) border = border_edges(s);
      const int u = tri[(k + 1) % 3], v = tri[(k + 2) % 3];
      if (std::binary_search(border->begin(), border->end(), std::pair{std::min(u, v), std::max(u, v)}))
        return true;
    }
    return false;
  }
  bool on_border(const ShadowSegment& seg, const Vec3& p) {
    return on_border(sa, border_a, seg.a, p) || on_border(sb, border_b, seg.b, p);
  }
};

// Everything view.intersections draws over the R^4 surfaces: the curves and beads in one
// DrawObject, the marks (unlit) in another.
class IntersectionOverlay {
 public:
  IntersectionOverlay(double line_radius, IntersectionSummary& sum)
      : size_(overlay_sizes(line_radius)), sum_(sum) {
    d_.surface = false;
    marks_.surface = false;
    marks_.lit = false;
  }

  void add(SheetPair& p) {
    sum_.add(p.r);
    curves(p.r);
    for (const ShadowStroke& k : p.r.strokes) marks(p, k);
    ends(p);
  }

  // The curves and beads, then the marks (unlit).
  std::vector<DrawObject> finish() {
    for (DrawObject* d : {&d_, &marks_}) d->mesh.source.assign(d->mesh.vertex_count(), 0);
    sum_.computed = true;
    std::vector<DrawObject> out;
    out.push_back(std::move(d_));
    out.push_back(std::move(marks_));
    return out;
  }

 private:
  static void append(DrawObject& d, const RenderMesh& m, const Vec3f& colour) {
    append_mesh(d.mesh, m, 0);
    d.colours.resize(d.mesh.vertex_count(), colour);
    d.depth.resize(d.mesh.vertex_count(), 0.0);
  }
  void append(const RenderMesh& m, const Vec3f& colour) { append(d_, m, colour); }
  void tube(const std::vector<Vec3>& pts, double radius, const Vec3f& colour, bool closed = false) {
    TubeOptions opt;
    opt.radius = radius;
    opt.sides = 8;
    append(d_, tube_mesh(pts, closed, opt), colour);
  }
  // A mark's line: unlit, so its cross-section does not show and four sides look as round as
  // eight, at half the vertices (the marks are most of what this overlay draws).
  void mark(const std::vector<Vec3>& pts, const Vec3f& colour) {
    TubeOptions opt;
    opt.radius = size_.mark;
    opt.sides = 4;
    append(marks_, tube_mesh(pts, false, opt), colour);
  }

  // The curves as thin tubes: one smooth tube per run of a stroke's segments of one class (a tube
  // per segment would show a cap at every joint), and a bead where the sheets truly meet.
  void curves(const ShadowIntersections& r) {
    for (const ShadowStroke& k : r.strokes) {
      const int n = static_cast<int>(k.segments.size());
      for (int first = 0; first < n;) {
        const bool is_true = r.segments[k.segments[first]].true_intersection;
        int last = first;
        while (last + 1 < n && r.segments[k.segments[last + 1]].true_intersection == is_true) ++last;
        const bool loop = k.closed && first == 0 && last == n - 1;
        std::vector<Vec3> pts(k.points.begin() + first, k.points.begin() + last + 2);
        if (loop) pts.pop_back();  // tube_mesh closes it
        tube(pts, size_.line, is_true ? kTrueIntersectionColour : kShadowOnlyColour, loop);
        first = last + 1;
      }
    }
    for (const ShadowSegment& s : r.segments) {
      if (!s.true_intersection) continue;
      const Vec3 along = (s.p1 - s.p0).norm() > 0 ? Vec3((s.p1 - s.p0).normalized()) : Vec3::UnitX();
      const double bead = 2.5 * size_.line;
      TubeOptions opt;
      opt.radius = bead;
      opt.sides = 8;
      append(tube_mesh({s.meet - bead * along, s.meet + bead * along}, false, opt), kTrueIntersectionColour);
    }
  }

  // The above-below marks along one stroke: on each sheet, a line on either side of the curve
  // (offset within the sheet's triangle, perpendicular to the curve), red on the sheet nearer in w
  // and blue on the farther. Both sides, because from any eye point the sheet in front hides one
  // side of the other. Where the sheets truly meet their order swaps, so the lines break there.
  void marks(SheetPair& p, const ShadowStroke& k) {
    struct Run {
      std::vector<Vec3> at;                  // points on the curve
      std::vector<Vec3> over_dir, under_dir; // unit, within each sheet, perpendicular to the curve
    } run;
    Vec3 last_over = Vec3::Zero(), last_under = Vec3::Zero();  // for a consistent side
    auto flush = [&] {
      if (run.at.size() >= 2)
        for (const double side : {1.0, -1.0}) {
          std::vector<Vec3> over(run.at.size()), under(run.at.size());
          for (std::size_t i = 0; i < run.at.size(); ++i) {
            over[i] = run.at[i] + side * size_.offset * run.over_dir[i];
            under[i] = run.at[i] + side * size_.offset * run.under_dir[i];
          }
          mark(over, kAboveColour);
          mark(under, kBelowColour);
        }
      run = Run{};
      last_over = last_under = Vec3::Zero();
    };
    // One piece of the curve, from `from` to `to`, with sheet a nearer in w or not.
    auto piece = [&](const ShadowSegment& s, const Vec3& from, const Vec3& to, bool a_over) {
      const Vec3 chord = to - from;
      if (!(chord.norm() > 1e-12 * (1 + from.norm()))) return;
      const Vec3 along = chord.normalized();
      const std::array<Vec3, 3> ta = shadow_triangle(p.sa, s.a, p.frame);
      const std::array<Vec3, 3> tb = shadow_triangle(p.sb, s.b, p.frame);
      const Vec3 na = (ta[1] - ta[0]).cross(ta[2] - ta[0]), nb = (tb[1] - tb[0]).cross(tb[2] - tb[0]);
      Vec3 over = (a_over ? na : nb).cross(along), under = (a_over ? nb : na).cross(along);
      if (!(over.norm() > 0) || !(under.norm() > 0)) return flush();  // a sheet seen edge-on
      over.normalize();
      under.normalize();
      if (over.dot(last_over) < 0) over = -over;
      if (under.dot(last_under) < 0) under = -under;
      if (run.at.empty()) {
        run.at.push_back(from);
        run.over_dir.push_back(over);
        run.under_dir.push_back(under);
      } else {  // a joint: the mean of the two pieces' directions
        run.over_dir.back() = (run.over_dir.back() + over).normalized();
        run.under_dir.back() = (run.under_dir.back() + under).normalized();
      }
      run.at.push_back(to);
      run.over_dir.push_back(over);
      run.under_dir.push_back(under);
      last_over = over;
      last_under = under;
    };
    for (std::size_t i = 0; i < k.segments.size(); ++i) {
      const ShadowSegment& s = p.r.segments[static_cast<std::size_t>(k.segments[i])];
      const Vec3& from = k.points[i];
      const Vec3& to = k.points[i + 1];
      // The stroke may walk the segment from p1 to p0.
      const bool forward = (s.p0 - from).squaredNorm() <= (s.p1 - from).squaredNorm();
      // w of sheet a less w of sheet b, at `from` and at `to`.
      const double at_from = forward ? s.depth_a0 - s.depth_b0 : s.depth_a1 - s.depth_b1;
      const double at_to = forward ? s.depth_a1 - s.depth_b1 : s.depth_a0 - s.depth_b0;
      if (!s.true_intersection) {
        piece(s, from, to, at_from + at_to > 0);
      } else {
        piece(s, from, s.meet, at_from > 0 || (at_from == 0 && at_to < 0));
        flush();
        piece(s, s.meet, to, at_to > 0 || (at_to == 0 && at_from < 0));
      }
    }
    flush();
  }

  // Where the curves end. Strokes of no length (where the curve passes exactly through a mesh
  // edge of both sheets, as on a symmetric surface, the finder returns point-like segments that
  // join the nodes around them) are left out; then a node that ends one stroke is a curve end, and
  // one that ends three or more is a branch point. A curve end on a surface's border is where a
  // sheet stops; any other is a pinch point of the shadow (the fold of a Whitney umbrella), beaded.
  void ends(SheetPair& p) {
    struct End {
      Vec3 at;
      int segment;
    };
    std::vector<End> found;
    for (const ShadowStroke& k : p.r.strokes) {
      if (k.closed) continue;
      double length = 0;
      for (std::size_t i = 0; i + 1 < k.points.size(); ++i) length += (k.points[i + 1] - k.points[i]).norm();
      if (!(length > 1e-9 * (1 + k.points.front().norm()))) continue;
      found.push_back({k.points.front(), k.segments.front()});
      found.push_back({k.points.back(), k.segments.back()});
    }
    // Strokes that meet share their end point exactly (the finder gives them the node's point).
    auto less = [](const End& x, const End& y) {
      return std::lexicographical_compare(x.at.data(), x.at.data() + 3, y.at.data(), y.at.data() + 3);
    };
    std::sort(found.begin(), found.end(), less);
    for (std::size_t i = 0; i < found.size();) {
      std::size_t j = i;
      while (j < found.size() && found[j].at == found[i].at) ++j;
      if (j - i >= 3) ++sum_.branch_points;
      if (j - i == 1) {
        const End& e = found[i];
        if (p.on_border(p.r.segments[static_cast<std::size_t>(e.segment)], e.at)) {
          ++sum_.border_ends;
        } else {
          ++sum_.pinch_points;
          sum_.pinch_at.push_back(e.at);
          append(sphere_mesh(e.at, size_.bead), kPinchPointColour);
        }
      }
      i = j;
    }
  }

  OverlaySizes size_;
  IntersectionSummary& sum_;
  DrawObject d_;      // curves, true points' and pinch points' beads
  DrawObject marks_;  // the above-below marks
};

// The overlays of the intersection curves of every R^4 surface with itself and with each other:
// the curves with their beads, and the marks.
std::vector<DrawObject> intersection_overlays(const Scene& scene, double radius, IntersectionSummary& sum) {
  std::vector<const Surface<4>*> surfaces;
  for (const SceneObject& obj : scene.objects)
    if (const auto* s = std::get_if<Surface<4>>(&obj.shape)) surfaces.push_back(s);
  sum.surfaces = static_cast<int>(surfaces.size());
  IntersectionOverlay overlay(radius, sum);
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const ShadowIntersections self = shadow_intersections(*surfaces[i], scene.frame);
    SheetPair p{self, *surfaces[i], *surfaces[i], scene.frame, {}, {}};
    overlay.add(p);
    for (std::size_t j = i + 1; j < surfaces.size(); ++j) {
      const ShadowIntersections pair = shadow_intersections(*surfaces[i], *surfaces[j], scene.frame);
      SheetPair q{pair, *surfaces[i], *surfaces[j], scene.frame, {}, {}};
      overlay.add(q);
    }
  }
  return overlay.finish();
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
// Gauss code in this view go to `sum`. `known`: the crossings of this camera when already found.
void add_crossings(const Scene& scene, const Camera& camera, double tube, DrawObject& d,
                   IntersectionSummary& sum, const ScreenCrossings* known) {
  for (const SceneObject& obj : scene.objects) sum.curve_objects += !is_surface(obj.shape);
  if (sum.curve_objects == 0) return;
  ScreenCrossings found_here;
  if (!known) found_here = screen_crossings(scene, camera);
  const ScreenCrossings& screen = known ? *known : found_here;
  const std::vector<ScreenCrossing>& found = screen.crossings;
  sum.crossings = static_cast<int>(found.size());
  sum.crossing_non_generic = screen.non_generic;
  sum.crossing_behind_eye = screen.behind_eye;
  for (const ScreenImage& im : screen.images) sum.gauss_codes.push_back(gauss_code_line(scene, im));
  TubeOptions dot;
  dot.radius = 0.7 * tube;
  dot.sides = 16;
  // The plain shadow (Fig. 1a) shows no crossing as over or under: the crossings are counted and
  // coded, not marked.
  const bool marks = scene.view.curve_mode != CurveMode::kShadow;
  for (const ScreenCrossing& c : found) {
    if (!marks) break;
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

std::string intersection_text(const IntersectionSummary& s) {
  std::ostringstream o;
  if (s.surfaces > 0 || s.curve_objects == 0) {
    // The ends go between the counts and counts_text's note on a non-generic view (its wording
    // kept), which ends the sentence.
    const std::string full = counts_text(s);
    ShadowCurveCounts plain = s;
    plain.coplanar_pairs = 0;
    const std::string counts = counts_text(plain);
    o << counts << "; " << s.pinch_points << " pinch point(s)";
    if (s.border_ends > 0) o << ", " << s.border_ends << " curve end(s) at a border";
    if (s.branch_points > 0) o << ", " << s.branch_points << " branch point(s)";
    o << full.substr(counts.size());
  }
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
  const bool tubes = view.curve_mode == CurveMode::kTubes;
  std::vector<Vec3> all_points, centrelines;  // centrelines: of the curves not drawn as tubes
  for (const SceneObject& obj : scene.objects) {
    built.push_back(build_object(obj.shape, scene.frame, radius, tubes));
    const auto& pos = built.back().mesh.positions;
    all_points.insert(all_points.end(), pos.begin(), pos.end());
    if (!tubes && !built.back().surface)
      centrelines.insert(centrelines.end(), built.back().anchors.begin(), built.back().anchors.end());
  }
  g.bounds = framing_sphere(all_points, centrelines, radius);
  const BoundingSphere framed = view.fit_radius > 0 ? BoundingSphere{view.fit_centre, view.fit_radius} : g.bounds;
  g.camera = make_camera(framed, view.trackball, view.distance, view.fov_deg, aspect, view.zoom);

  // The flat curve modes draw each curve's strands where the tube would be, recomputed from the
  // camera every frame.
  if (!tubes) {
    const double half_width = strand_half_width(g.camera, radius);
    g.diagram = curve_diagram(scene, g.camera, half_width, view.curve_mode == CurveMode::kDiagram);
    for (const DiagramStrand& s : g.diagram.strands)
      append_mesh(built[static_cast<std::size_t>(s.object)].mesh,
                  strand_strip_mesh(s, half_width, g.camera.aspect, g.camera), 0);
  }

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
    d.screen = !d.surface && view.curve_mode != CurveMode::kTubes;
    d.lit = !d.screen;
    d.mesh = std::move(built[i].mesh);
    const std::size_t nv = d.mesh.vertex_count();
    d.depth.resize(nv);
    d.colours.resize(nv);
    const Vec3f plain = plain_colour(scene.objects[i]);
    // The plain shadow of Fig. 1a: a curve's strands in one colour, no cue of depth at all.
    const bool plain_shadow = d.screen && view.curve_mode == CurveMode::kShadow;
    for (std::size_t v = 0; v < nv; ++v) {
      const double depth = anchor_depth[i][d.mesh.source[v]];
      d.depth[v] = depth;
      if (!depth_colour || plain_shadow) {
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
  if (view.slice && std::isfinite(view.slice_level) && has_4d_surfaces(scene)) {
    // Thicker than the curves' tubes: the slice is what the picture is about while it shows.
    const SceneSlice slice = scene_slice(scene, view.slice_level);
    DrawObject d;
    d.surface = false;
    TubeOptions opt;
    opt.radius = 1.25 * radius;
    opt.sides = kTubeSides;
    for (const Polyline<3>& line : slice.curve.components) {
      append_mesh(d.mesh, tube_mesh(line.points, line.closed, opt), 0);
      d.colours.resize(d.mesh.vertex_count(), kSliceColour);
      d.depth.resize(d.mesh.vertex_count(), view.slice_level);
    }
    g.slice_components = static_cast<int>(slice.curve.components.size());
    if (d.mesh.vertex_count() > 0) g.overlays.push_back(std::move(d));
  }
  if (view.intersections) {
    // Half the curves' tube radius: the curves lie on the sheets and should not hide them.
    g.overlays = intersection_overlays(scene, 0.5 * radius, g.intersections);
    add_crossings(scene, g.camera, radius, g.overlays.front(), g.intersections,
                  view.curve_mode != CurveMode::kTubes ? &g.diagram.screen : nullptr);
    if (g.intersections.surfaces == 0) g.overlays.pop_back();  // no marks without surfaces
  }
  return g;
}

double drawn_opacity(const ViewSettings& view) {
  const double opacity = std::isfinite(view.opacity) ? std::clamp(view.opacity, 0.05, 1.0) : 1.0;
  return view.slice && view.slice_fade ? std::min(opacity, kSliceFadeOpacity) : opacity;
}

}  // namespace s4d
