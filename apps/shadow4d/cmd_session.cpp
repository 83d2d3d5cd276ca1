// `shadow4d session info FILE.s4d`: what a saved session holds. `shadow4d session run INPUT`: a
// session headless — the live simulation on the real 1 kHz loop, edited by a scripted hand
// (grabs, pulls, pins, undo), autosaved every --interval seconds; --restore first takes up the
// autosave a killed run left. What the window does, without a window: the kill test drives it.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <random>
#include <thread>

#include "command.hpp"
#include "core/error.hpp"
#include "interact/session/autosave.hpp"
#include "interact/live/live_simulation.hpp"
#include "interact/session/session.hpp"

namespace s4d::cli {
namespace {

namespace fs = std::filesystem;

std::string when(double unix_seconds) {
  char b[64];
  std::snprintf(b, sizeof b, "%.3f s since 1970", unix_seconds);
  return b;
}

void info(const std::string& path) {
  const SessionFile f = read_session(path);
  std::cout << path << ": a session of shadow4d (version " << kSessionVersion << "), opened from '" << f.opened
            << "', saved at " << when(f.saved_at) << (f.clean_exit ? "" : " (the run did not quit normally)") << "\n";
  std::cout << "  " << f.scene.objects.size() << " object(s):";
  for (const SceneObject& o : f.scene.objects) std::cout << " '" << o.name << "'";
  std::cout << "\n";
  const SimulationState& s = f.simulation;
  if (s.dim > 0)
    std::cout << "  simulation in R^" << s.dim << ": " << s.positions.size() / static_cast<std::size_t>(s.dim)
              << " vertices, t = " << s.time << " s, " << s.pinned.size() << " pinned, "
              << (s.playing ? "playing" : "paused") << "\n";
  std::cout << "  history: " << f.history_head << " step(s) done, " << f.history.size() - static_cast<std::size_t>(f.history_head)
            << " undone; tool '" << f.tool << "'\n";
}

struct RunArgs {
  std::string input;
  double seconds = 10;
  std::string autosave;
  double interval = 1;
  bool restore = false;
  double edit_every = 0.5;
  unsigned seed = 1;
  std::string device = "mouse";
};

void run(const RunArgs& a) {
  Session session;
  SessionOptions o;
  o.device = a.device;
  Autosaver autosaver({a.autosave, a.interval, 3});
  if (a.restore) {
    // The work of a run that is no longer running, as the slot was claimed (read once, there).
    if (const auto& saved = autosaver.unfinished()) {
      session.open_saved(*saved, saved->opened, o);
      std::cout << "restored " << autosaver.path().string() << " saved at " << when(saved->saved_at) << " ("
                << saved->simulation.positions.size() / std::max(1, saved->simulation.dim) << " vertices, t = "
                << saved->simulation.time << " s)" << std::endl;
    } else if (!autosaver.note().empty()) {
      std::cout << autosaver.note() << "; starting afresh" << std::endl;
    }
  }
  if (!session.simulating() && session.document().spec.empty()) session.open(load_document(a.input), o);
  if (!session.simulating())
    throw Error("nothing to simulate: " + (session.physics_error().empty() ? std::string("no surface") : session.physics_error()));
  session.send(live::Play{});
  // When the work begins (a restore of a large history takes a while): what a kill can lose is
  // what was done since then or since the last autosave, whichever is later.
  std::cout << "running from " << when(std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count())
            << std::endl;
  std::mt19937 rng(a.seed);
  const auto t0 = std::chrono::steady_clock::now();
  auto next_edit = t0;
  int edits = 0, undos = 0;
  bool holding = false;
  Vec3 hand = Vec3::Zero();
  while (std::chrono::steady_clock::now() - t0 < std::chrono::duration<double>(a.seconds)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    session.refresh();
    const auto now = std::chrono::steady_clock::now();
    const HapticSnapshot* snap = session.snapshot();
    if (snap && now >= next_edit && !snap->points.empty()) {
      next_edit = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(a.edit_every));
      const int nv = static_cast<int>(snap->points.size()) / snap->point_dimension;
      std::uniform_int_distribution<int> vertex(0, nv - 1), action(0, 9);
      const int act = action(rng);
      if (holding) {
        session.send(live::Release{});
        holding = false;
      } else if (act < 6) {  // grab a vertex and pull it a little
        const int v = vertex(rng);
        hand = session.vertex_shadow(v);
        session.record("drag vertex " + std::to_string(v));
        session.set_hand(hand, true);
        session.send(live::Grab{v, act == 5 ? live::GrabMode::kAlongRay : live::GrabMode::kShadow, live::point(hand)});
        holding = true;
        ++edits;
      } else if (act < 8) {
        const int v = vertex(rng);
        session.record("pin vertex " + std::to_string(v));
        session.send(live::Pin{v, live::PinAction::kToggle});
        ++edits;
      } else if (session.undo()) {
        session.send(live::Play{});
        ++undos;
      }
    }
    if (holding) {
      std::normal_distribution<double> step(0, 0.01);
      hand += Vec3(step(rng), step(rng), step(rng));
      session.set_hand(hand, true);
    }
    autosaver.tick(session, now);
  }
  session.refresh();
  autosaver.save_now(session, true);
  const HapticSnapshot* snap = session.snapshot();
  const MonitorResult c = session.checks();
  std::cout << "session: " << (snap ? snap->status.sim_steps : 0) << " steps, " << edits << " edits, " << undos
            << " undos, " << autosaver.saves() << " autosaves to " << autosaver.path().string() << "; true intersections "
            << c.true_intersections << std::endl;
  if (!autosaver.last_error().empty()) throw Error(autosaver.last_error());
}

const CommandRegistrar kSession(
    "session", "saved sessions (.s4d): info FILE, or run INPUT headless with autosaves and --restore",
    [](CLI::App& sub) {
      sub.require_subcommand(1);
      auto* inf = sub.add_subcommand("info", "what a saved session holds");
      auto path = std::make_shared<std::string>();
      inf->add_option("file", *path, "a .s4d file")->required();
      inf->callback([path] { info(*path); });
      auto* r = sub.add_subcommand("run", "a live session headless: scripted edits, autosaves, --restore");
      auto a = std::make_shared<RunArgs>();
      r->add_option("input", a->input, "scene, scenario, mesh or generator to start from")->required();
      r->add_option("--seconds", a->seconds, "wall seconds to run")->check(CLI::Range(0.0, 1e6));
      r->add_option("--autosave", a->autosave, "the autosave file (default: the window's)");
      r->add_option("--interval", a->interval, "s between autosaves")->check(CLI::Range(0.01, 1e5));
      r->add_flag("--restore", a->restore, "take up the autosave an unfinished run left, if any");
      r->add_option("--edit-every", a->edit_every, "s between scripted edits")->check(CLI::Range(0.01, 1e5));
      r->add_option("--seed", a->seed, "of the scripted edits");
      r->add_option("--device", a->device, "the loop's device");
      r->callback([a] { run(*a); });
    });

}  // namespace
}  // namespace s4d::cli
