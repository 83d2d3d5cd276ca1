// How many of the persistent contacts could sleep through a step (issue 36): the ceiling of any
// scheme that leaves "dormant" listed pairs untouched until a bound says they may matter.
//
// A ContactCache with the World's own settings is fed the folded cloth's positions after every
// step (at rest, then its upper layer dragged: cloth_scene.hpp's FoldedDrag). Each listed pair's
// lower bound L (exact distance at its last solve less its motion since) is sorted against:
//  - the reach (1.5 δ): a pair with L > reach is never handed to the contacts, so it could sleep
//    until its vertices' motion has used up L − reach;
//  - δ and a step's approach: a pair with L ≥ δ needs an impulse only if its cells approach faster
//    than (L − δ)/dt; their speed is at most s_a + s_b (each cell's fastest vertex, less the mean
//    velocity). r = (L − δ) / (dt (s_a + s_b)) < 1: it may need one this step; r ≥ 1: it could
//    sleep through the first sweep (the impulses of the other contacts can still wake it).
// The counts are each a step's mean over the window printed; "acted" is the World's own count of
// contacts given an impulse or a push.
// Usage: contact_slack [--n 64] [--every 100]
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cloth_scene.hpp"
#include "physics/contact_cache.hpp"

namespace s4d::bench {
namespace {

struct Window {
  double listed = 0, beyond_reach = 0, below_delta = 0, acted = 0;
  std::array<double, 4> ratio{};  // r < 1, 1–4, 4–16, ≥ 16
  int steps = 0;
};

struct Slack {
  const World<4>& w;
  SelfProximity<4, 3> prox;
  ContactCache<4, 3> cache{0.2, 0.02};  // CollisionSolver's kCacheSkin, kCacheReSolve
  std::vector<double> cell_speed;
  explicit Slack(const World<4>& world)
      : w(world), prox(std::vector<Cell<3>>(world.model().triangles.begin(), world.model().triangles.end())) {
    prox.set_skin(0.5);  // collision.cpp's kProximitySkin
  }
  void sample(Window& win) {
    const auto& tri = w.model().triangles;
    const double delta = w.model().contact_thickness, reach = 1.5 * delta, dt = w.model().params.time_step;
    cache.update(prox, tri, w.positions(), reach);
    const auto v = w.velocities();
    Vec4 mean = Vec4::Zero();
    for (const Vec4& u : v) mean += u;
    mean /= static_cast<double>(v.size());
    cell_speed.assign(tri.size(), 0.0);
    for (std::size_t t = 0; t < tri.size(); ++t)
      for (const int k : tri[t]) cell_speed[t] = std::max(cell_speed[t], (v[k] - mean).norm());
    for (const auto& e : cache.entries()) {
      const double l = ContactCache<4, 3>::lower_bound(e);
      win.listed += 1;
      if (l > reach) win.beyond_reach += 1;
      if (l < delta) {
        win.below_delta += 1;
        continue;
      }
      const double r = (l - delta) / (dt * (cell_speed[e.a] + cell_speed[e.b]));
      win.ratio[r < 1 ? 0 : r < 4 ? 1 : r < 16 ? 2 : 3] += 1;
    }
    win.acted += w.data().last_contacts;
    ++win.steps;
  }
};

void print(const char* what, long long from, const Window& w) {
  const double k = 1.0 / std::max(1, w.steps);
  std::printf("%-6s %5lld–%-5lld %7.0f %7.0f %7.0f %7.0f %7.0f %7.0f %7.0f %6.0f\n", what, from,
              from + w.steps - 1, w.listed * k, w.beyond_reach * k, w.below_delta * k, w.ratio[0] * k,
              w.ratio[1] * k, w.ratio[2] * k, w.ratio[3] * k, w.acted * k);
}

int usage() {
  std::fprintf(stderr, "usage: contact_slack [--n N] [--every K]\n");
  return 2;
}

}  // namespace
}  // namespace s4d::bench

int main(int argc, char** argv) {
  using namespace s4d::bench;
  int n = 64, every = 100;
  if ((argc - 1) % 2 != 0) return usage();
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const int value = std::atoi(argv[i + 1]);
    if (flag == "--n" && value >= 8) n = value;
    else if (flag == "--every" && value >= 1) every = value;
    else return usage();
  }
  std::printf("folded %d² cloth, a step's mean over each window: listed pairs; L > reach; L < δ; "
              "L ≥ δ by r = (L − δ)/(dt (s_a + s_b)); contacts acted\n", n);
  std::printf("%-6s %-11s %7s %7s %7s %7s %7s %7s %7s %6s\n", "", "steps", "listed", ">reach", "<δ", "r<1",
              "r 1–4", "r 4–16", "r≥16", "acted");
  // At rest: physics_bench's folded figure is steps 201–300 of this.
  {
    auto w = folded_cloth_on_table<4>(n);
    Slack slack(*w);
    Window win;
    for (int s = 0; s < 300; ++s) {
      w->step();
      slack.sample(win);
      if ((s + 1) % every == 0) {
        print("rest", s + 2 - win.steps, win);
        win = Window{};
      }
    }
  }
  // The drag: 200 steps settling, then 2 s (physics_bench's BM_Cloth4DFoldedDragStep).
  FoldedDrag<4> d(n, 200, true);
  Slack slack(*d.world);
  Window win;
  for (int s = 0; s < 2000; ++s) {
    d.step();
    slack.sample(win);
    if ((s + 1) % every == 0) {
      print("drag", s + 2 - win.steps, win);
      win = Window{};
    }
  }
  return 0;
}
