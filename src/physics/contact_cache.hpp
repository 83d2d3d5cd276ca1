// Persistent contacts for the repulsion: the cell pairs (triangles, or a curve's segments) near
// each other are kept from step to
// step with their closest features, normal and distance. A step carries each distance along its
// normal by the vertices' motion (the first-order change, as a persistent contact manifold does)
// and solves a pair exactly again only once it has moved enough to matter; the pairs are found
// afresh only when the motion since the last search could have brought an unlisted pair within
// reach. A cloth resting on itself then costs what changes, not what touches.
//
// Bounds: a distance is 1-Lipschitz in the relative motion of the two cells' vertices, so a
// pair solved exactly at distance L and moved by at most M since (summed per step) is at least
// L - M apart now. A pair not listed was farther than the search radius R at the search, and the
// net motion since then, less a common translation, is at most ρ per vertex: it is at least
// R - 2ρ apart, within reach only once 2ρ exceeds R - reach.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/vec.hpp"
#include "proximity/self_proximity.hpp"

namespace s4d {

// The face of cell c holding a closest point (the vertices of non-zero weight) as one number:
// their indices + 1, sorted, 21 bits each.
template <int K>
std::uint64_t feature_key(const std::array<int, K>& c, const std::array<double, 3>& w) {
  std::uint64_t v[3] = {0, 0, 0};
  for (int q = 0; q < K; ++q) v[q] = w[q] > 0 ? static_cast<std::uint64_t>(c[q]) + 1 : 0;
  if (v[0] > v[1]) std::swap(v[0], v[1]);
  if (v[1] > v[2]) std::swap(v[1], v[2]);
  if (v[0] > v[1]) std::swap(v[0], v[1]);
  return v[0] | v[1] << 21 | v[2] << 42;
}

struct ContactCacheStats {
  long long searches = 0;  // fresh searches (SelfProximity::pairs_within)
  long long solves = 0;    // exact re-solves of listed pairs
  long long carried = 0;   // entry updates from the motion alone
  ContactCacheStats& operator+=(const ContactCacheStats& o) {
    searches += o.searches;
    solves += o.solves;
    carried += o.carried;
    return *this;
  }
};

// K: vertices per cell (3 triangles, 2 segments).
template <int D, int K>
class ContactCache {
 public:
  struct Entry {
    int a = 0, b = 0;                  // cells, a < b
    std::array<double, 3> wa{}, wb{};  // barycentric weights of the closest points (last solve)
    Vec<D> n = Vec<D>::Zero();         // unit, from b's point to a's (zero: touching, no direction)
    double d = 0;                      // distance now: the last solve's, carried along n since
    double solved = 0;                 // distance at the last exact solve
    double moved = 0;                  // upper bound of the pair's relative motion since then
    unsigned code = 0;                 // face pair of the last solve (closest_points_warm)
    // The faces holding the closest points (feature_key): equal keys, the same constraint.
    std::uint64_t key_a = 0, key_b = 0;
  };
  using Stats = ContactCacheStats;

  // skin: the search radius is reach × (1 + skin); re_solve: a listed pair within reach is solved
  // again once its motion since the last solve exceeds re_solve × reach.
  ContactCache(double skin, double re_solve) : skin_(skin), re_solve_(re_solve) {}

  // Brings the entries to positions x (nv × D). Pairs sharing a vertex and ring pairs are never
  // listed (the springs hold those; the fail-safe guards them).
  void update(SelfProximity<D, K>& prox, std::span<const std::array<int, K>> cells, std::span<const Vec<D>> x,
              double reach);
  // Every listed pair; those with lower_bound(e) <= reach may be within reach.
  std::span<const Entry> entries() const { return entries_; }
  static double lower_bound(const Entry& e) { return e.solved - e.moved; }
  const Stats& stats() const { return stats_; }
  // Forget everything: the next update searches afresh (a restored state, new parameters).
  void clear() { x_search_.clear(); }

 private:
  void search(SelfProximity<D, K>& prox, std::span<const std::array<int, K>> cells, std::span<const Vec<D>> x,
              double reach);
  // Whether some unlisted pair may have come within reach since the search.
  bool search_stale(std::span<const Vec<D>> x, double reach) const;
  void solve(Entry& e, std::span<const std::array<int, K>> cells, std::span<const Vec<D>> x);

  double skin_, re_solve_;
  double radius_ = 0;              // the last search's radius
  std::vector<Entry> entries_;
  std::vector<Vec<D>> x_search_;   // positions at the last search (empty: none)
  std::vector<Vec<D>> x_last_;     // positions at the last update
  std::vector<Vec<D>> step_;       // nv: motion since the last update
  std::vector<double> vertex_move_;    // nv: |that motion less the mean one|
  std::vector<double> cell_move_;    // per cell: the largest of its vertices'
  std::vector<ProximityPair<D>> found_;  // scratch of the search
  Stats stats_;
};

}  // namespace s4d
