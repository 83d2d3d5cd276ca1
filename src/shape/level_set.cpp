// The level set of a view's depth on a triangle mesh (see level_set.hpp): one segment per triangle
// the level crosses, joined through the edges they share into curves.
#include "shape/level_set.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

#include "core/error.hpp"

namespace s4d {
namespace {

using EdgeKey = std::uint64_t;
EdgeKey edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

// A segment of the level set inside one triangle, from the crossing on edge `from` to that on
// edge `to`, with the part above the level on its left as the triangle's orientation sees it.
struct Segment {
  EdgeKey from, to;
};

// Drops points within `eps` of the one before them (and, closed, the last within eps of the
// first): a curve through a vertex at the level meets it from each triangle around it.
template <int N>
void merge_close_points(Polyline<N>& line, double eps) {
  std::vector<Vec<N>> kept;
  kept.reserve(line.points.size());
  for (const Vec<N>& p : line.points)
    if (kept.empty() || (p - kept.back()).norm() > eps) kept.push_back(p);
  if (line.closed)
    while (kept.size() > 1 && (kept.back() - kept.front()).norm() <= eps) kept.pop_back();
  line.points = std::move(kept);
}

}  // namespace

template <int D>
LevelSet<D> level_set(const Surface<D>& mesh, const Frame<D>& frame, double level) {
  if (!std::isfinite(level)) throw Error("a slice needs a finite level");
  const int nv = static_cast<int>(mesh.vertices.size());
  std::vector<Vec<D>> view(mesh.vertices.size());
  Vec<D> lo = Vec<D>::Constant(0), hi = Vec<D>::Constant(0);
  for (int i = 0; i < nv; ++i) {
    if (!mesh.vertices[i].allFinite())
      throw Error("cannot slice a mesh with a non-finite vertex (" + std::to_string(i) + ")");
    view[i] = frame.to_view(mesh.vertices[i]);
    lo = i == 0 ? view[i] : Vec<D>(lo.cwiseMin(view[i]));
    hi = i == 0 ? view[i] : Vec<D>(hi.cwiseMax(view[i]));
  }
  LevelSet<D> out;
  out.level = level;
  auto above = [&](int v) { return view[v][D - 1] >= level; };
  for (int v = 0; v < nv; ++v) out.vertices_at_level += view[v][D - 1] == level ? 1 : 0;

  std::vector<Segment> segments;
  std::vector<EdgeKey> keys;
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || t[k] >= nv)
        throw Error("cannot slice a mesh whose triangle uses vertex " + std::to_string(t[k]) + " of " +
                    std::to_string(nv));
    const bool s0 = above(t[0]), s1 = above(t[1]), s2 = above(t[2]);
    if (s0 == s1 && s1 == s2) continue;
    // The corner on its own side of the level, and the edges into and out of it (in the
    // triangle's order): the segment from the one to the other has that corner on its right.
    const int odd = s0 == s1 ? 2 : (s0 == s2 ? 1 : 0);
    const int prev = t[(odd + 2) % 3], corner = t[odd], next = t[(odd + 1) % 3];
    const EdgeKey in = edge_key(prev, corner), out_edge = edge_key(corner, next);
    segments.push_back(above(corner) ? Segment{out_edge, in} : Segment{in, out_edge});
    keys.push_back(in);
    keys.push_back(out_edge);
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  const int nodes = static_cast<int>(keys.size());
  auto node = [&](EdgeKey k) {
    return static_cast<int>(std::lower_bound(keys.begin(), keys.end(), k) - keys.begin());
  };

  // Where the level crosses each edge, in shadow coordinates.
  std::vector<Vec<D - 1>> point(nodes);
  for (int n = 0; n < nodes; ++n) {
    int a = static_cast<int>(keys[n] >> 32), b = static_cast<int>(keys[n] & 0xffffffffu);
    if (above(a)) std::swap(a, b);  // a below, b at or above
    const double fa = view[a][D - 1], fb = view[b][D - 1];
    if (fb == level) {
      point[n] = frame.project(view[b]);
    } else {
      const double t = (level - fa) / (fb - fa);
      point[n] = frame.project(view[a] + t * (view[b] - view[a]));
    }
  }

  // The segments at each node (two on a manifold's interior edge, one on its boundary).
  std::vector<int> start(nodes + 1, 0);
  std::vector<std::array<int, 2>> ends(segments.size());
  for (std::size_t s = 0; s < segments.size(); ++s) {
    ends[s] = {node(segments[s].from), node(segments[s].to)};
    ++start[ends[s][0] + 1];
    ++start[ends[s][1] + 1];
  }
  for (int n = 0; n < nodes; ++n) start[n + 1] += start[n];
  std::vector<int> incident(start.back()), fill(start.begin(), start.end() - 1);
  for (std::size_t s = 0; s < segments.size(); ++s)
    for (int e : ends[s]) incident[fill[e]++] = static_cast<int>(s);
  auto degree = [&](int n) { return start[n + 1] - start[n]; };

  std::vector<char> used(segments.size(), 0);
  const double eps = 1e-12 * std::max(1.0, (hi - lo).norm());
  // Walks from `first` along unused segments until a node without one, or one where curves
  // branch (not two segments), or back at the start.
  auto walk = [&](int first, bool closed) {
    Polyline<D - 1> line;
    line.closed = closed;
    int at = first, forward = 0, backward = 0;
    line.points.push_back(point[at]);
    for (;;) {
      int next_segment = -1;
      for (int i = start[at]; i < start[at + 1]; ++i)
        if (!used[incident[i]]) {
          next_segment = incident[i];
          break;
        }
      if (next_segment < 0) break;
      used[next_segment] = 1;
      const bool along = ends[next_segment][0] == at;
      (along ? forward : backward) += 1;
      at = along ? ends[next_segment][1] : ends[next_segment][0];
      if (at == first && closed) break;
      line.points.push_back(point[at]);
      if (degree(at) != 2) break;
    }
    if (backward > forward) std::reverse(line.points.begin(), line.points.end());
    merge_close_points(line, eps);
    if (line.points.size() >= (closed ? 3u : 2u)) {
      out.open_components += closed ? 0 : 1;
      out.curve.components.push_back(std::move(line));
    }
  };
  for (int n = 0; n < nodes; ++n)
    if (degree(n) != 2)
      while (std::any_of(incident.begin() + start[n], incident.begin() + start[n + 1],
                         [&](int s) { return !used[s]; }))
        walk(n, false);
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (!used[s]) walk(ends[s][0], true);
  return out;
}

template <int D>
std::pair<double, double> depth_range(const Surface<D>& mesh, const Frame<D>& frame) {
  if (mesh.vertices.empty()) return {0.0, 0.0};
  double lo = frame.depth(mesh.vertices.front()), hi = lo;
  for (const Vec<D>& p : mesh.vertices) {
    const double d = frame.depth(p);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return {lo, hi};
}

std::vector<double> movie_levels(double lo, double hi, int count) {
  std::vector<double> levels;
  for (int i = 0; i < count; ++i) levels.push_back(lo + (i + 1) * (hi - lo) / (count + 1));
  if (count % 2 == 1) levels[count / 2] = 0.5 * (lo + hi);
  return levels;
}

template <int D>
Curve<D> lift_slice(const Curve<D - 1>& slice, const Frame<D>& frame, double level) {
  Curve<D> out;
  for (const Polyline<D - 1>& line : slice.components) {
    Polyline<D> lifted;
    lifted.closed = line.closed;
    for (const Vec<D - 1>& p : line.points) lifted.points.push_back(frame.to_world(frame.lift(p, level)));
    out.components.push_back(std::move(lifted));
  }
  return out;
}

template LevelSet<2> level_set(const Surface<2>&, const Frame<2>&, double);
template LevelSet<3> level_set(const Surface<3>&, const Frame<3>&, double);
template LevelSet<4> level_set(const Surface<4>&, const Frame<4>&, double);
template std::pair<double, double> depth_range(const Surface<2>&, const Frame<2>&);
template std::pair<double, double> depth_range(const Surface<3>&, const Frame<3>&);
template std::pair<double, double> depth_range(const Surface<4>&, const Frame<4>&);
template Curve<2> lift_slice(const Curve<1>&, const Frame<2>&, double);
template Curve<3> lift_slice(const Curve<2>&, const Frame<3>&, double);
template Curve<4> lift_slice(const Curve<3>&, const Frame<4>&, double);

}  // namespace s4d
