// Curve display modes (issue 26 point 2): the per-frame cost of drawing a 500-point knot (the
// trefoil as torus-knot:p=2,q=3,n=500) as lit tubes, as the plain shadow and as the crossing
// diagram, the camera turning a little every frame so that the diagram is recomputed from it:
// build_scene_geometry alone, curve_diagram alone (the crossings of the view, the gaps and the
// strands) and a whole frame offscreen (build, upload, draw, glFinish; EGL llvmpipe).
#include <benchmark/benchmark.h>

#include <GL/gl.h>

#include "io/scene.hpp"
#include "render/curve_diagram.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "render/scene_geometry.hpp"

namespace {

using namespace s4d;

constexpr int kWidth = 1024, kHeight = 768;

Scene knot(CurveMode mode) {
  Scene sc = load_scene_or_object("torus-knot:p=2,q=3,n=500");
  sc.view.curve_mode = mode;
  sc.view.tube_radius = 0.1;
  sc.view.trackball = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Vec3::UnitX()));
  return sc;
}

// The user turning the view: every frame re-projects the curve.
void next_frame(Scene& sc) {
  sc.view.trackball = (Eigen::Quaterniond(Eigen::AngleAxisd(2e-3, Vec3::UnitY())) * sc.view.trackball).normalized();
}

void count(benchmark::State& state, const SceneGeometry& g) {
  state.counters["crossings"] = static_cast<double>(g.diagram.gaps.size());
  state.counters["strands"] = static_cast<double>(g.diagram.strands.size());
  state.counters["merged"] = static_cast<double>(g.diagram.merged_gaps);
  state.counters["vertices"] = static_cast<double>(g.objects.at(0).mesh.vertex_count());
}

// arg: 0 tubes, 1 shadow, 2 diagram
void BM_BuildSceneGeometry(benchmark::State& state) {
  Scene sc = knot(static_cast<CurveMode>(state.range(0)));
  count(state, build_scene_geometry(sc, static_cast<double>(kWidth) / kHeight));  // of the first view
  for (auto _ : state) {
    next_frame(sc);
    SceneGeometry g = build_scene_geometry(sc, static_cast<double>(kWidth) / kHeight);
    benchmark::DoNotOptimize(g.objects.data());
  }
}
BENCHMARK(BM_BuildSceneGeometry)->ArgName("mode")->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

// The diagram alone, from a fixed camera.
void BM_CurveDiagram(benchmark::State& state) {
  Scene sc = knot(CurveMode::kDiagram);
  const SceneGeometry g = build_scene_geometry(sc, static_cast<double>(kWidth) / kHeight);
  for (auto _ : state) {
    CurveDiagram d = curve_diagram(sc, g.camera, g.diagram.half_width, state.range(0) != 0);
    benchmark::DoNotOptimize(d.strands.data());
  }
  count(state, g);
}
BENCHMARK(BM_CurveDiagram)->ArgName("gaps")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_Frame(benchmark::State& state) {
  Scene sc = knot(static_cast<CurveMode>(state.range(0)));
  OffscreenContext context;
  RenderTarget target(kWidth, kHeight, 4);
  Renderer renderer;
  target.bind();
  renderer.draw(sc, kWidth, kHeight);
  glFinish();
  for (auto _ : state) {
    next_frame(sc);
    renderer.draw(sc, kWidth, kHeight);
    glFinish();
  }
  state.SetLabel(context.renderer());
}
BENCHMARK(BM_Frame)->ArgName("mode")->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
