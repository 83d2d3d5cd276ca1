// What a window's start costs in reading the autosave slots: a session with a long undo history
// (40 states of a 64 x 64 cloth, about 17 MB), read whole (the document a slot offers) and as the
// summary each slot's claim reads; and a start (Autosaver's claim) over three such slots left by
// clean quits, which reads only their summaries.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

#include "interact/session/autosave.hpp"
#include "io/session_file.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

SessionFile long_history_session() {
  SessionFile f;
  SceneObject o;
  o.name = "cloth";
  o.shape = generate("cloth", {{"n", 64}, {"size", 1}});
  f.scene.objects.push_back(o);
  for (int i = 0; i < 40; ++i) {
    auto state = std::make_shared<DocumentState>();
    state->scene = f.scene;
    for (Vec4& p : std::get<Surface<4>>(state->scene.objects[0].shape).vertices) p.z() += 1e-3 * i * p.x();
    f.history.push_back("drag vertex " + std::to_string(i));
    f.history_states.push_back(std::move(state));
  }
  f.history_head = 40;
  f.clean_exit = true;
  return f;
}

const fs::path& session_dir() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / "s4d_session_bench";
    fs::remove_all(d);
    fs::create_directories(d);
    const SessionFile f = long_history_session();
    for (int k = 1; k <= 3; ++k) write_session(f, autosave_slot(d / "auto.s4d", k));
    return d;
  }();
  return dir;
}

void BM_ReadSessionWhole(benchmark::State& state) {
  const fs::path p = session_dir() / "auto.s4d";
  for (auto _ : state) benchmark::DoNotOptimize(read_session(p));
  state.counters["MB"] = static_cast<double>(fs::file_size(p)) / 1e6;
}
BENCHMARK(BM_ReadSessionWhole)->Unit(benchmark::kMillisecond);

void BM_ReadSessionSummary(benchmark::State& state) {
  const fs::path p = session_dir() / "auto.s4d";
  for (auto _ : state) benchmark::DoNotOptimize(read_session_summary(p));
}
BENCHMARK(BM_ReadSessionSummary)->Unit(benchmark::kMillisecond);

void BM_AutosaverStartOverThreeFinishedSlots(benchmark::State& state) {
  const fs::path first = session_dir() / "auto.s4d";
  for (auto _ : state) {
    Autosaver a({first, 30, 0});
    benchmark::DoNotOptimize(a.path());
  }
}
BENCHMARK(BM_AutosaverStartOverThreeFinishedSlots)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace s4d

BENCHMARK_MAIN();
