// Projection, normals, tubes and bounding spheres for the renderer (see geometry.hpp).
#include "render/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"

namespace s4d {

ProjectedSurface project_surface(const Surface<4>& s, const Frame<4>& frame) {
  ProjectedSurface out;
  out.positions.reserve(s.vertices.size());
  out.depth.reserve(s.vertices.size());
  for (const Vec4& p : s.vertices) {
    const Vec4 q = frame.to_view(p);
    out.positions.push_back(frame.project(q));
    out.depth.push_back(q[3]);
  }
  return out;
}

std::vector<Vec3> vertex_normals(const std::vector<Vec3>& positions,
                                 const std::vector<Triangle>& triangles) {
  const int nv = static_cast<int>(positions.size());
  std::vector<Vec3> acc(positions.size(), Vec3::Zero());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (int i : tri)
      if (i < 0 || i >= nv)
        throw Error("triangle " + std::to_string(t) + " uses vertex " + std::to_string(i) +
                    " but the mesh has " + std::to_string(nv) + " vertices");
    // The cross product's length is twice the area: summing it weights normals by area, so
    // slivers from a fine grid near a pole do not dominate.
    const Vec3 n = (positions[tri[1]] - positions[tri[0]]).cross(positions[tri[2]] - positions[tri[0]]);
    if (!n.allFinite()) continue;
    for (int i : tri) acc[i] += n;
  }
  std::vector<Vec3> normals(positions.size());
  std::vector<bool> ok(positions.size(), false);
  for (std::size_t v = 0; v < acc.size(); ++v) {
    const double len = acc[v].norm();
    ok[v] = len > 1e-300 && std::isfinite(len);
    normals[v] = ok[v] ? Vec3(acc[v] / len) : Vec3::UnitZ();
  }
  // Pinch points of a projected surface have cancelling normals: borrow a neighbour's so the
  // lighting stays continuous there instead of flashing to +z.
  for (const Triangle& tri : triangles)
    for (int k = 0; k < 3; ++k)
      if (!ok[tri[k]])
        for (int m = 1; m < 3; ++m)
          if (ok[tri[(k + m) % 3]]) {
            normals[tri[k]] = normals[tri[(k + m) % 3]];
            break;
          }
  return normals;
}

RenderMesh surface_mesh(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles) {
  RenderMesh m;
  m.normals = vertex_normals(positions, triangles);  // validates indices
  m.positions = positions;
  m.source.resize(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) m.source[i] = static_cast<int>(i);
  m.indices.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
    for (int i : t) m.indices.push_back(static_cast<std::uint32_t>(i));
  return m;
}

namespace {

// Any unit vector perpendicular to unit vector t.
Vec3 any_perpendicular(const Vec3& t) {
  const Vec3 a = std::abs(t.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (a - a.dot(t) * t).normalized();
}

// Rotates v about unit axis t by angle (Rodrigues; v is perpendicular to t here).
Vec3 rotate_about(const Vec3& v, const Vec3& t, double angle) {
  return std::cos(angle) * v + std::sin(angle) * t.cross(v) + (1 - std::cos(angle)) * t.dot(v) * t;
}

}  // namespace

RenderMesh tube_mesh(const std::vector<Vec3>& input, bool closed, const TubeOptions& options,
                     int first_source) {
  if (options.sides < 3) throw Error("a tube needs at least 3 sides, got " + std::to_string(options.sides));
  if (!(options.radius > 0) || !std::isfinite(options.radius))
    throw Error("tube radius must be positive and finite, got " + std::to_string(options.radius));
  RenderMesh mesh;
  // Distinct points only (a zero-length segment has no direction), remembering their indices.
  std::vector<Vec3> x;
  std::vector<int> src;
  const double eps = 1e-12;
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (!input[i].allFinite()) throw Error("curve point " + std::to_string(i) + " is not finite");
    if (!x.empty() && (input[i] - x.back()).norm() <= eps) continue;
    x.push_back(input[i]);
    src.push_back(first_source + static_cast<int>(i));
  }
  if (closed && x.size() > 2 && (x.back() - x.front()).norm() <= eps) {
    x.pop_back();
    src.pop_back();
  }
  const int n = static_cast<int>(x.size());
  if (n < 2) return mesh;
  if (n == 2) closed = false;  // two points make a segment, not a loop

  auto next = [&](int i) { return closed ? (i + 1) % n : std::min(i + 1, n - 1); };
  auto prev = [&](int i) { return closed ? (i + n - 1) % n : std::max(i - 1, 0); };

  // Tangents: the mean of the adjacent segment directions (a segment's own direction where the
  // curve doubles back on itself and the mean vanishes).
  std::vector<Vec3> t(n);
  for (int i = 0; i < n; ++i) {
    const Vec3 a = (x[i] - x[prev(i)]).normalized();
    const Vec3 b = (x[next(i)] - x[i]).normalized();
    const bool has_a = prev(i) != i, has_b = next(i) != i;
    Vec3 m = (has_a ? a : Vec3::Zero()) + (has_b ? b : Vec3::Zero());
    if (m.norm() < 1e-9) m = has_b ? b : a;
    t[i] = m.normalized();
  }

  // Rotation-minimising frames by double reflection.
  std::vector<Vec3> r(n);
  r[0] = any_perpendicular(t[0]);
  auto propagate = [&](const Vec3& ri, const Vec3& ti, const Vec3& xi, const Vec3& xj,
                       const Vec3& tj) {
    const Vec3 v1 = xj - xi;
    const double c1 = v1.squaredNorm();
    const Vec3 rl = ri - (2 / c1) * v1.dot(ri) * v1;
    const Vec3 tl = ti - (2 / c1) * v1.dot(ti) * v1;
    const Vec3 v2 = tj - tl;
    const double c2 = v2.squaredNorm();
    Vec3 rj = c2 > 1e-20 ? Vec3(rl - (2 / c2) * v2.dot(rl) * v2) : rl;
    rj -= rj.dot(tj) * tj;  // keep it exactly perpendicular against round-off
    const double len = rj.norm();
    return len > 1e-12 ? Vec3(rj / len) : any_perpendicular(tj);
  };
  for (int i = 0; i + 1 < n; ++i) r[i + 1] = propagate(r[i], t[i], x[i], x[i + 1], t[i + 1]);
  if (closed) {
    // Going once round leaves the frame turned by the curve's holonomy; spread the correction
    // along the arc length so ring n-1 joins ring 0 without a visible twist jump.
    const Vec3 rn = propagate(r[n - 1], t[n - 1], x[n - 1], x[0], t[0]);
    const double phi = std::atan2(t[0].dot(rn.cross(r[0])), rn.dot(r[0]));
    std::vector<double> s(n + 1, 0.0);
    for (int i = 0; i < n; ++i) s[i + 1] = s[i] + (x[next(i)] - x[i]).norm();
    for (int i = 1; i < n; ++i) r[i] = rotate_about(r[i], t[i], phi * s[i] / s[n]);
  }

  const int sides = options.sides;
  const double R = options.radius;
  const int rings = n;
  const int cap_vertices = closed ? 0 : 2 * (sides + 1);
  mesh.positions.reserve(rings * sides + cap_vertices);
  mesh.normals.reserve(rings * sides + cap_vertices);
  mesh.source.reserve(rings * sides + cap_vertices);
  std::vector<double> cs(sides), sn(sides);
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * std::numbers::pi * k / sides;
    cs[k] = std::cos(a);
    sn[k] = std::sin(a);
  }
  for (int i = 0; i < rings; ++i) {
    const Vec3 b = t[i].cross(r[i]);  // (r, b, t) is right-handed
    for (int k = 0; k < sides; ++k) {
      const Vec3 nrm = cs[k] * r[i] + sn[k] * b;
      mesh.positions.push_back(x[i] + R * nrm);
      mesh.normals.push_back(nrm);
      mesh.source.push_back(src[i]);
    }
  }
  auto vid = [&](int i, int k) { return static_cast<std::uint32_t>(i * sides + (k % sides)); };
  const int segments = closed ? n : n - 1;
  mesh.indices.reserve(3 * (2 * segments * sides + (closed ? 0 : 2 * sides)));
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % n;
    for (int k = 0; k < sides; ++k) {
      // Counter-clockwise seen from outside: (i,k) -> (i,k+1) -> (j,k+1), then (i,k) -> (j,k+1) -> (j,k).
      mesh.indices.insert(mesh.indices.end(), {vid(i, k), vid(i, k + 1), vid(j, k + 1)});
      mesh.indices.insert(mesh.indices.end(), {vid(i, k), vid(j, k + 1), vid(j, k)});
    }
  }
  if (!closed) {
    // Flat caps need their own vertices: their normal is the tangent, not the radial direction.
    for (int end = 0; end < 2; ++end) {
      const int i = end == 0 ? 0 : n - 1;
      const Vec3 nrm = end == 0 ? Vec3(-t[i]) : t[i];
      const Vec3 b = t[i].cross(r[i]);
      const auto centre = static_cast<std::uint32_t>(mesh.positions.size());
      mesh.positions.push_back(x[i]);
      mesh.normals.push_back(nrm);
      mesh.source.push_back(src[i]);
      for (int k = 0; k < sides; ++k) {
        mesh.positions.push_back(x[i] + R * (cs[k] * r[i] + sn[k] * b));
        mesh.normals.push_back(nrm);
        mesh.source.push_back(src[i]);
      }
      for (int k = 0; k < sides; ++k) {
        const std::uint32_t a = centre + 1 + k, c = centre + 1 + (k + 1) % sides;
        if (end == 0)
          mesh.indices.insert(mesh.indices.end(), {centre, c, a});
        else
          mesh.indices.insert(mesh.indices.end(), {centre, a, c});
      }
    }
  }
  return mesh;
}

RenderMesh sphere_mesh(const Vec3& centre, double radius, int rings, int sides) {
  if (rings < 3 || sides < 3)
    throw Error("a sphere needs at least 3 rings and 3 sides, got " + std::to_string(rings) + " and " +
                std::to_string(sides));
  if (!(radius > 0) || !std::isfinite(radius) || !centre.allFinite())
    throw Error("a sphere needs a finite centre and a positive finite radius");
  RenderMesh m;
  // Rows 0..rings of latitude, the poles as rows of coincident points (their triangles have no
  // area, which costs nothing and keeps the indexing one grid).
  for (int i = 0; i <= rings; ++i) {
    const double th = std::numbers::pi * i / rings;
    for (int k = 0; k < sides; ++k) {
      const double ph = 2 * std::numbers::pi * k / sides;
      const Vec3 n(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      m.positions.push_back(centre + radius * n);
      m.normals.push_back(n);
      m.source.push_back(0);
    }
  }
  auto vid = [&](int i, int k) { return static_cast<std::uint32_t>(i * sides + k % sides); };
  for (int i = 0; i < rings; ++i)
    for (int k = 0; k < sides; ++k) {
      // Counter-clockwise seen from outside (theta runs down from +z, phi counter-clockwise).
      m.indices.insert(m.indices.end(), {vid(i, k), vid(i + 1, k), vid(i + 1, k + 1)});
      m.indices.insert(m.indices.end(), {vid(i, k), vid(i + 1, k + 1), vid(i, k + 1)});
    }
  return m;
}

void append_mesh(RenderMesh& mesh, const RenderMesh& part, int source_offset) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
  for (int s : part.source) mesh.source.push_back(s + source_offset);
  for (std::uint32_t i : part.indices) mesh.indices.push_back(base + i);
}

}  // namespace s4d
