// The live simulation: [SECTION] commands (UI side), [SECTION] core (the World's owner),
// [SECTION] physics thread (async), [SECTION] haptic scene (the tick: hand, band, felt force).
#include "interact/live_simulation.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <thread>

#include "core/error.hpp"
#include "haptics/spsc_queue.hpp"
#include "haptics/triple_buffer.hpp"
#include "interact/curve_sketch_scene.hpp"
#include "interact/handover.hpp"
#include "interact/curve_explorer_scene.hpp"
#include "interact/surface_explorer.hpp"
#include "knots/relax.hpp"
#include "physics/patch.hpp"
#include "scenario/script_driver.hpp"
#include "scenario/world_builder.hpp"

namespace s4d {

// [SECTION] commands
namespace {

constexpr const char* kIntegrators[] = {"symplectic-euler", "paper-euler"};

int integrator_code(const std::string& name) {
  const Integrator i = parse_integrator(name);
  return i == Integrator::kPaperEuler ? 1 : 0;
}

}  // namespace

SceneCommand live_command(LiveCode code, int i0, int i1) {
  SceneCommand c;
  c.code = static_cast<int>(code);
  c.i[0] = i0;
  c.i[1] = i1;
  return c;
}

SceneCommand live_time_scale(double scale) {
  SceneCommand c = live_command(LiveCode::kTimeScale);
  c.x[0] = scale;
  return c;
}

SceneCommand live_settings(const PhysicsSettings& s) {
  SceneCommand c = live_command(LiveCode::kSettings, integrator_code(s.integrator));
  const double v[] = {s.time_step, s.thickness, s.gravity[0], s.gravity[1], s.gravity[2], s.gravity[3],
                      s.mass, s.stiffness, s.shear_scale, s.bending_scale, s.beta, s.damping,
                      s.spring_damping, s.friction, s.max_step_motion, s.collisions ? 1.0 : 0.0};
  std::copy(std::begin(v), std::end(v), c.x);
  return c;
}

SceneCommand live_grab(int vertex, int mode, const Vec3& hand, double carry_radius) {
  SceneCommand c = live_command(LiveCode::kGrab, vertex, mode);
  for (int k = 0; k < 3; ++k) c.x[k] = hand[k];
  c.x[3] = carry_radius;
  return c;
}

SceneCommand live_grab_nearest(const Vec3& point, double radius, int mode, double carry_radius) {
  SceneCommand c = live_command(LiveCode::kGrabNearest, 0, mode);
  for (int k = 0; k < 3; ++k) c.x[k] = point[k];
  c.x[3] = radius;
  c.x[4] = carry_radius;
  return c;
}

SceneCommand live_frame(const Frame<4>& frame) {
  SceneCommand c = live_command(LiveCode::kFrame);
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) c.x[4 * r + k] = frame.matrix()(r, k);
  return c;
}

SceneCommand live_explore(bool on, const Vec3& at) {
  SceneCommand c = live_command(LiveCode::kExplore, 0, on ? 1 : 0);
  for (int k = 0; k < 3; ++k) c.x[k] = at[k];
  return c;
}

SceneCommand live_relax(bool on) { return live_command(LiveCode::kRelax, 0, on ? 1 : 0); }

SceneCommand live_mapping(const DeviceMapping& m) {
  SceneCommand c = live_command(LiveCode::kMapping);
  for (int k = 0; k < 3; ++k) c.x[k] = m.centre[k];
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) c.x[3 + 3 * r + k] = m.axes(r, k);
  c.x[12] = m.metres_per_unit;
  for (int k = 0; k < 3; ++k) c.x[13 + k] = m.workspace_centre[k];
  return c;
}

namespace {

PhysicsSettings settings_of(const SceneCommand& c) {
  PhysicsSettings s;
  s.time_step = c.x[0];
  s.thickness = c.x[1];
  s.gravity = Vec4(c.x[2], c.x[3], c.x[4], c.x[5]);
  s.mass = c.x[6];
  s.stiffness = c.x[7];
  s.shear_scale = c.x[8];
  s.bending_scale = c.x[9];
  s.beta = c.x[10];
  s.damping = c.x[11];
  s.spring_damping = c.x[12];
  s.friction = c.x[13];
  s.max_step_motion = c.x[14];
  s.collisions = c.x[15] != 0;
  s.integrator = kIntegrators[std::clamp(c.i[0], 0, 1)];
  return s;
}

bool finite_command(const SceneCommand& c) {
  for (double v : c.x)
    if (!std::isfinite(v)) return false;
  return true;
}

void set_message(char (&m)[160], const std::string& text) { std::snprintf(m, sizeof m, "%s", text.c_str()); }

void set_message(SceneStatus& s, const std::string& text) {
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
  double k = 0, b = 0, max_force = 0;
  // Carrying: the patch of this radius (along the surface) around the vertex follows the hand
  // kinematically, each vertex by its weight, and stays held where the hand lets go. 0: the band.
  double carry_radius = 0;
  std::uint64_t grab = 0;  // counts the grabs, so that a new grab of the same vertex starts a new patch
};

// The band's force on the vertex at world position x, velocity v, in world coordinates.
template <int D>
Vec<D> band_force(const Hand<D>& h, const Vec<D>& x, const Vec<D>& v) {
  const Vec<D> q = h.frame.transpose() * x, qv = h.frame.transpose() * v;
  Vec<D> f = (h.k * (h.target - q) - h.b * (qv - h.target_v)).cwiseProduct(h.weight);
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

}  // namespace

// [SECTION] core
namespace {

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

  // Sim-level requests; the rest (grab, frame, mapping) are the haptic side's.
  void command(const SceneCommand& c) {
    World<D>& w = world_.world;
    const int nv = w.vertex_count();
    const int v = c.i[0];
    switch (static_cast<LiveCode>(c.code)) {
      case LiveCode::kPlay: playing_ = true; break;
      case LiveCode::kPause: playing_ = false; break;
      case LiveCode::kStepOnce: single_steps_ += 1; break;
      case LiveCode::kReset: restart(false); break;
      case LiveCode::kPlayScript: restart(true); break;
      case LiveCode::kStopScript:  // the user takes over where the script was: its set-up holds on
        if (!script_) break;
        script_->release(w);
        script_.reset();
        start_by_hand();
        break;
      case LiveCode::kTimeScale:
        if (std::isfinite(c.x[0])) time_scale_ = std::clamp(c.x[0], 0.01, 4.0);
        break;
      case LiveCode::kPin:
      case LiveCode::kUnpin:
      case LiveCode::kTogglePin: {
        if (v < 0 || v >= nv) break;
        const bool pin = static_cast<LiveCode>(c.code) == LiveCode::kPin ||
                         (static_cast<LiveCode>(c.code) == LiveCode::kTogglePin && !w.is_pinned(v));
        if (pin) w.pin(v);
        else w.unpin(v);
        break;
      }
      case LiveCode::kClearPins:
        for (int i = 0; i < nv; ++i) w.unpin(i);
        break;
      case LiveCode::kRelease:
        if (w.model().curves()) {  // clay: it stays where the hand left it
          w.rest_here();
          w.stop();
        }
        break;
      case LiveCode::kRelax:
        if (c.i[1] == 1) start_relax();
        else stop_relax();
        break;
      case LiveCode::kSettings:
        if (!finite_command(c)) {
          set_message(status_, "physics settings refused: a value is not finite");
          break;
        }
        try {
          const PhysicsSettings s = settings_of(c);
          world_.apply_settings(s);
          settings_ = s;
          ++status_.settings_revision;
          status_.message[0] = 0;
        } catch (const std::exception& e) {
          set_message(status_, e.what());
        }
        break;
      default: break;
    }
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
    const bool wants = hand_.vertex >= 0 && hand_.vertex < w.vertex_count() && hand_.carry_radius > 0;
    if (!wants) {
      carrying_ = false;
      return;
    }
    const auto x = w.positions();
    if (!carrying_ || carry_grab_ != hand_.grab || carry_vertex_ != hand_.vertex) {
      const int centre[] = {hand_.vertex};
      grow_patch<D>(w.model(), x, centre, hand_.carry_radius, patch_, patch_scratch_);
      carry_start_.clear();
      for (int v : patch_.vertices) {
        carry_start_.push_back(x[static_cast<std::size_t>(v)]);
        w.pin(v);
      }
      carried_.setZero();
      carry_grab_ = hand_.grab;
      carry_vertex_ = hand_.vertex;
      carrying_ = true;
    }
    // Where the hand wants the centre, as a displacement from its start, on the axes it moves.
    const Vec<D> q0 = hand_.frame.transpose() * carry_start_.front();
    const Vec<D> want = hand_.frame * (hand_.target - q0).cwiseProduct(hand_.weight);
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
    patch_scratch_.reserve(m.nv, m.adjacency.size());
    patch_.vertices.reserve(nv);
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
  int carry_vertex_ = -1;
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

}  // namespace

// [SECTION] physics thread
namespace {

// Runs a Core on its own thread: commands and the hand come in lock-free, the state goes out
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
  void command(const SceneCommand& c) {
    if (!commands_.try_push(c)) dropped_.fetch_add(1, std::memory_order_relaxed);
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
      while (auto c = commands_.try_pop()) {
        core_->command(*c);
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
  SpscQueue<SceneCommand, 64> commands_;
  Handover<WorldState> states_;
  TripleBuffer<Hand<D>> hand_;
  TripleBuffer<LiveState<D>> state_;
  std::atomic<std::uint64_t> clock_ns_{0};
  std::atomic<std::uint64_t> dropped_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace

// [SECTION] haptic scene
namespace {

template <int D>
class LiveSimulation final : public HapticScene, public LiveHandover, public SketchHost {
 public:
  LiveSimulation(const Scene& scene, const Scenario* scenario, const LiveOptions& o)
      : options_(o), mapping_(o.mapping), frame4_(o.frame),
        button_carry_(std::isfinite(o.button_carry) ? std::clamp(o.button_carry, 0.0, kMaxCarryRadius) : 0.0),
        button_action_(o.button) {
    auto core = std::make_unique<Core<D>>(scene, scenario, o.start_playing, o.reset_to);
    nv_ = core->vertex_count();
    triangles_ = core->world().model().triangles;
    curves_ = core->world().model().curves();
    if (o.async_physics) {
      thread_ = std::make_unique<PhysicsThread<D>>(std::move(core));
      current_ = &thread_->state();  // before the loop thread starts: it becomes the one reader
    } else {
      core_ = std::move(core);
    }
    params_[kBandStiffness] = {"K", 100, 0, 2000, "N per scene unit"};
    params_[kBandDamping] = {"B", 0.5, 0, 20, "N s per scene unit"};
    // Scenes are in metres and kilograms (1 g a vertex): the chain of Fig. 8 weighs 2.9 N, so the
    // band carries 5 N, enough to lift it with room to spare. The hand feels that scaled by
    // kForceScale and the device mapping's stiffness cap, then clamped by the safety (felt()).
    params_[kBandMaxForce] = {"max force", 5, 0.01, 50, "N on the vertex"};
    params_[kForceScale] = {"force scale", 1, 0, 10, "device N per vertex N"};
    params_[kExploreStiffness] = {"explore K", 200, 0, 1000, "N/m at the device: the navigation spring"};
    params_[kExploreDamping] = {"explore B", 1.0, 0, 10, "N s/m at the device"};
    if constexpr (D == 4)
      if (!triangles_.empty()) explorer_ = std::make_unique<SurfaceExplorer>(triangles_, nv_);
  }


  std::span<const Triangle> triangles() const override { return triangles_; }
  void offer_crossings(std::unique_ptr<CrossingTable> table) override {
    if (explorer_ && table) crossings_.offer(std::move(table));
  }
  void offer_curve_image(std::unique_ptr<CurveImage> image) override {
    if constexpr (D == 3)
      if (image) curve_nav_.offer(std::move(image));
  }
  void offer_state(std::unique_ptr<WorldState> state) override {
    if (!state) return;
    // The hand lets go on the loop's thread (step() reads this), which owns held_ and exploring_.
    let_go_.store(true, std::memory_order_release);
    if (thread_) thread_->offer_state(std::move(state));
    else states_.offer(std::move(state));
  }

  std::string_view name() const override { return "live-simulation"; }
  std::span<SceneParam> params() override { return params_; }
  int point_count() const override { return nv_; }
  int point_dimension() const override { return D; }

  void reset() override { command(live_command(LiveCode::kReset)); }

  CurveSketch& curve_sketch() override { return sketch_; }

  void command(const SceneCommand& c) override {
    if (is_sketch_command(c)) {  // the sketch mode (interact/curve_sketch_scene) holds the hand
      sketch_.command(c);
      if (sketch_.active()) held_ = -1, exploring_ = false;
      return;
    }
    switch (static_cast<LiveCode>(c.code)) {
      case LiveCode::kGrab:
        if (c.i[0] >= 0 && c.i[0] < nv_ && finite_command(c)) take(c.i[0], c.i[1], c.x[3]);
        return;
      case LiveCode::kGrabNearest:
        if (finite_command(c)) {
          const int v = nearest(Vec3(c.x[0], c.x[1], c.x[2]), c.x[3]);
          if (v >= 0) take(v, c.i[1], c.x[4]);
        }
        return;
      case LiveCode::kRelease:
        held_ = -1;
        break;  // the core lets a curve rest where it was left
      case LiveCode::kGrabMode:
        if (held_ >= 0) grab(held_, c.i[1]);
        return;
      case LiveCode::kFrame:
        if (finite_command(c)) {
          Mat<4> r;
          for (int i = 0; i < 16; ++i) r(i / 4, i % 4) = c.x[i];
          frame4_ = Frame<4>(r);
          if (held_ >= 0) grab(held_, mode_);  // keep holding where the vertex is now
        }
        return;
      case LiveCode::kMapping:
        if (finite_command(c) && c.x[12] > 0) {
          DeviceMapping m;
          for (int k = 0; k < 3; ++k) m.centre[k] = c.x[k];
          for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) m.axes(r, k) = c.x[3 + 3 * r + k];
          m.metres_per_unit = c.x[12];
          for (int k = 0; k < 3; ++k) m.workspace_centre[k] = c.x[13 + k];
          mapping_ = m;
          if (held_ >= 0) grab(held_, mode_);
        }
        return;
      case LiveCode::kExplore:
        explored_by_button_ = false;
        if (c.i[1] == 1 && finite_command(c)) start_exploring(Vec3(c.x[0], c.x[1], c.x[2]));
        else exploring_ = false;
        return;
      case LiveCode::kDeviceButton:
        button_action_ = static_cast<DeviceButton>(std::clamp(c.i[1], 0, 2));
        button_carry_ = std::isfinite(c.x[0]) ? std::clamp(c.x[0], 0.0, kMaxCarryRadius) : 0.0;
        return;
      case LiveCode::kReset:
      case LiveCode::kPlayScript:
        held_ = -1;
        exploring_ = false;
        break;
      default: break;
    }
    if (core_) core_->command(c);
    else thread_->command(c);
  }

  ToolOutput step(const DeviceState& device, double dt) override {
    device_ = device;
    const bool button = device.buttons & 1u;
    if (thread_) current_ = &thread_->state();  // one consistent state for the whole tick
    if (let_go_.exchange(false, std::memory_order_acq_rel)) {
      held_ = -1;
      exploring_ = false;
      grabbed_by_button_ = explored_by_button_ = false;
    }
    if (core_) {
      if (WorldState* st = states_.take()) {
        core_->set_state(*st);
        states_.retire(st);
      }
    }
    if (button && !button_ && held_ < 0 && !exploring_ && !sketch_.active()) {
      // A device's button does what the active tool does with a press (the mouse path sends the
      // tool's command with what is under the cursor instead): grab the vertex nearest its point
      // in the shadow, or start the probe there.
      const Vec3 at = mapping_.to_shadow(device.position);
      if (button_action_ == DeviceButton::kGrab) {
        const int v = nearest(at, kGrabReach / mapping_.metres_per_unit);
        if (v >= 0) take(v, (device.buttons & 2u) ? 1 : 0, button_carry_);
        grabbed_by_button_ = held_ >= 0;
      } else if (button_action_ == DeviceButton::kExplore) {
        start_exploring(at);
        explored_by_button_ = exploring_;
      }
    }
    if (!button && button_ && grabbed_by_button_) {
      held_ = -1;
      grabbed_by_button_ = false;
      const SceneCommand release = live_command(LiveCode::kRelease);
      if (core_) core_->command(release);
      else thread_->command(release);
    }
    if (!button && button_ && explored_by_button_) {
      exploring_ = false;
      explored_by_button_ = false;
    }
    button_ = button;

    const Hand<D> hand = make_hand();
    ToolOutput out;
    out.anchor = device.position;
    if (core_) {
      core_->set_hand(hand);
      core_->owe(dt);
      for (int s = 0; s < options_.max_steps_per_tick && core_->step_if_owed(); ++s) {
      }
    } else {
      thread_->set_hand(hand);
      thread_->advance_clock(dt);
    }
    if (sketch_.active()) {
      band_force_ = 0;
      return sketch_.step(device, dt);
    }
    if (exploring_) {
      explore(device, dt, out);
      band_force_ = 0;
      return out;
    }
    const auto x = positions();
    const auto v = velocities();
    if (held_ >= 0 && held_ < static_cast<int>(x.size())) {
      const Vec<D> f = band_force(hand, x[held_], v[held_]);  // on the vertex, world
      out.force = felt(f);
      out.anchor = mapping_.to_device(shadow(x[held_]));
      out.engaged = true;
      band_force_ = f.norm();
    } else {
      band_force_ = 0;
    }
    return out;
  }

  // The loop publishes points, then flags, then status: the points take the physics thread's
  // newest state and the other two read the same one.
  void copy_points(std::span<double> out) const override {
    if (thread_) current_ = &thread_->state();
    const auto x = positions();
    const std::size_t n = std::min(x.size(), out.size() / D);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < D; ++k) out[i * D + k] = x[i][k];
  }
  void copy_velocities(std::span<double> out) const override {
    const auto v = velocities();
    const std::size_t n = std::min(v.size(), out.size() / D);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < D; ++k) out[i * D + k] = v[i][k];
  }
  void copy_flags(std::span<std::uint8_t> out) const override {
    const auto p = pinned();
    const std::size_t n = std::min(p.size(), out.size());
    for (std::size_t i = 0; i < n; ++i) out[i] = p[i] ? 1 : 0;
  }
  void copy_status(SceneStatus& out) const override {
    out = core_ ? core_->status() : current_->status;
    out.held_vertex = held_;
    out.grab_mode = mode_;
    out.carry_radius = held_ >= 0 ? carry_radius_ : 0;
    const auto x = positions();
    if (held_ >= 0 && held_ < static_cast<int>(x.size())) {
      out.band_to = shadow(x[held_]);
      out.band_from = hand_shadow();
    }
    out.band_force = band_force_;
    if (message_[0] && !out.message[0]) std::copy(std::begin(message_), std::end(message_), out.message);
    out.exploring = exploring_;
    out.probe = probe_;
    out.probe_w = probe_w_;
    out.event_count = event_count_;
    std::copy(std::begin(events_), std::end(events_), out.events);
  }

 private:
  std::span<const Vec<D>> positions() const {
    if (core_) return core_->world().positions();
    return thread_state().x;
  }
  std::span<const Vec<D>> velocities() const {
    if (core_) return core_->world().velocities();
    return thread_state().v;
  }
  std::span<const std::uint8_t> pinned() const {
    if (core_) return core_->world().data().pinned;
    return thread_state().pinned;
  }
  // The physics thread's state as read at the start of this tick: it stays unchanged until the
  // next read on this (the loop's) thread, TripleBuffer's promise.
  const LiveState<D>& thread_state() const { return *current_; }

  // View coordinates of a world point: R^4 through the frame; R^3 objects are seen as they are.
  Vec<D> to_view(const Vec<D>& p) const {
    if constexpr (D == 4) return frame4_.to_view(p);
    else return p;
  }
  Vec<D> to_world(const Vec<D>& q) const {
    if constexpr (D == 4) return frame4_.to_world(q);
    else return q;
  }
  Vec3 shadow(const Vec<D>& p) const { return to_view(p).template head<3>(); }

  Vec3 hand_shadow() const { return mapping_.to_shadow(device_.position) + offset_; }

  // The positions as the explorer reads them (a world of R^4; empty otherwise).
  std::span<const Vec4> positions4() const {
    if constexpr (D == 4) return positions();
    else return {};
  }

  // 4.3.1 and 5.3: the probe walks its sheet towards the hand, the hand feels the navigation
  // spring, each pass of a shadow curve becomes an event for the sound cues.
  // The knot studio's navigation: the probe on the curve's image, a cue per crossing passed.
  void explore_curve(const DeviceState& device, double dt, ToolOutput& out) {
    curve_nav_.install();
    explore_time_ += dt;
    const double mpu = mapping_.metres_per_unit;
    const Vec3 c = mapping_.to_shadow(device.position), v = mapping_.vector_to_shadow(device.velocity);
    const DampedSpring spring{params_[kExploreStiffness].value * mpu * mpu, params_[kExploreDamping].value * mpu * mpu};
    curve_nav_.explorer().set_rearm_distance(1e-3 / mpu);  // a millimetre of the hand
    const Vec3 f = curve_nav_.update(c, v, 1.0 / dt, explore_time_, spring);
    while (auto e = curve_nav_.explorer().pop_event()) {
      SceneEvent& se = events_[event_count_ % SceneStatus::kRecentEvents];
      se = SceneEvent{};
      se.time = e->time;
      se.kind = e->over ? kEventCrossedOver : kEventCrossedUnder;
      const Frame<3>& view = curve_nav_.explorer().image().frame;
      const Vec3 at = view.matrix() * Vec3(e->point[0], e->point[1], view.to_view(c).z());
      for (int k = 0; k < 3; ++k) se.point[k] = at[k];
      se.label = e->label;
      ++event_count_;
    }
    const Vec3 probe = curve_nav_.probe_at(c);
    if (!probe.allFinite()) return;
    probe_ = probe;
    probe_w_ = curve_nav_.explorer().probe_depth();
    out.force = mapping_.vector_to_device(f) / (mpu * mpu);
    if (!out.force.allFinite()) out.force.setZero();
    out.anchor = mapping_.to_device(probe);
    out.engaged = true;
  }

  void explore(const DeviceState& device, double dt, ToolOutput& out) {
    if constexpr (D == 3) return explore_curve(device, dt, out);
    if (!explorer_) return;
    if (CrossingTable* t = crossings_.take()) {
      explorer_->swap_crossings(*t);  // the old table goes back to the UI for freeing
      crossings_.retire(t);
    }
    explore_time_ += dt;
    const double mpu = mapping_.metres_per_unit;
    const Vec3 c = mapping_.to_shadow(device.position), v = mapping_.vector_to_shadow(device.velocity);
    // Felt in N/m at the device: in shadow units the constants scale by mpu², the force back by 1/mpu².
    const DampedSpring spring{params_[kExploreStiffness].value * mpu * mpu, params_[kExploreDamping].value * mpu * mpu};
    explorer_->settings().rearm_distance = 1e-3 / mpu;  // a millimetre of the hand
    const ExplorerStep st = explorer_->update(positions4(), frame4_, c, v, 1.0 / dt, explore_time_, spring);
    while (auto e = explorer_->pop_event()) {
      SceneEvent& se = events_[event_count_ % SceneStatus::kRecentEvents];
      se.time = e->time;
      se.kind = e->above ? kEventPassedAbove : kEventPassedBelow;
      for (int k = 0; k < 3; ++k) se.point[k] = e->point[k];
      se.w_self = e->w_self;
      se.w_other = e->w_other;
      ++event_count_;
    }
    if (!st.ok) return;
    probe_ = st.probe;
    probe_w_ = explorer_->probe_depth(positions4(), frame4_);
    out.force = mapping_.vector_to_device(st.force) / (mpu * mpu);
    if (!out.force.allFinite()) out.force.setZero();
    out.anchor = mapping_.to_device(st.probe);
    out.engaged = true;
  }

  // The probe placed nearest `at` (shadow): on the surface's sheet in R^4 (5.3), on the knot's
  // image offered last in R^3 (4.3.1). Stops holding.
  void start_exploring(const Vec3& at) {
    held_ = -1;
    exploring_ = false;
    if constexpr (D == 3) {
      curve_nav_.install();
      exploring_ = curve_nav_.place(at);
      if (!exploring_) set_message(message_, "no curve to explore here (offer its image first)");
    } else if (!explorer_) {
      set_message(message_, "exploring needs a surface of R^4 (its w is what the sound tells)");
    } else {
      exploring_ = explorer_->place(positions4(), frame4_, at);
    }
  }

  // The vertex nearest `point` in the shadow within `radius`. A knot's shadow is the view's plane:
  // there the distance across the line of sight counts, depth only a little (a device need not
  // find a strand's depth to take it; at a crossing the nearer strand in depth wins).
  int nearest(const Vec3& point, double radius) const {
    const auto x = positions();
    int best = -1;
    double best_d2 = radius * radius;
    const Vec3 depth = mapping_.axes.col(2);
    for (int v = 0; v < static_cast<int>(x.size()); ++v) {
      Vec3 d = shadow(x[v]) - point;
      if constexpr (D == 3)
        if (curves_) d -= 0.9 * d.dot(depth) * depth;
      const double d2 = d.squaredNorm();
      if (d2 < best_d2) {
        best_d2 = d2;
        best = v;
      }
    }
    return best;
  }

  // A new grab of vertex v: on the band, or carrying the patch of `carry_radius` around it.
  void take(int v, int mode, double carry_radius) {
    carry_radius_ = std::isfinite(carry_radius) ? std::clamp(carry_radius, 0.0, kMaxCarryRadius) : 0.0;
    ++grab_count_;
    grab(v, mode);
  }

  // Holds vertex v from where the hand is now: the band starts slack (no jump on grabbing). Also
  // re-anchors a held vertex (another mode, frame or mapping): a carried patch carries on.
  void grab(int v, int mode) {
    const auto x = positions();
    if (v < 0 || v >= static_cast<int>(x.size())) return;
    held_ = v;
    mode_ = mode == 1 ? 1 : 0;
    const Vec<D> q = to_view(x[v]);
    offset_ = q.template head<3>() - mapping_.to_shadow(device_.position);
    grab_view_ = q;
    grab_device_ = device_.position;
  }

  Hand<D> make_hand() const {
    Hand<D> h;
    if (held_ < 0) return h;
    h.vertex = held_;
    h.k = params_[kBandStiffness].value;
    h.b = params_[kBandDamping].value;
    h.max_force = params_[kBandMaxForce].value;
    h.carry_radius = carry_radius_;
    h.grab = grab_count_;
    if constexpr (D == 4) h.frame = frame4_.matrix();
    h.target = grab_view_;
    if (mode_ == 1) {
      // Along the shadow ray: the device's motion along its y axis moves the depth (w; for a world
      // of R^3 the view's depth axis, the camera's); the shadow holds.
      if constexpr (D == 3) {
        h.frame = mapping_.axes;
        h.target = mapping_.axes.transpose() * grab_view_;
      }
      h.target[D - 1] += (device_.position - grab_device_).y() / mapping_.metres_per_unit;
      h.target_v[D - 1] = device_.velocity.y() / mapping_.metres_per_unit;
    } else {
      h.target.template head<3>() = hand_shadow();
      h.target_v.template head<3>() = mapping_.vector_to_shadow(device_.velocity);
      if constexpr (D == 4) h.weight[D - 1] = 0;  // a 3D hand pulls in the shadow; w stays free
    }
    if (!h.target.allFinite() || !h.target_v.allFinite()) h.vertex = -1;
    return h;
  }

  // The band's reaction as the device renders it: the shadow part along the device's axes, the w
  // part (along-w mode) along its y axis; scaled, and never stiffer than the device can render.
  Vec3 felt(const Vec<D>& on_vertex) const {
    const Vec<D> q = to_view(-on_vertex);
    Vec3 f = mapping_.axes.transpose() * Vec3(q.template head<3>());
    if (mode_ == 1) f = Vec3(0, D == 4 ? q[D - 1] : f.z(), 0);
    const double k = std::max(params_[kBandStiffness].value, 1e-9);
    const double stiffness_cap = kMaxFeltStiffness * mapping_.metres_per_unit / k;
    const double scale = std::min(params_[kForceScale].value, stiffness_cap);
    f *= scale;
    return f.allFinite() ? f : Vec3::Zero();
  }

  CurveSketch sketch_;                             // the sketch mode, while the window sketches
  std::vector<Triangle> triangles_;                // the world's, fixed
  std::unique_ptr<SurfaceExplorer> explorer_;      // R^4 only
  Handover<CrossingTable> crossings_;            // from the UI, taken by the tick
  Handover<WorldState> states_;                  // inline: from the UI, applied by the tick
  bool exploring_ = false;
  CurveNavigation curve_nav_;  // R^3: a knot's image, offered by the UI
  double explore_time_ = 0;
  Vec3 probe_ = Vec3::Zero();
  double probe_w_ = 0;
  std::uint64_t event_count_ = 0;
  SceneEvent events_[SceneStatus::kRecentEvents] = {};
  char message_[160] = {};

  static constexpr double kMaxFeltStiffness = 800;  // N/m: what a desktop arm renders stably
  static constexpr double kGrabReach = 0.01;         // m: how near a device's point grabs a vertex
  static constexpr double kMaxCarryRadius = 1e3;     // scene units: beyond any scene, a sane bound

  LiveOptions options_;
  std::unique_ptr<Core<D>> core_;
  std::unique_ptr<PhysicsThread<D>> thread_;
  mutable const LiveState<D>* current_ = nullptr;  // async: the state of this tick (loop thread)
  std::array<SceneParam, kLiveParamCount> params_;
  DeviceMapping mapping_;
  Frame<4> frame4_;
  DeviceState device_;
  int nv_ = 0;
  bool curves_ = false;  // the bodies are curves (a knot: its shadow is the view's plane)
  int held_ = -1, mode_ = 0;
  double carry_radius_ = 0;       // of the held vertex's grab: 0 on the band
  double button_carry_ = 0;       // what a device's button carries (the tool's radius)
  std::uint64_t grab_count_ = 0;
  Vec3 offset_ = Vec3::Zero();  // shadow: vertex minus hand at the grab
  Vec<D> grab_view_ = Vec<D>::Zero();
  Vec3 grab_device_ = Vec3::Zero();
  bool button_ = false, grabbed_by_button_ = false, explored_by_button_ = false;
  DeviceButton button_action_ = DeviceButton::kGrab;
  std::atomic<bool> let_go_{false};  // an offered state: the hand lets go at the next tick
  double band_force_ = 0;
};

}  // namespace

std::unique_ptr<HapticScene> make_live_simulation(const Scene& scene, const Scenario* scenario,
                                                  const LiveOptions& options) {
  const int dim = simulation_dimension(scene);
  if (dim == 0) throw Error("nothing to simulate: the scene has no surface");
  if (dim == 3) return std::make_unique<LiveSimulation<3>>(scene, scenario, options);
  return std::make_unique<LiveSimulation<4>>(scene, scenario, options);
}

}  // namespace s4d
