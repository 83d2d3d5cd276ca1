// Physics step costs (issue 5): a crumpled 4D cloth with self-collision at 64² and 128², the spun
// trefoil at scenario resolution, a knot of 500 points dragged through itself (issue 26: the drag
// must run at the 1 kHz haptic rate), and the peer comparison with Bullet's btSoftBody on the same
// 3D cloth (steps per second and pass-throughs left, side by side). Every world is a scene built by
// the one world builder.
#include <benchmark/benchmark.h>

#include <btBulletDynamicsCommon.h>
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

#include <chrono>
#include <memory>

#include "io/scene.hpp"
#include "physics/world.hpp"
#include "proximity/mesh_proximity.hpp"
#include "scenario/world_builder.hpp"
#include "shape/generators.hpp"
#include "shape/grid_mesh.hpp"

#include "cloth_scene.hpp"
#include "spun_trefoil_scene.hpp"

namespace s4d {
namespace {

using bench::crumpled_cloth;
using bench::drive_corners;
using bench::flat_cloth_scene;
using bench::folded_cloth_on_table;

template <int D>
int pass_throughs(std::span<const Vec<D>> x, const std::vector<Triangle>& tris) {
  std::vector<Cell<3>> cells(tris.begin(), tris.end());
  return static_cast<int>(intersecting_pairs<D, 3>(x, cells, 1e-9).size());
}

// Persistent contacts on, or every contact found afresh each step (the path before issue 28).
template <int D>
void use_persistent_contacts(World<D>& w, bool on) {
  Model<D> m = w.model();
  m.params.persistent_contacts = on;
  w.set_model(std::move(m));
}

void BM_Cloth4DCrumpledStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  auto w = crumpled_cloth<4>(n, 600);
  const long long runs0 = w->broad_phase_runs();
  double max_move = 0;
  for (auto _ : state) {
    drive_corners(*w, n, w->data().time);
    w->step();
    state.PauseTiming();  // the step is timed, not this statistic of it
    double move2 = 0;
    for (int i = 0; i < w->vertex_count(); ++i)
      move2 = std::max(move2, (w->data().x[i] - w->data().x0[i]).squaredNorm());
    max_move = std::max(max_move, std::sqrt(move2));
    state.ResumeTiming();
  }
  state.counters["rebuilds_per_step"] =
      static_cast<double>(w->broad_phase_runs() - runs0) / static_cast<double>(state.iterations());
  state.counters["max_move"] = max_move;
  state.counters["delta"] = w->model().contact_thickness;
  state.counters["vertices"] = n * n;
  state.counters["contacts"] = w->data().last_contacts;
  state.counters["substeps"] = w->data().last_substeps;
  state.counters["ccd_freezes"] = static_cast<double>(w->data().warnings.ccd_freezes);
  state.counters["pass_throughs"] = pass_throughs<4>(w->positions(), w->model().triangles);
}
// A fixed number of steps: the cloth keeps moving, so a run of another length would time other
// states (steps 601–900 of the scripted pull at 64², 601–660 at 128²).
BENCHMARK(BM_Cloth4DCrumpledStep)->Arg(64)->Iterations(300)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Cloth4DCrumpledStep)->Arg(128)->Iterations(60)->Unit(benchmark::kMillisecond);

// range(1): 1 = persistent contacts (physics/contact_cache.hpp), 0 = every pair found and solved
// afresh each step (the path before issue 28), side by side.
void BM_Cloth4DFoldedContactStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  auto world = folded_cloth_on_table<4>(n);
  World<4>& w = *world;
  use_persistent_contacts(w, state.range(1) != 0);
  for (int s = 0; s < 200; ++s) w.step();  // the upper half settles onto the lower
  double contacts = 0;
  const long long runs0 = w.broad_phase_runs(), exact0 = w.exact_distances();
  for (auto _ : state) {
    w.step();
    contacts += w.data().last_contacts;
  }
  const double steps = static_cast<double>(state.iterations());
  state.counters["vertices"] = n * n;
  state.counters["contacts_per_step"] = contacts / steps;
  state.counters["exact_per_step"] = static_cast<double>(w.exact_distances() - exact0) / steps;
  state.counters["rebuilds_per_step"] = static_cast<double>(w.broad_phase_runs() - runs0) / steps;
  state.counters["min_gap_over_delta"] = w.min_separation(2 * w.model().contact_thickness) /
                                         w.model().contact_thickness;
  state.counters["pass_throughs"] = pass_throughs<4>(w.positions(), w.model().triangles);
}
BENCHMARK(BM_Cloth4DFoldedContactStep)
    ->ArgNames({"n", "persistent"})
    ->Args({64, 0})
    ->Args({64, 1})
    ->Iterations(300)
    ->Unit(benchmark::kMillisecond);

void BM_SpunTrefoilStep(benchmark::State& state) {
  World<4> w = bench::pulled_spun_trefoil();
  for (auto _ : state) w.step();  // fixed count below: later steps are other states
  state.counters["vertices"] = w.vertex_count();
  state.counters["contacts"] = w.data().last_contacts;
}
BENCHMARK(BM_SpunTrefoilStep)->Iterations(1000)->Unit(benchmark::kMillisecond);

// A trefoil of 500 points as the knot scene simulates it (scenes/trefoil-knot.json: thickness 0.24,
// the tube's diameter), one point held by the window's rubber band (100 N/unit, 2 N at most) and
// pulled to and fro straight across the knot, through the strands in its way: collision avoidance
// stops it at them. Timed: a step (the band's force and World::step), 3000 steps, 3 s of drag.
void BM_KnotDrag500Step(benchmark::State& state) {
  Scene scene = load_scene(std::string(S4D_SOURCE_DIR) + "/scenes/trefoil-knot.json");
  scene.objects[0].shape = generate("torus-knot", {{"p", 2}, {"q", 3}, {"n", 500}});
  SceneWorld<3> sw = build_world<3>(scene);
  World<3>& w = sw.world;
  const int held = 0;
  const Vec3 from = w.positions()[held], to = -from;  // across the knot's middle and out beyond
  int most_contacts = 0, step = 0;
  for (auto _ : state) {
    const double u = 0.5 - 0.5 * std::cos(2 * 3.141592653589793 * step / 3000.0);
    const Vec3 target = from + u * (to - from);
    Vec3 f = 100 * (target - w.positions()[held]) - 0.5 * w.velocities()[held];
    if (f.norm() > 2) f *= 2 / f.norm();
    w.set_external_force(held, f);
    w.step();
    most_contacts = std::max(most_contacts, w.data().last_contacts);
    ++step;
  }
  state.counters["vertices"] = w.vertex_count();
  state.counters["contacts_max"] = most_contacts;
  state.counters["ccd_freezes"] = static_cast<double>(w.data().warnings.ccd_freezes);
  state.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_KnotDrag500Step)->Iterations(3000)->Unit(benchmark::kMillisecond);
// The folded cloth's upper layer dragged 3 cm across the lower and back over 2 s by its free edge
// (cloth_scene.hpp's FoldedDrag; issue 36): the steps of the whole drag, timed together.
// range(1) as in the folded step.
void BM_Cloth4DFoldedDragStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  bench::FoldedDrag<4> d(n, 200, state.range(1) != 0);
  const int steps = static_cast<int>(2 * bench::kDragSeconds / d.world->model().params.time_step + 0.5);
  double contacts = 0, seconds = 0;
  int bad = 0;
  const long long searches0 = d.world->contact_stats().searches, exact0 = d.world->exact_distances();
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) {
      d.step();
      contacts += d.world->data().last_contacts;
      if (s % 500 == 499) {
        state.PauseTiming();
        bad = std::max(bad, pass_throughs<4>(d.world->positions(), d.world->model().triangles));
        state.ResumeTiming();
      }
    }
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  const double total = static_cast<double>(state.iterations()) * steps;
  state.counters["ms_per_step"] = 1e3 * seconds / total;
  state.counters["x_real_time"] = total * d.world->model().params.time_step / seconds;
  state.counters["contacts_per_step"] = contacts / total;
  state.counters["searches_per_step"] = static_cast<double>(d.world->contact_stats().searches - searches0) / total;
  state.counters["exact_per_step"] = static_cast<double>(d.world->exact_distances() - exact0) / total;
  state.counters["pass_throughs"] = bad;
}
BENCHMARK(BM_Cloth4DFoldedDragStep)
    ->ArgNames({"n", "persistent"})
    ->Args({32, 0})
    ->Args({32, 1})
    ->Args({64, 0})
    ->Args({64, 1})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// [SECTION] Peer: the same 3D cloth, grid springs, self-collision on, 1000 steps of 1 ms.
constexpr int kPeerSteps = 1000;

void BM_Peer3DCloth_s4d(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  int bad = 0;
  double steps_per_s = 0;
  for (auto _ : state) {
    World<3> w = build_world<3>(flat_cloth_scene<3>(n)).world;
    use_persistent_contacts(w, state.range(1) != 0);
    w.pin(0);
    w.pin(n - 1);
    const auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < kPeerSteps; ++s) {
      drive_corners(w, n, w.data().time);
      w.step();
      if (s % 100 == 99) bad = std::max(bad, pass_throughs<3>(w.positions(), w.model().triangles));
    }
    steps_per_s = kPeerSteps / std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  state.counters["steps_per_s"] = steps_per_s;
  state.counters["pass_throughs"] = bad;
}
// range(1): persistent contacts (1) or every contact found afresh (0), as in the folded step.
BENCHMARK(BM_Peer3DCloth_s4d)
    ->ArgNames({"n", "persistent"})
    ->Args({64, 0})
    ->Args({64, 1})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

void BM_Peer3DCloth_Bullet(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  int bad = 0;
  double steps_per_s = 0;
  for (auto _ : state) {
    btSoftBodyRigidBodyCollisionConfiguration config;
    btCollisionDispatcher dispatcher(&config);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btSoftRigidDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
    world.setGravity(btVector3(0, -9.81, 0));
    btSoftBodyWorldInfo& info = world.getWorldInfo();
    info.m_gravity = btVector3(0, -9.81, 0);
    info.m_sparsesdf.Initialize();
    // Same grid and corners as ours; the patch adds structural + shear links (gendiags).
    btSoftBody* cloth = btSoftBodyHelpers::CreatePatch(
        info, btVector3(-0.5, 0, -0.5), btVector3(0.5, 0, -0.5), btVector3(-0.5, 0, 0.5),
        btVector3(0.5, 0, 0.5), n, n, 0, true);
    cloth->generateBendingConstraints(2, cloth->appendMaterial());
    cloth->setTotalMass(1e-3 * n * n);
    cloth->m_cfg.piterations = 4;
    cloth->m_cfg.kDF = 0.3;  // friction, as ours
    cloth->m_cfg.collisions = btSoftBody::fCollision::CL_SS | btSoftBody::fCollision::CL_SELF;
    cloth->generateClusters(64);
    // Patch node (ix, iy) = iy * n + ix: our corners (0,0) and (0,n-1) are x = -0.5, z = ∓0.5.
    const int ca = 0, cb = (n - 1) * n;
    cloth->setMass(ca, 0);
    cloth->setMass(cb, 0);
    world.addSoftBody(cloth);
    const btVector3 a0 = cloth->m_nodes[ca].m_x, b0 = cloth->m_nodes[cb].m_x;
    std::vector<Triangle> tris;
    for (int f = 0; f < cloth->m_faces.size(); ++f) {
      const auto& face = cloth->m_faces[f];
      tris.push_back({static_cast<int>(face.m_n[0] - &cloth->m_nodes[0]),
                      static_cast<int>(face.m_n[1] - &cloth->m_nodes[0]),
                      static_cast<int>(face.m_n[2] - &cloth->m_nodes[0])});
    }
    std::vector<Vec3> x(cloth->m_nodes.size());
    double t = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < kPeerSteps; ++s) {
      const double u = std::min(1.0, t / 0.6);
      cloth->m_nodes[ca].m_x = a0 + btVector3(0, 0, 0.35 * u);
      cloth->m_nodes[cb].m_x = b0 - btVector3(0, 0, 0.35 * u);
      world.stepSimulation(1e-3, 1, 1e-3);
      t += 1e-3;
      if (s % 100 == 99) {
        for (int i = 0; i < cloth->m_nodes.size(); ++i) {
          const btVector3& p = cloth->m_nodes[i].m_x;
          x[i] = Vec3(p.x(), p.y(), p.z());
        }
        bad = std::max(bad, pass_throughs<3>(x, tris));
      }
    }
    steps_per_s = kPeerSteps / std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    world.removeSoftBody(cloth);
    delete cloth;
  }
  state.counters["steps_per_s"] = steps_per_s;
  state.counters["pass_throughs"] = bad;
}
BENCHMARK(BM_Peer3DCloth_Bullet)->Arg(64)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace s4d

BENCHMARK_MAIN();
