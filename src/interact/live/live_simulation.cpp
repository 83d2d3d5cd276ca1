// The live simulation as the haptic loop's scene (the tick: the hand, the band or the carried
// patch, the felt force, exploring, the sketch mode); its Core and physics thread are in
// interact/live/live_core.hpp, its requests in live_requests.hpp.
#include "interact/live/live_simulation.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "interact/live/curve_explorer_scene.hpp"
#include "interact/live/curve_sketch_scene.hpp"
#include "interact/live/live_core.hpp"
#include "interact/live/surface_explorer.hpp"

namespace s4d {

namespace {

using namespace live_detail;

template <int D>
class LiveSimulation final : public HapticScene, public LiveHandover, public SketchHost {
 public:
  LiveSimulation(const Scene& scene, const Scenario* scenario, const LiveOptions& o)
      : options_(o), mapping_(o.mapping), frame4_(o.frame),
        button_carry_(std::clamp(o.button_carry, 0, kMaxCarryRings)),
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

  void reset() override { on(live::Reset{}); }

  CurveSketch& curve_sketch() override { return sketch_; }

  // The one place a request is applied: the hand's, the view's and the sketch's here on the
  // loop's thread; the World's passed on to the core (on the physics thread when it has one).
  void command(const SceneCommand& c) override {
    if (const live::Request* r = live::request(c)) std::visit([this](const auto& q) { this->on(q); }, *r);
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
        if (v >= 0) take(v, (device.buttons & 2u) ? live::GrabMode::kAlongRay : live::GrabMode::kShadow, button_carry_);
        grabbed_by_button_ = held_ >= 0;
      } else if (button_action_ == DeviceButton::kExplore) {
        start_exploring(at);
        explored_by_button_ = exploring_;
      }
    }
    if (!button && button_ && grabbed_by_button_) {
      held_ = -1;
      grabbed_by_button_ = false;
      to_core(live::Release{});
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
    out.grab_mode = static_cast<int>(mode_);
    out.carry_rings = held_ >= 0 ? carry_rings_ : 0;
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
  // [requests] The hand's, the view's and the sketch's; the World's go on to the core.
  void on(const live::Grab& r) {
    const Vec3 hand = live::vec(r.hand);
    if (r.vertex >= 0 && r.vertex < nv_ && hand.allFinite()) take(r.vertex, r.mode, r.carry_rings);
  }
  void on(const live::GrabNearest& r) {
    if (!live::vec(r.point).allFinite() || !std::isfinite(r.reach)) return;
    const int v = nearest(live::vec(r.point), r.reach);
    if (v >= 0) take(v, r.mode, r.carry_rings);
  }
  void on(const live::Release& r) {
    held_ = -1;
    to_core(r);  // the core lets a curve rest where it was left
  }
  void on(const live::SetGrabMode& r) {
    if (held_ >= 0) grab(held_, r.mode);
  }
  void on(const live::SetFrame& r) {
    const Frame<4> f = r.frame();
    if (!f.matrix().allFinite()) return;
    frame4_ = f;
    if (held_ >= 0) grab(held_, mode_);  // keep holding where the vertex is now
  }
  void on(const live::SetMapping& r) {
    if (!r.valid()) return;
    mapping_ = r.mapping();
    if (held_ >= 0) grab(held_, mode_);
  }
  void on(const live::StartExploring& r) {
    explored_by_button_ = false;
    if (live::vec(r.at).allFinite()) start_exploring(live::vec(r.at));
    else exploring_ = false;
  }
  void on(const live::StopExploring&) {
    explored_by_button_ = false;
    exploring_ = false;
  }
  void on(const live::SetDeviceButton& r) {
    button_action_ = static_cast<DeviceButton>(std::clamp(static_cast<int>(r.action), 0, 2));
    button_carry_ = std::clamp(r.carry_rings, 0, kMaxCarryRings);
  }
  void on(const live::Reset& r) {
    held_ = -1;
    exploring_ = false;
    to_core(r);
  }
  void on(const live::PlayScript& r) {
    held_ = -1;
    exploring_ = false;
    to_core(r);
  }
  // The sketch mode (interact/live/curve_sketch_scene) holds the hand while it is on.
  void on(const live::SketchBegin& r) {
    sketch_.begin(r.plane_z);
    if (sketch_.active()) held_ = -1, exploring_ = false;
  }
  void on(const live::SketchEnd&) { sketch_.end(); }
  void on(const live::SketchBackspace&) { sketch_.backspace(); }
  void on(const live::SketchClear&) { sketch_.clear(); }
  template <class WorldRequest>
  void on(const WorldRequest& r) { to_core(r); }
  void to_core(const live::Request& r) {
    if (core_) core_->apply(r);
    else thread_->apply(r);
  }

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
  Vec3 shadow(const Vec<D>& p) const {
    if constexpr (D == 4) return frame4_.shadow(p);
    else return p;
  }

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

  // A new grab of vertex v: on the band, or carrying the patch of `carry_rings` rings around it.
  void take(int v, live::GrabMode mode, int carry_rings) {
    carry_rings_ = std::clamp(carry_rings, 0, kMaxCarryRings);
    ++grab_count_;
    grab(v, mode);
  }

  // Holds vertex v from where the hand is now: the band starts slack (no jump on grabbing). Also
  // re-anchors a held vertex (another mode, frame or mapping): a carried patch carries on.
  void grab(int v, live::GrabMode mode) {
    const auto x = positions();
    if (v < 0 || v >= static_cast<int>(x.size())) return;
    held_ = v;
    mode_ = mode;
    // Where it is seen: its shadow (perspective or not) and, in R^4, its depth.
    Vec<D> q = to_view(x[v]);
    q.template head<3>() = shadow(x[v]);
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
    h.carry_rings = carry_rings_;
    h.grab = grab_count_;
    if constexpr (D == 4) {
      h.frame = frame4_.matrix();
      h.perspective = frame4_.perspective();
    }
    h.target = grab_view_;
    if (mode_ == live::GrabMode::kAlongRay) {
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
    if (mode_ == live::GrabMode::kAlongRay) f = Vec3(0, D == 4 ? q[D - 1] : f.z(), 0);
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
  static constexpr int kMaxCarryRings = 1000;         // beyond any mesh, a sane bound

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
  int held_ = -1;
  live::GrabMode mode_ = live::GrabMode::kShadow;
  int carry_rings_ = 0;           // of the held vertex's grab: 0 on the band
  int button_carry_ = 0;          // what a device's button carries (the tool's rings)
  std::uint64_t grab_count_ = 0;
  Vec3 offset_ = Vec3::Zero();  // shadow: vertex minus hand at the grab
  Vec<D> grab_view_ = Vec<D>::Zero();  // the held vertex at the grab: its shadow, then (R^4) its w
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

