// How long the stepping benchmark's pair list could live under each bound of the unlisted pairs'
// motion (docs/performance.md): the ceiling any scheme that defers list builds can reach.
//
// A list built at radius R = δ (1 + skin) holds every pair whose boxes were within R; an unlisted
// pair may come within δ once its relative motion since the build, M_ab, reaches its build gap
// minus δ. SelfProximity bounds every M_ab by 2ρ (ρ: the largest centred displacement), one
// number for the whole mesh. This program follows proximity_bench's motion from a build and
// reports the steps until each bound lets some unlisted pair reach δ:
//  - global: 2ρ, what the code does;
//  - exact: every unlisted pair's own M_ab (its build gap kept per pair), the ceiling;
//  - patch: per pair of B × B-quad mesh patches, the gap of their boxes (at least R) less
//    |c_i - c_j| + r_i + r_j, the balls holding each patch's displacements.
// Usage: list_lifetime [--n 64] [--skin 1.5] [--patch 2] [--builds 3]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "proximity/cell_boxes.hpp"
#include "proximity_grid.hpp"

namespace s4d::bench {
namespace {

struct Options {
  int n = 64, patch = 2, builds = 3;
  double skin = SelfProximity<4, 3>::kDefaultSkin;
};

struct Ball {
  Vec4 centre = Vec4::Zero();
  double radius = 0;
};

// The ball about the bounding box's centre holding u[v] for the vertices listed.
Ball ball_of(const std::vector<Vec4>& u, const std::vector<int>& vertices) {
  Box<4> box;
  for (const int v : vertices) box.add(u[v]);
  Ball b;
  b.centre = 0.5 * (box.lo + box.hi);
  for (const int v : vertices) b.radius = std::max(b.radius, (u[v] - b.centre).norm());
  return b;
}

void run(const Options& o) {
  const int n = o.n;
  const double delta = grid_delta(n), radius = delta * (1 + o.skin);
  // Unlisted pairs farther than this at the build cannot reach δ until 2ρ has grown to five times
  // what ends the global bound's list: the exact search looks no further (and says ">=" past it).
  const double horizon = radius + 4 * (radius - delta);
  const std::vector<Cell<3>> cells = grid_triangles(n);
  const int nc = static_cast<int>(cells.size());
  const CellTopology<3> topo(cells, n * n);
  std::vector<std::set<int>> near_on_mesh(nc);  // sharing a vertex or a ring pair: never listed
  for (int a = 0; a < nc; ++a)
    topo.for_each_topological_neighbour(cells[a], [&](int c) { near_on_mesh[a].insert(c); });
  // Patches: grid_triangles numbers the two triangles of quad (i, j) 2 ((n - 1) i + j) + {0, 1}.
  const int per_side = (n - 2) / o.patch + 1, patches = per_side * per_side;
  std::vector<int> patch_of(nc);
  std::vector<std::vector<int>> patch_vertices(patches);
  for (int c = 0; c < nc; ++c) {
    const int quad = c / 2, i = quad / (n - 1), j = quad % (n - 1);
    patch_of[c] = (i / o.patch) * per_side + j / o.patch;
    for (const int v : cells[c]) patch_vertices[patch_of[c]].push_back(v);
  }
  for (auto& vs : patch_vertices) {
    std::sort(vs.begin(), vs.end());
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  }
  std::printf("n %d (%d triangles), skin %.2f (R = %.2f δ), patches of %d × %d quads (%d)\n", n, nc,
              o.skin, 1 + o.skin, o.patch, o.patch, patches);
  int step = 0;
  for (int build = 0; build < o.builds; ++build) {
    const std::vector<Vec4> xb = crumpled_grid<4>(n, kPhasePerStep * step);
    std::vector<Box<4>> boxes;
    prox_detail::static_boxes<4, 3>(xb, cells, boxes);
    Bvh<4> tree;
    tree.build(boxes);
    struct Watched {
      int a, b;
      double gap;
    };
    std::vector<Watched> watched;
    long listed = 0;
    tree.self_pairs(horizon, [&](int a, int b) {
      if (near_on_mesh[a].count(b)) return;
      const double gap = prox_detail::box_gap<4>(boxes[a], boxes[b]);
      if (gap <= radius)
        ++listed;
      else if (gap <= horizon)
        watched.push_back({std::min(a, b), std::max(a, b), gap});
    });
    std::vector<Box<4>> patch_box(patches);
    for (int c = 0; c < nc; ++c) patch_box[patch_of[c]].add(boxes[c]);
    struct PatchPair {
      int i, j;
      double gap;  // at least R: the unlisted pairs between them were farther
    };
    std::vector<PatchPair> patch_pairs;
    for (int i = 0; i < patches; ++i)
      for (int j = i; j < patches; ++j) {
        const double gap = prox_detail::box_gap<4>(patch_box[i], patch_box[j]);
        if (gap <= horizon) patch_pairs.push_back({i, j, std::max(gap, radius)});
      }
    int global = 0, exact = 0, patch = 0;
    for (int s = 1; !(global && exact && patch) && s <= 1000; ++s) {
      const std::vector<Vec4> x = crumpled_grid<4>(n, kPhasePerStep * (step + s));
      std::vector<Vec4> u;
      const double rho = prox_detail::centred_difference<4>(x, xb, u);
      if (!global && radius - 2 * rho < delta) global = s;
      if (!exact)
        for (const Watched& w : watched)
          if (w.gap - prox_detail::max_relative<4, 3>(u, cells[w.a], cells[w.b]) < delta) {
            exact = s;
            break;
          }
      if (!exact && horizon - 2 * rho < delta) exact = -s;  // past the horizon: at least s
      if (!patch) {
        std::vector<Ball> balls(patches);
        for (int p = 0; p < patches; ++p) balls[p] = ball_of(u, patch_vertices[p]);
        bool ok = horizon - 2 * rho >= delta;
        for (const PatchPair& pp : patch_pairs) {
          const Ball &bi = balls[pp.i], &bj = balls[pp.j];
          if (pp.gap - ((bi.centre - bj.centre).norm() + bi.radius + bj.radius) < delta) ok = false;
        }
        if (!ok) patch = s;
      }
    }
    std::printf("build at step %4d: listed %ld; lifetime in steps: global %d, exact %s%d, patch %d "
                "(%zu patch pairs)\n",
                step, listed, global, exact < 0 ? ">= " : "", std::abs(exact), patch,
                patch_pairs.size());
    step += global;
  }
}

}  // namespace
}  // namespace s4d::bench

int main(int argc, char** argv) {
  s4d::bench::Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const double value = std::atof(argv[i + 1]);
    if (key == "--n") o.n = static_cast<int>(value);
    else if (key == "--skin") o.skin = value;
    else if (key == "--patch") o.patch = static_cast<int>(value);
    else if (key == "--builds") o.builds = static_cast<int>(value);
    else {
      std::fprintf(stderr, "usage: list_lifetime [--n N] [--skin S] [--patch B] [--builds K]\n");
      return 2;
    }
  }
  if (!(o.n >= 3 && o.n <= 1024 && o.patch >= 1 && o.builds >= 1 && o.builds <= 100 && o.skin > 0 &&
        o.skin <= 8)) {
    std::fprintf(stderr, "list_lifetime: need 3 <= n <= 1024, patch >= 1, 1 <= builds <= 100, "
                         "0 < skin <= 8\n");
    return 2;
  }
  s4d::bench::run(o);
  return 0;
}
