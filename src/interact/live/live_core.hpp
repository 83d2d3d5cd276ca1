// The live simulation's owner of the World (Core: steps, commands, the hand's band or carried
// patch, relax, the scenario's script and set-up) and the thread that runs it on its own
// (PhysicsThread). Private to interact/live/live_simulation.cpp.
#pragma once
#include "interact/live/live_simulation.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "core/error.hpp"
#include "haptics/spsc_queue.hpp"
#include "haptics/triple_buffer.hpp"
#include "interact/live/handover.hpp"
#include "knots/relax.hpp"
#include "physics/patch.hpp"
#include "scenario/script_driver.hpp"
#include "scenario/world_builder.hpp"

namespace s4d::live_detail {

inline void set_message(char (&m)[160], const std::string& text) { std::snprintf(m, sizeof m, "%s", text.c_str()); }

inline void set_message(SceneStatus& s, const std::string& text) {
  std::snprintf(s.message, sizeof s.message, "%s", text.c_str());
}

// The hand's pull on the held vertex, evaluated where the vertex is now by whichever thread steps
// the World (so the spring is stable whatever the threads' timing). It acts in view coordinates:
// in the shadow (the paper's 3D external force: w stays free) or, along w, holding the shadow.
template <int D>
struct Hand {
  int vertex = -1;
  Mat<D> frame = Mat<D>::Identity();    // view axes in world coordinates (columns)
  Vec<D> target = Vec<D>::Zero();       // view coordinates
  Vec<D> target_v = Vec<D>::Zero();     // view coordinates, per s
  Vec<D> weight = Vec<D>::Ones();       // 1 on the view axes the band pulls along
  // R^4 seen in perspective from an eye at this distance along w (0: orthographic). Then the
  // target's first three coordinates are the hand's point in the shadow, and the vertex is pulled
  // to the point of its own depth under it (Frame::lift): the shadow follows the hand exactly.
  double perspective = 0;
  double k = 0, b = 0, max_force = 0;
  // Carrying: the patch of this many rings of mesh edges around the vertex follows the hand
  // kinematically, each vertex by its weight, and stays held where the hand lets go. 0: the band.
  int carry_rings = 0;
  std::uint64_t grab = 0;  // counts the grabs, so that a new grab of the same vertex starts a new patch

  // The target (or its velocity) in view coordinates for the vertex at depth w.
  Vec<D> in_view(const Vec<D>& t, double w) const {
    if (!(perspective > 0)) return t;
    Vec<D> q = t;
    q.template head<D - 1>() /= Frame<D>::magnification(perspective, w);
    return q;
  }
};

// The band's force on the vertex at world position x, velocity v, in world coordinates.
template <int D>
Vec<D> band_force(const Hand<D>& h, const Vec<D>& x, const Vec<D>& v) {
  const Vec<D> q = h.frame.transpose() * x, qv = h.frame.transpose() * v;
  Vec<D> f = (h.k * (h.in_view(h.target, q[D - 1]) - q) - h.b * (qv - h.in_view(h.target_v, q[D - 1]))).cwiseProduct(h.weight);
  const double n = f.norm();
  if (!std::isfinite(n)) return Vec<D>::Zero();
  if (n > h.max_force) f *= h.max_force / n;
  return h.frame * f;
}

// What the owner of the World publishes for the haptic side and the snapshots.
template <int D>
struct LiveState {
  std::vector<Vec<D>> x, v;          // nv each
  std::vector<std::uint8_t> pinned;  // nv
  SceneStatus status;
};

template <int D>
class Core {
 public:
  Core(const Scene& scene, const Scenario* scenario, bool playing, const Scene* reset_to)
      : start_(reset_to ? *reset_to : scene), settings_(scene.physics), world_(build_world<D>(scene)), playing_(playing) {
    if (reset_to) added_ = scene;
    if (scenario) scenario_ = *scenario;
    status_.simulating = true;
    start_by_hand();
    reserve_carry();
  }

  const World<D>& world() const { return world_.world; }
  int vertex_count() const { return world_.world.vertex_count(); }
  double time_step() const { return world_.world.model().params.time_step; }

  void set_hand(const Hand<D>& h) {
    if (hand_.vertex >= 0 && hand_.vertex != h.vertex) world_.world.set_external_force(hand_.vertex, Vec<D>::Zero());
    hand_ = h;
  }

  // The requests for the World; the hand's, the view's and the sketch's stay on the haptic side
  // (LiveSimulation::command), which passes the rest on.
  void apply(const live::Request& r) {
    std::visit([this](const auto& q) { this->on(q); }, r);
  }

  // The World put in `s` (an undo, a restored session), paused there.
  void set_state(const WorldState& s) {
    status_.state_revision = s.revision;  // landed, even when refused (its message says why)
    World<D>& w = world_.world;
    const std::size_t n = static_cast<std::size_t>(w.vertex_count());
    if (s.positions.size() != n * D || (!s.velocities.empty() && s.velocities.size() != n * D)) {
      set_message(status_, "a state of another size was refused (" + std::to_string(s.positions.size() / D) +
                               " vertices for " + std::to_string(n) + ")");
      return;
    }
    std::vector<Vec<D>> x(n), v(n, Vec<D>::Zero());
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < D; ++k) {
        x[i][k] = s.positions[i * D + static_cast<std::size_t>(k)];
        if (!s.velocities.empty()) v[i][k] = s.velocities[i * D + static_cast<std::size_t>(k)];
      }
    const std::vector<Vec<D>> before(w.positions().begin(), w.positions().end());
    const std::vector<Vec<D>> before_v(w.velocities().begin(), w.velocities().end());
    try {
      w.set_state(x, v);
      if (s.reshape) world_.apply_settings(settings_);  // the springs rest in the edited shape
    } catch (const std::exception& e) {
      w.set_state(before, before_v);
      set_message(status_, std::string("the edit was refused: ") + e.what());
      return;
    }
    w.set_time(s.time);
    if (relaxing_) stop_relax();
    for (int i = 0; i < w.vertex_count(); ++i) w.unpin(i);
    for (int p : s.pinned)
      if (p >= 0 && p < w.vertex_count()) w.pin(p);
    if (script_) script_->release(w);
    script_.reset();
    hand_ = Hand<D>{};
    carrying_ = false;
    owed_ = 0;
    playing_ = s.play;
  }

  // Adds dt of haptic time (s) to what the simulation owes; at most 0.1 s is owed (beyond it
  // the simulation runs in slow motion rather than racing to catch up).
  void owe(double dt) {
    if (playing_) owed_ = std::min(owed_ + dt * time_scale_, 0.1);
  }
  // One World step when one is owed (or a single step was asked for). True when it stepped.
  bool step_if_owed() {
    const double ts = time_step();
    const bool owed = playing_ && owed_ >= ts * (1 - 1e-6);  // sums of ticks round a little
    if (!owed && single_steps_ == 0) return false;
    if (owed) owed_ = std::max(0.0, owed_ - ts);
    else --single_steps_;
    World<D>& w = world_.world;
    if (relaxing_) relax_forces_now();
    if (hand_.vertex >= 0 && hand_.vertex < w.vertex_count())
      w.set_external_force(hand_.vertex, band_force(hand_, w.positions()[hand_.vertex], w.velocities()[hand_.vertex]));
    if (script_) script_->apply(w, (w.data().steps + 1) * ts);
    if (setup_) {
      if (hand_.vertex >= 0) setup_->hand_takes(w, hand_.vertex);
      setup_->apply(w, (w.data().steps + 1) * ts);
    }
    carry(w, ts);  // last: the hand's patch wins over a hold of the set-up
    w.step();
    return true;
  }
  double owed() const { return owed_; }

  const SceneStatus& status() {
    const Data<D>& d = world_.world.data();
    status_.sim_time = d.time;
    status_.sim_steps = d.steps;
    status_.playing = playing_;
    status_.script_running = script_.has_value();
    status_.script_time = script_ ? d.time : 0;
    status_.contacts = d.last_contacts;
    status_.rollbacks = d.warnings.rollbacks;
    status_.ccd_freezes = d.warnings.ccd_freezes;
    status_.global_freezes = d.warnings.global_freezes;
    status_.rejected_inputs = d.warnings.rejected_inputs;
    status_.lag = owed_;
    status_.relaxing = relaxing_;
    int pins = 0;
    for (std::uint8_t p : d.pinned) pins += p != 0;
    status_.pinned = pins;
    return status_;
  }

  void publish(LiveState<D>& s) {
    const World<D>& w = world_.world;
    s.x.assign(w.positions().begin(), w.positions().end());
    s.v.assign(w.velocities().begin(), w.velocities().end());
    s.pinned.assign(w.data().pinned.begin(), w.data().pinned.end());
    s.status = status();
  }

 private:
  // [requests]
  void on(const live::Play&) { playing_ = true; }
  void on(const live::Pause&) { playing_ = false; }
  void on(const live::StepOnce&) { single_steps_ += 1; }
  void on(const live::Reset&) { restart(false); }
  void on(const live::PlayScript&) { restart(true); }
  void on(const live::StopScript&) {  // the user takes over where the script was: its set-up holds on
    if (!script_) return;
    script_->release(world_.world);
    script_.reset();
    start_by_hand();
  }
  void on(const live::SetTimeScale& r) {
    if (std::isfinite(r.scale)) time_scale_ = std::clamp(r.scale, 0.01, 4.0);
  }
  void on(const live::Pin& r) {
    World<D>& w = world_.world;
    if (r.vertex < 0 || r.vertex >= w.vertex_count()) return;
    const bool pin = r.action == live::PinAction::kPin || (r.action == live::PinAction::kToggle && !w.is_pinned(r.vertex));
    if (pin) w.pin(r.vertex);
    else w.unpin(r.vertex);
  }
  void on(const live::ClearPins&) {
    World<D>& w = world_.world;
    for (int i = 0; i < w.vertex_count(); ++i) w.unpin(i);
  }
  void on(const live::Release&) {
    World<D>& w = world_.world;
    if (w.model().curves()) {  // clay: it stays where the hand left it
      w.rest_here();
      w.stop();
    }
  }
  void on(const live::StartRelaxing&) { start_relax(); }
  void on(const live::StopRelaxing&) { stop_relax(); }
  void on(const live::SetPhysics& r) {
    if (!r.finite()) {
      set_message(status_, "physics settings refused: a value is not finite");
      return;
    }
    try {
      const PhysicsSettings s = r.settings();
      world_.apply_settings(s);
      settings_ = s;
      ++status_.settings_revision;
      status_.message[0] = 0;
    } catch (const std::exception& e) {
      set_message(status_, e.what());
    }
  }
  template <class Other>
  void on(const Other&) {}  // the haptic side's

  // Back to the start (rebuilt with the settings in force), with the script when asked.
  void restart(bool with_script) {
    Scene s = start_;
    s.physics = settings_;
    try {
      SceneWorld<D> fresh = build_world<D>(s);
      world_ = std::move(fresh);
    } catch (const std::exception& e) {
      // The start of the bodies there before with one added since may meet: back to when it was.
      if (!added_) {
        set_message(status_, e.what());
        return;
      }
      Scene a = *added_;
      a.physics = settings_;
      try {
        SceneWorld<D> fresh = build_world<D>(a);
        world_ = std::move(fresh);
        set_message(status_, std::string("reset to when the last object was added (from the very start: ") + e.what() + ")");
      } catch (const std::exception& e2) {
        set_message(status_, e2.what());
        return;
      }
    }
    hand_ = Hand<D>{};
    carrying_ = false;
    reserve_carry();
    owed_ = 0;
    script_.reset();
    relaxing_ = false;
    if (with_script && scenario_) {
      setup_.reset();
      try {
        script_.emplace(*scenario_, world_);
      } catch (const std::exception& e) {
        set_message(status_, e.what());
      }
      playing_ = true;
    } else {
      start_by_hand();
    }
  }

  // [relax] The knot energy of knots/relax.hpp as forces in this World, so that its collision
  // avoidance guards every step as ever: every few steps the energy's step (what `knot relax`
  // moves a point by) becomes each vertex's velocity over those steps, and the springs rest where
  // the curve is (they would pull it back); every step a force gives each vertex that velocity.
  void start_relax() {
    if constexpr (D != 3) {
      set_message(status_, "relax works on knots: closed curves of R^3");
    } else {
      Curve<3> now;
      const auto x = world_.world.positions();
      std::size_t v = 0;
      for (const Body<D>& b : world_.bodies) {
        const auto* c = std::get_if<Curve<D>>(&b);
        if (!c) {
          set_message(status_, "relax works on knots: this scene simulates surfaces");
          return;
        }
        for (const Polyline<D>& comp : c->components) {
          Polyline<3> p{{}, comp.closed};
          for (std::size_t i = 0; i < comp.points.size(); ++i) p.points.push_back(x[v++]);
          now.components.push_back(std::move(p));
        }
      }
      try {
        relax_setup(now, relax_model_, relax_data_);
      } catch (const std::exception& e) {
        set_message(status_, std::string("cannot relax: ") + e.what());
        return;
      }
      relax_target_.assign(x.size(), Vec<D>::Zero());
      relax_countdown_ = 0;
      // The energy costs O(n²) an evaluation: a large knot is evaluated less often (as often as a
      // 220-point one every other step), so that the physics keeps up with the clock.
      const double n = static_cast<double>(x.size());
      relax_every_ = std::max(2, static_cast<int>(std::lround(n * n / 25000)));
      relaxing_ = true;
      status_.message[0] = 0;
    }
  }
  void stop_relax() {
    if (!relaxing_) return;
    relaxing_ = false;
    World<D>& w = world_.world;
    w.clear_external_forces();
    w.rest_here();
    w.stop();
  }
  void relax_forces_now() {
    World<D>& w = world_.world;
    const auto x = w.positions(), v = w.velocities();
    if constexpr (D == 3) {
      if (relax_countdown_-- <= 0) {
        relax_countdown_ = relax_every_ - 1;
        std::copy(x.begin(), x.end(), relax_data_.x.begin());
        relax_forces(relax_model_, relax_data_);
        const double period = relax_every_ * time_step();
        bool limited = false;
        for (std::size_t i = 0; i < x.size(); ++i)
          relax_target_[i] = relax_move(relax_model_, relax_data_, static_cast<int>(i), limited) / period;
        w.rest_here();
      }
    }
    // Reaches the target velocity in one step (symplectic Euler: v += dt f / m).
    const double dt = time_step();
    for (std::size_t i = 0; i < x.size(); ++i)
      w.set_external_force(static_cast<int>(i), (w.model().mass[i] / dt) * (relax_target_[i] - v[i]));
  }

  // [carry] The hand carries a patch: pinned from the grab, each vertex following the hand's
  // displacement times its weight, at most kCarrySpeed fast (a mouse may jump; the World's
  // collision handling then sees a hand's motion, and the band shows the lag). Where the hand lets
  // go the patch stays held: a sculptor's local deformation (paper Fig. 12), undone as one step.
  void carry(World<D>& w, double ts) {
    const bool wants = hand_.vertex >= 0 && hand_.vertex < w.vertex_count() && hand_.carry_rings > 0;
    if (!wants) {
      carrying_ = false;
      return;
    }
    const auto x = w.positions();
    if (!carrying_ || carry_grab_ != hand_.grab) {  // every new grab counts up, whatever the vertex
      const int centre[] = {hand_.vertex};
      grow_patch<D>(w.model(), centre, hand_.carry_rings, patch_, patch_scratch_);
      carry_start_.clear();
      for (int v : patch_.vertices) {
        carry_start_.push_back(x[static_cast<std::size_t>(v)]);
        w.pin(v);
      }
      carried_.setZero();
      carry_grab_ = hand_.grab;
      carrying_ = true;
    }
    // Where the hand wants the centre, as a displacement from its start, on the axes it moves.
    const Vec<D> q0 = hand_.frame.transpose() * carry_start_.front();
    const Vec<D> want = hand_.frame * (hand_.in_view(hand_.target, q0[D - 1]) - q0).cwiseProduct(hand_.weight);
    Vec<D> step = want - carried_;
    const double most = kCarrySpeed * ts, n = step.norm();
    if (!std::isfinite(n)) return;
    if (n > most) step *= most / n;
    carried_ += step;
    for (std::size_t i = 0; i < patch_.vertices.size(); ++i)
      w.set_target(patch_.vertices[i], carry_start_[i] + patch_.weights[i] * carried_);
  }
  void reserve_carry() {
    const Model<D>& m = world_.world.model();
    const std::size_t nv = static_cast<std::size_t>(m.nv);
    patch_scratch_.reserve(m.nv);
    patch_.vertices.reserve(nv);
    patch_.rings.reserve(nv);
    patch_.weights.reserve(nv);
    carry_start_.reserve(nv);
  }

  // The scenario's set-up for doing it by hand (ByHand in scenario.hpp), in force from the start
  // so that its holds show as pins while the scenario waits, paused.
  void start_by_hand() {
    setup_.reset();
    if (!scenario_) return;
    try {
      setup_.emplace(*scenario_, world_, ScriptMode::kByHand);
      if (setup_->empty()) setup_.reset();
      else setup_->apply(world_.world, 0);
    } catch (const std::exception& e) {
      setup_.reset();
      set_message(status_, e.what());
    }
  }

  Scene start_;                 // where Reset goes
  std::optional<Scene> added_;  // the scene when an object was last added, if Reset cannot start
  PhysicsSettings settings_;
  std::optional<Scenario> scenario_;
  SceneWorld<D> world_;
  bool relaxing_ = false;
  RelaxModel relax_model_;
  RelaxData relax_data_;
  std::vector<Vec<D>> relax_target_;  // nv, m/s
  int relax_countdown_ = 0;
  int relax_every_ = 2;  // steps between evaluations of the knot energy
  std::optional<ScriptDriver<D>> script_;  // Play script: the scenario's scripted hand
  std::optional<ScriptDriver<D>> setup_;   // otherwise: the set-up kept while a person does it
  Hand<D> hand_;
  static constexpr double kCarrySpeed = 2;  // scene units (m) per s: a brisk hand
  bool carrying_ = false;
  std::uint64_t carry_grab_ = 0;
  Patch patch_;
  PatchScratch patch_scratch_;
  std::vector<Vec<D>> carry_start_;  // the patch's positions at the grab
  Vec<D> carried_ = Vec<D>::Zero();  // world: how far the hand has carried the centre
  bool playing_ = true;
  double time_scale_ = 1;
  double owed_ = 0;  // s of simulated time the clock calls for
  int single_steps_ = 0;
  SceneStatus status_;
};

// Runs a Core on its own thread: requests and the hand come in lock-free, the state goes out
// through a triple buffer, and the haptic clock it follows is an atomic count of nanoseconds.
template <int D>
class PhysicsThread {
 public:
  explicit PhysicsThread(std::unique_ptr<Core<D>> core) : core_(std::move(core)), state_(first_state(*core_)) {
    thread_ = std::thread([this] { run(); });
  }
  ~PhysicsThread() {
    stop_.store(true);
    thread_.join();
  }
  void apply(const live::Request& r) {
    if (!requests_.try_push(r)) dropped_.fetch_add(1, std::memory_order_relaxed);
  }
  void set_hand(const Hand<D>& h) { hand_.write(h); }
  void offer_state(std::unique_ptr<WorldState> s) { states_.offer(std::move(s)); }
  void advance_clock(double dt) { clock_ns_.fetch_add(static_cast<std::uint64_t>(std::llround(dt * 1e9)), std::memory_order_release); }
  const LiveState<D>& state() { return state_.read(); }

 private:
  static LiveState<D> first_state(Core<D>& core) {
    LiveState<D> s;
    core.publish(s);
    return s;
  }
  void run() {
    std::uint64_t last = 0;  // the clock's start, whatever ticks ran before this thread did
    while (!stop_.load(std::memory_order_relaxed)) {
      bool changed = false;
      while (auto r = requests_.try_pop()) {
        core_->apply(*r);
        changed = true;
      }
      if (WorldState* st = states_.take()) {
        core_->set_state(*st);
        states_.retire(st);
        changed = true;
      }
      core_->set_hand(hand_.read());
      const std::uint64_t now = clock_ns_.load(std::memory_order_acquire);
      core_->owe(static_cast<double>(now - last) * 1e-9);
      last = now;
      changed = core_->step_if_owed() || changed;
      if (changed) {
        core_->publish(state_.back());
        state_.publish();
      } else {
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
    }
  }

  std::unique_ptr<Core<D>> core_;
  SpscQueue<live::Request, 64> requests_;
  Handover<WorldState> states_;
  TripleBuffer<Hand<D>> hand_;
  TripleBuffer<LiveState<D>> state_;
  std::atomic<std::uint64_t> clock_ns_{0};
  std::atomic<std::uint64_t> dropped_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace s4d::live_detail
