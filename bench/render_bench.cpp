// Render benchmarks (issue 25, the surface studio's display): the frame cost of the spun trefoil
// (spun-trefoil:n=64,m=12, 746 vertices) as a live simulation shows it, every vertex moving each
// frame: build_scene_geometry alone, and a whole frame (build, upload, draw, glFinish) offscreen
// through EGL (llvmpipe without a GPU), with the shadow's intersection curves off and on, opaque
// and see-through. Counters: vertices, and the bytes each frame uploads (indices: 0 while the
// triangles are unchanged).
#include <benchmark/benchmark.h>

#include <GL/gl.h>

#include <cstdint>
#include <string>
#include <variant>

#include "io/scene.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "render/scene_geometry.hpp"

namespace {

using namespace s4d;

constexpr int kWidth = 1024, kHeight = 768;

Scene spun_trefoil(bool intersections, double opacity) {
  Scene sc = load_scene_or_object("spun-trefoil:n=64,m=12");
  sc.frame.rotate(Plane{0, 3}, 0.4);
  sc.frame.rotate(Plane{1, 2}, 0.3);
  sc.view.intersections = intersections;
  sc.view.opacity = opacity;
  return sc;
}

std::size_t vertex_count(const Scene& sc) {
  return std::get<Surface<4>>(sc.objects.at(0).shape).vertices.size();
}

// A small 4D turn each frame moves every vertex of the shadow and leaves the triangles, as a
// simulation step does.
void next_frame(Scene& sc) { sc.frame.rotate(Plane{0, 3}, 1e-3); }

void BM_BuildSceneGeometry(benchmark::State& state) {
  Scene sc = spun_trefoil(state.range(0) != 0, 1.0);
  for (auto _ : state) {
    next_frame(sc);
    SceneGeometry g = build_scene_geometry(sc, static_cast<double>(kWidth) / kHeight);
    benchmark::DoNotOptimize(g.objects.data());
  }
  state.counters["vertices"] = static_cast<double>(vertex_count(sc));
}
BENCHMARK(BM_BuildSceneGeometry)->ArgName("intersections")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// arg 0: intersections off/on; arg 1: opacity in percent.
void BM_Frame(benchmark::State& state) {
  Scene sc = spun_trefoil(state.range(0) != 0, state.range(1) / 100.0);
  OffscreenContext context;
  RenderTarget target(kWidth, kHeight, 4);
  Renderer renderer;
  target.bind();
  renderer.draw(sc, kWidth, kHeight);  // the first frame fills every buffer
  glFinish();
  double vertex_bytes = 0, index_bytes = 0, index_uploads = 0;
  for (auto _ : state) {
    next_frame(sc);
    renderer.draw(sc, kWidth, kHeight);
    glFinish();  // llvmpipe draws on its own threads: wait for the picture
    vertex_bytes += static_cast<double>(renderer.uploads().vertex_bytes);
    index_bytes += static_cast<double>(renderer.uploads().index_bytes);
    index_uploads += renderer.uploads().index_uploads;
  }
  const double frames = static_cast<double>(state.iterations());
  state.counters["vertices"] = static_cast<double>(vertex_count(sc));
  state.counters["vertex_bytes/frame"] = vertex_bytes / frames;
  state.counters["index_bytes/frame"] = index_bytes / frames;
  state.counters["index_uploads/frame"] = index_uploads / frames;
  state.SetLabel(context.renderer());
}
BENCHMARK(BM_Frame)
    ->ArgNames({"intersections", "opacity_pct"})
    ->Args({0, 100})
    ->Args({1, 100})
    ->Args({0, 50})
    ->Args({1, 50})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
