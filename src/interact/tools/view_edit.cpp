#include "interact/tools/view_edit.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "interact/session/session.hpp"

namespace s4d {

namespace {

// A curve object's points where they are drawn (shadow space), and the way back to its own space.
struct Drawn {
  std::vector<Polyline<3>> components;
  std::vector<std::vector<double>> w;  // curves of R^4: each point's view w, kept by an edit
  bool four = false;
};

Drawn drawn_of(const Scene& scene, const SceneObject& obj) {
  if (is_surface(obj.shape)) throw Error("'" + obj.name + "' is a surface: only curves have crossings to change");
  Drawn d;
  d.four = std::holds_alternative<Curve<4>>(obj.shape);
  d.components = drawn_curve(obj.shape, scene.frame, &d.w);
  return d;
}

Shape to_shape(const Scene& scene, const Drawn& d) {
  if (d.four) {
    Curve<4> c;
    for (std::size_t i = 0; i < d.components.size(); ++i) {
      Polyline<4> p{{}, d.components[i].closed};
      for (std::size_t k = 0; k < d.components[i].points.size(); ++k) {
        const Vec3& s = d.components[i].points[k];
        p.points.push_back(scene.frame.to_world(scene.frame.lift(s, d.w[i][k])));
      }
      c.components.push_back(std::move(p));
    }
    return c;
  }
  Curve<3> c;
  c.components = d.components;
  return c;
}

// The object's crossings on the screen (normalised device coordinates) with their over strands.
struct Seen {
  Vec2 at;
  SegmentRef over;
};
std::vector<Seen> seen_crossings(const Scene& scene, const Camera& camera, int object) {
  std::vector<Seen> out;
  for (const ScreenCrossing& c : screen_crossings(scene, camera).crossings)
    if (c.object == object) out.push_back({camera.ndc(c.over), c.over_at});
  return out;
}

}  // namespace

Shape change_crossing_in_view(const Scene& scene, const Camera& camera, const ScreenCrossing& c,
                              double clearance) {
  if (c.object < 0 || c.object >= static_cast<int>(scene.objects.size()))
    throw Error("no such object for this crossing");
  const SceneObject& obj = scene.objects[c.object];
  if (c.under_at.component < 0)
    throw Error("part of '" + obj.name + "' is behind the eye: step back to change its crossings");
  const Drawn drawn = drawn_of(scene, obj);
  const std::vector<Seen> before = seen_crossings(scene, camera, c.object);
  const Vec2 target = camera.ndc(c.over);
  const Vec3 eye = camera.eye();
  const Vec3 toward = (eye - c.under).normalized();
  const double needed = (c.over - c.under).dot(toward) + clearance;
  const auto& strand = drawn.components.at(c.under_at.component);
  const int n = static_cast<int>(strand.points.size()), k = c.under_at.segment;

  for (const int reach : {6, 3, 1, 0}) {
    for (const double scale : {1.0, 2.0, 4.0, 8.0}) {
      Drawn moved = drawn;
      auto& pts = moved.components[c.under_at.component].points;
      for (int d = -reach; d <= reach + 1; ++d) {
        int j = k + d;
        if (strand.closed) j = ((j % n) + n) % n;
        else if (j < 0 || j >= n) continue;
        const int from_segment = d <= 0 ? -d : d - 1;  // 0 for the segment's own ends
        const double weight = std::pow(std::cos(0.5 * std::numbers::pi * from_segment / (reach + 1)), 2);
        const Vec3 to_eye = eye - pts[j];
        // Along its own line of sight, never past the near side of the eye.
        const double lift = std::min(weight * scale * needed, 0.9 * to_eye.norm());
        pts[j] += lift * to_eye.normalized();
      }
      Scene edited = scene;
      edited.objects[c.object].shape = to_shape(scene, moved);
      const std::vector<Seen> after = seen_crossings(edited, camera, c.object);
      if (after.size() != before.size()) break;  // a wider bump changed the diagram: narrower
      bool flipped = false, others_kept = true;
      for (const Seen& b : before) {
        const Seen* match = nullptr;
        for (const Seen& a : after)
          if ((a.at - b.at).norm() < 1e-7) match = &a;
        if (!match) {
          others_kept = false;
          break;
        }
        if ((b.at - target).norm() < 1e-7) flipped = match->over == c.under_at;
        else others_kept = others_kept && match->over == b.over;
      }
      if (!others_kept) break;
      if (flipped) return edited.objects[c.object].shape;
    }
  }
  throw Error("changing this crossing from this view would change others: turn the view a little");
}

std::optional<ScreenCrossing> crossing_under(const ToolView& view, const Scene& scene) {
  const Camera& camera = view.camera;
  std::optional<ScreenCrossing> best;
  double best_px = 14;  // pixels: about a dot's size
  const ScreenCrossings found = screen_crossings(scene, camera);
  for (const ScreenCrossing& c : found.crossings) {
    const Vec2 at = camera.ndc(c.over);
    const Vec2 px((at.x() + 1) / 2 * view.window.x(), (1 - at.y()) / 2 * view.window.y());
    if ((px - view.cursor).norm() < best_px) {
      best_px = (px - view.cursor).norm();
      best = c;
    }
  }
  return best;
}

bool change_crossing_under(const ToolView& view, Session& session, std::string& message) {
  Scene& scene = session.scene();
  const Camera& camera = view.camera;
  const std::optional<ScreenCrossing> best = crossing_under(view, scene);
  if (!best) return false;
  try {
    Shape changed = change_crossing_in_view(scene, camera, *best, 2.5 * scene.view.tube_radius);
    session.record("change a crossing");
    SceneObject& obj = scene.objects[static_cast<std::size_t>(best->object)];
    obj.shape = std::move(changed);
    obj.generator.reset();  // edited geometry: saved as a file beside the scene
    obj.source_path.clear();
    if (session.first_vertex(best->object) >= 0) session.shapes_edited();  // a simulated knot takes it
    message = "changed a crossing of '" + obj.name + "'";
  } catch (const std::exception& e) {
    message = std::string("cannot change that crossing: ") + e.what();
  }
  return true;
}

}  // namespace s4d
