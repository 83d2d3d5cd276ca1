// Ray against every triangle of the shadow (Möller–Trumbore), sorted, merged per sheet; curves
// by their strands' distance to the cursor on the screen.
#include "view/pick.hpp"

#include <algorithm>
#include <cmath>

#include "view/view_crossings.hpp"

namespace s4d {

namespace {

// The ray parameter t and barycentric (u, v) of the hit, or false.
bool ray_triangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c, double& t, double& u,
                  double& v) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-300) return false;
  const double inv = 1 / det;
  const Vec3 s = o - a;
  u = s.dot(p) * inv;
  if (u < -1e-12 || u > 1 + 1e-12) return false;
  const Vec3 q = s.cross(e1);
  v = d.dot(q) * inv;
  if (v < -1e-12 || u + v > 1 + 1e-12) return false;
  t = e2.dot(q) * inv;
  return t > 0;
}

}  // namespace

std::vector<SheetHit> pick_sheets(const Scene& scene, const Vec3& origin, const Vec3& dir_in) {
  std::vector<SheetHit> hits;
  if (!origin.allFinite() || !dir_in.allFinite() || !(dir_in.norm() > 0)) return hits;
  const Vec3 dir = dir_in.normalized();
  double scale = 0;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    std::visit([&](const auto& s) {
      using T = std::decay_t<decltype(s)>;
      if constexpr (std::is_same_v<T, Surface<T::kDim>>) {
        constexpr int D = T::kDim;
        std::vector<Vec3> p(s.vertices.size());
        std::vector<double> w(s.vertices.size(), 0.0);
        for (std::size_t i = 0; i < p.size(); ++i) {
          if constexpr (D == 4) {
            const Vec4 q = scene.frame.to_view(s.vertices[i]);
            p[i] = scene.frame.project(q);
            w[i] = q[3];
          } else {
            p[i] = s.vertices[i];
          }
          scale = std::max(scale, p[i].cwiseAbs().maxCoeff());
        }
        for (std::size_t t = 0; t < s.triangles.size(); ++t) {
          const Triangle& tri = s.triangles[t];
          if (tri[0] < 0 || tri[1] < 0 || tri[2] < 0) continue;
          const auto n = static_cast<int>(p.size());
          if (tri[0] >= n || tri[1] >= n || tri[2] >= n) continue;
          double h = 0, u = 0, v = 0;
          if (!ray_triangle(origin, dir, p[tri[0]], p[tri[1]], p[tri[2]], h, u, v)) continue;
          SheetHit hit;
          hit.object = static_cast<int>(o);
          hit.triangle = static_cast<int>(t);
          hit.point = origin + h * dir;
          hit.distance = h;
          hit.w = scene.frame.depth_at(std::array<double, 3>{1 - u - v, u, v},
                                       std::array<double, 3>{w[tri[0]], w[tri[1]], w[tri[2]]});
          // The corner nearest the hit in the shadow; of two as near, the lower index.
          hit.vertex = tri[0];
          for (int k = 1; k < 3; ++k) {
            const double dk = (p[tri[k]] - hit.point).squaredNorm(), db = (p[hit.vertex] - hit.point).squaredNorm();
            if (dk < db || (dk == db && tri[k] < hit.vertex)) hit.vertex = tri[k];
          }
          hits.push_back(hit);
        }
      }
    }, scene.objects[o].shape);
  }
  // Nearest the eye first; ties (a ray through an edge, two sheets crossing there) in a fixed order,
  // so that the same pixel gives the same list whatever order the triangles came in.
  std::sort(hits.begin(), hits.end(), [](const SheetHit& a, const SheetHit& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    if (a.object != b.object) return a.object < b.object;
    return a.triangle < b.triangle;
  });
  // Hits on a shared edge or vertex come once per triangle: the same place of the same object.
  const double eps = 1e-7 * std::max(scale, 1.0);
  std::vector<SheetHit> merged;
  for (const SheetHit& h : hits) {
    bool same = false;
    for (auto m = merged.rbegin(); m != merged.rend() && h.distance - m->distance < eps && !same; ++m)
      same = m->object == h.object && std::abs(m->w - h.w) < eps;
    if (!same) merged.push_back(h);
  }
  return merged;
}

namespace {

struct StrandCandidate {
  int segment = 0;
  double pixels = 0, t = 0;
};

// Where `p` is drawn, in window pixels; false behind the eye.
bool on_screen(const Camera& camera, const Vec3& p, const Vec2& window, Vec2& out) {
  if (!p.allFinite() || camera.view_depth(p) <= camera.near_plane) return false;
  const Vec2 n = camera.ndc(p);
  out = Vec2((n.x() + 1) * 0.5 * window.x(), (1 - n.y()) * 0.5 * window.y());
  return out.allFinite();
}

}  // namespace

std::vector<SheetHit> pick_strands(const Scene& scene, const Camera& camera, const Vec2& cursor, const Vec2& window,
                                   double pixels) {
  std::vector<SheetHit> hits;
  if (!cursor.allFinite() || !(pixels > 0)) return hits;
  const Vec3 eye = camera.eye();
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    std::vector<std::vector<double>> ws;
    const std::vector<Polyline<3>> comps = drawn_curve(scene.objects[o].shape, scene.frame, &ws);
    int first = 0;
    for (std::size_t c = 0; c < comps.size(); ++c) {
      const Polyline<3>& pl = comps[c];
      const int n = static_cast<int>(pl.points.size());
      std::vector<StrandCandidate> near;
      for (int k = 0; k < static_cast<int>(pl.segment_count()); ++k) {
        Vec2 a, b;
        if (!on_screen(camera, pl.seg_a(static_cast<std::size_t>(k)), window, a) ||
            !on_screen(camera, pl.seg_b(static_cast<std::size_t>(k)), window, b))
          continue;
        const Vec2 ab = b - a;
        const double l2 = ab.squaredNorm();
        const double t = l2 > 0 ? std::clamp((cursor - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
        const double d = (a + t * ab - cursor).norm();
        if (d < pixels) near.push_back({k, d, t});
      }
      // Runs of consecutive segments are one strand (a closed component's last run joins its first).
      std::vector<StrandCandidate> best;
      for (std::size_t i = 0; i < near.size(); ++i) {
        const bool continues = i > 0 && near[i].segment == near[i - 1].segment + 1;
        if (!continues) best.push_back(near[i]);
        else if (near[i].pixels < best.back().pixels) best.back() = near[i];
      }
      if (pl.closed && best.size() > 1 && near.front().segment == 0 &&
          near.back().segment == static_cast<int>(pl.segment_count()) - 1) {
        if (best.back().pixels < best.front().pixels) best.front() = best.back();
        best.pop_back();
      }
      for (const StrandCandidate& sc : best) {
        const std::size_t k = static_cast<std::size_t>(sc.segment);
        SheetHit h;
        h.object = static_cast<int>(o);
        h.strand = true;
        h.triangle = sc.segment;
        h.point = pl.seg_a(k) + sc.t * (pl.seg_b(k) - pl.seg_a(k));
        h.distance = (h.point - eye).norm();
        h.vertex = first + (sc.t < 0.5 ? sc.segment : (sc.segment + 1) % n);
        if (c < ws.size() && !ws[c].empty()) {
          const auto& w = ws[c];
          h.w = (1 - sc.t) * w[k] + sc.t * w[(k + 1) % static_cast<std::size_t>(n)];
        }
        hits.push_back(h);
      }
      first += n;
    }
  }
  std::sort(hits.begin(), hits.end(), [](const SheetHit& a, const SheetHit& b) { return a.distance < b.distance; });
  return hits;
}

}  // namespace s4d
