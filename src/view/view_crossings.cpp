// screen_crossings: each curve's image mapped to an orthographic shadow of the screen, cut where it
// passes behind the eye, and handed to the shadow-crossing finder.
#include "view/view_crossings.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace s4d {

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
        p.points.push_back(frame.project(v));
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

}  // namespace s4d
