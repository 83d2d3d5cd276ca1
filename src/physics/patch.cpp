// Dijkstra over the mesh's CSR adjacency, cut off at the radius.
#include "physics/patch.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace s4d {

void PatchScratch::reserve(int vertex_count, std::size_t edge_ends) {
  distance.reserve(static_cast<std::size_t>(vertex_count));
  heap.reserve(edge_ends + static_cast<std::size_t>(vertex_count));
}

template <int D>
void grow_patch(const Model<D>& model, std::span<const Vec<D>> x, std::span<const int> centres, double radius,
                Patch& out, PatchScratch& scratch) {
  out.vertices.clear();
  out.weights.clear();
  const int nv = std::min(model.nv, static_cast<int>(x.size()));
  constexpr double kFar = std::numeric_limits<double>::infinity();
  auto& dist = scratch.distance;
  auto& heap = scratch.heap;
  dist.assign(static_cast<std::size_t>(nv), kFar);
  heap.clear();
  const std::greater<> later;  // a min-heap on distance
  for (int c : centres)
    if (c >= 0 && c < nv && dist[static_cast<std::size_t>(c)] > 0) {
      dist[static_cast<std::size_t>(c)] = 0;
      heap.emplace_back(0.0, c);
      std::push_heap(heap.begin(), heap.end(), later);
    }
  const double r = std::isfinite(radius) ? std::max(radius, 0.0) : 0.0;
  const bool adjacency = model.adjacency_offset.size() == static_cast<std::size_t>(model.nv) + 1;
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const auto [d, v] = heap.back();
    heap.pop_back();
    if (d > dist[static_cast<std::size_t>(v)]) continue;  // a stale entry
    const double u = r > 0 ? d / r : 0;
    out.vertices.push_back(v);
    out.weights.push_back((1 - u * u) * (1 - u * u));
    if (r <= 0 || !adjacency) continue;
    for (int k = model.adjacency_offset[static_cast<std::size_t>(v)];
         k < model.adjacency_offset[static_cast<std::size_t>(v) + 1]; ++k) {
      const int n = model.adjacency[static_cast<std::size_t>(k)];
      if (n < 0 || n >= nv) continue;
      const double e = (x[static_cast<std::size_t>(n)] - x[static_cast<std::size_t>(v)]).norm();
      const double dn = d + (std::isfinite(e) ? e : kFar);
      if (dn < r && dn < dist[static_cast<std::size_t>(n)]) {
        dist[static_cast<std::size_t>(n)] = dn;
        heap.emplace_back(dn, n);
        std::push_heap(heap.begin(), heap.end(), later);
      }
    }
  }
}

template void grow_patch<3>(const Model<3>&, std::span<const Vec<3>>, std::span<const int>, double, Patch&,
                            PatchScratch&);
template void grow_patch<4>(const Model<4>&, std::span<const Vec<4>>, std::span<const int>, double, Patch&,
                            PatchScratch&);

}  // namespace s4d
