// Ray against every triangle of the shadow (Möller–Trumbore), sorted, merged per sheet.
#include "interact/pick.hpp"

#include <algorithm>
#include <cmath>

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
            p[i] = q.head<3>();
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
          const double b[3] = {1 - u - v, u, v};
          hit.w = b[0] * w[tri[0]] + b[1] * w[tri[1]] + b[2] * w[tri[2]];
          const int k = static_cast<int>(std::max_element(b, b + 3) - b);
          hit.vertex = tri[k];
          hits.push_back(hit);
        }
      }
    }, scene.objects[o].shape);
  }
  std::sort(hits.begin(), hits.end(), [](const SheetHit& a, const SheetHit& b) { return a.distance < b.distance; });
  // Hits on a shared edge or vertex come once per triangle: the same place of the same object.
  const double eps = 1e-7 * std::max(scale, 1.0);
  std::vector<SheetHit> merged;
  for (const SheetHit& h : hits) {
    const bool same = !merged.empty() && merged.back().object == h.object &&
                      std::abs(merged.back().distance - h.distance) < eps && std::abs(merged.back().w - h.w) < eps;
    if (!same) merged.push_back(h);
  }
  return merged;
}

}  // namespace s4d
