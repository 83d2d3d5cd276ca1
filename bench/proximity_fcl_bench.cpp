// D = 3 comparison with FCL on the same triangle mesh (the crumpled 64×64 grid's xyz part): all
// non-adjacent triangle pairs within δ. FCL: dynamic AABB tree over δ-inflated triangle boxes,
// then fcl::distance on one-triangle BVHModel<OBBRSS> pairs. Ours: SelfProximity<3, 3>.
// Ratio = FCL time / ours.
#include <benchmark/benchmark.h>

#include <fcl/fcl.h>

#include <memory>

#include "proximity_grid.hpp"

namespace s4d::bench {
namespace {

void BM_Ours3D(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto x = crumpled_grid<3>(n, 0.0);
  SelfProximity<3, 3> q(grid_triangles(n));
  q.set_temporal_coherence(false);  // FCL answers each query from scratch: so do we here
  std::vector<ProximityPair<3>> out;
  q.pairs_within(x, grid_delta(n), out);
  for (auto _ : state) {
    q.pairs_within(x, grid_delta(n), out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["pairs"] = static_cast<double>(out.size());
}
BENCHMARK(BM_Ours3D)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

struct FclScene {
  std::vector<Cell<3>> tris;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> proxies;  // δ-inflated boxes (broad phase)
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> shapes;   // the triangles (narrow phase)
  std::unique_ptr<fcl::DynamicAABBTreeCollisionManagerd> manager;
  double delta = 0;
  int pairs = 0;
};

bool fcl_pair(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* s = static_cast<FclScene*>(data);
  const int a = static_cast<int>(reinterpret_cast<std::intptr_t>(o1->getUserData()));
  const int b = static_cast<int>(reinterpret_cast<std::intptr_t>(o2->getUserData()));
  if (share_vertex<3, 3>(s->tris[a], s->tris[b])) return false;
  fcl::DistanceRequestd req;
  fcl::DistanceResultd res;
  fcl::distance(s->shapes[a].get(), s->shapes[b].get(), req, res);
  if (res.min_distance <= s->delta) ++s->pairs;
  return false;  // keep going
}

void BM_Fcl3D(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto x = crumpled_grid<3>(n, 0.0);
  FclScene s;
  s.tris = grid_triangles(n);
  s.delta = grid_delta(n);
  s.manager = std::make_unique<fcl::DynamicAABBTreeCollisionManagerd>();
  std::vector<fcl::CollisionObjectd*> raw;
  for (std::size_t i = 0; i < s.tris.size(); ++i) {
    const auto& t = s.tris[i];
    // FCL has no TriangleP–TriangleP distance; a one-triangle BVH model is its exact route.
    auto tri = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    tri->beginModel();
    tri->addTriangle(x[t[0]], x[t[1]], x[t[2]]);
    tri->endModel();
    s.shapes.push_back(std::make_unique<fcl::CollisionObjectd>(tri));
    Box<3> b;
    for (int v : t) b.add(x[v]);
    const Vec3 size = (b.hi - b.lo) + Vec3::Constant(s.delta);
    auto box = std::make_shared<fcl::Boxd>(size);
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() = 0.5 * (b.lo + b.hi);
    s.proxies.push_back(std::make_unique<fcl::CollisionObjectd>(box, tf));
    s.proxies.back()->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(i)));
    raw.push_back(s.proxies.back().get());
  }
  s.manager->registerObjects(raw);
  s.manager->setup();
  for (auto _ : state) {
    s.pairs = 0;
    s.manager->update();  // the refit step, as ours does every query
    s.manager->collide(&s, fcl_pair);
    benchmark::DoNotOptimize(s.pairs);
  }
  state.counters["pairs"] = s.pairs;
}
BENCHMARK(BM_Fcl3D)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace s4d::bench

BENCHMARK_MAIN();
