// Session: opening documents, starting the loop with the live simulation, and the UI-side
// refresh of positions, rates and checks.
#include "interact/session/session.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "core/error.hpp"
#include "haptics/device_spec.hpp"
#include "haptics/mouse_device.hpp"
#include "interact/live/curve_explorer.hpp"
#include "interact/live/curve_sketch_scene.hpp"
#include "interact/live/surface_explorer.hpp"
#include "knots/knot_table.hpp"
#include "scenario/world_builder.hpp"

namespace s4d {

namespace {

// The window's mouse: a proxy in a cube large enough that the view's whole ball fits in depth.
std::unique_ptr<Device> open_device(const std::string& spec) {
  const DeviceSpec d = parse_device_spec(spec);
  if (d.kind == DeviceSpec::Kind::mouse) {
    MouseProxyConfig c;
    c.half_extent = Vec3::Constant(0.1);
    return std::make_unique<MouseDevice>(c);
  }
  return make_device(d);
}

// The bodies' points as a World state of dimension `dim` (body order, nv × dim values).
std::vector<double> body_positions(const Scene& scene, const std::vector<int>& first, int dim) {
  std::vector<double> out;
  for (std::size_t o = 0; o < scene.objects.size() && o < first.size(); ++o) {
    if (first[o] < 0) continue;
    for_each_point(scene.objects[o].shape, [&](const auto& p) {
      for (int k = 0; k < dim; ++k) out.push_back(k < static_cast<int>(p.size()) ? p[k] : 0.0);
    });
  }
  return out;
}

}  // namespace

// The loop with the session's device around `scene` (the live simulation, or the sketch alone).
void Session::start_loop(std::unique_ptr<HapticScene> scene) {
  std::unique_ptr<Device> device;
  try {
    device = open_device(options_.device);
  } catch (const std::exception& e) {
    device_error_ = std::string(e.what()) + "; using the mouse";
    options_.device = "mouse";
    device = open_device("mouse");
  }
  HapticLoopConfig config;
  config.realtime_priority = options_.realtime_priority;
  sketch_host_ = dynamic_cast<SketchHost*>(scene.get());
  loop_ = std::make_unique<HapticLoop>(std::move(device), std::move(scene), config);
  if (options_.threaded) loop_->start();
}

CurveSketch* Session::curve_sketch() { return sketch_host_ ? &sketch_host_->curve_sketch() : nullptr; }

Document load_document(const std::string& spec) {
  Document d;
  d.spec = spec;
  // "knot:NAME": a knot or link of the table drawn as `knot make NAME` draws it, so that a page
  // address (index.html?open=knot:10_123) or `shadow4d open` can start from any table entry.
  if (spec.starts_with(kTableKnotPrefix)) {
    const std::string name = spec.substr(kTableKnotPrefix.size());
    SceneObject o;
    o.name = name;
    o.shape = make_table_knot(name);
    d.scene.objects.push_back(std::move(o));
    return d;
  }
  d.scene = load_scene_or_object(spec);
  if (is_scenario(d.scene)) d.scenario = scenario_of_scene(d.scene, spec);
  return d;
}

Session::~Session() { close(); }

void Session::close() {
  if (loop_) loop_->stop();
  loop_.reset();
  monitor_.reset();
  snapshot_ = nullptr;
  handover_ = nullptr;
  sketch_host_ = nullptr;
  events_seen_ = 0;
}

void Session::open(Document doc, const SessionOptions& options) {
  close();
  history_.clear();
  doc_ = std::move(doc);
  options_ = options;
  start_shapes_.clear();
  for (const SceneObject& o : doc_.scene.objects) start_shapes_.emplace(o.name, o.shape);
  start(options_.start_playing);
}

void Session::rebuild() {
  close();
  start(options_.start_playing);
}

namespace {

int vertex_count_of(const Shape& shape) {
  return std::visit([](const auto& s) -> int {
    using T = std::decay_t<decltype(s)>;
    if constexpr (std::is_same_v<T, Surface<T::kDim>>) return static_cast<int>(s.vertices.size());
    return -1;
  }, shape);
}

}  // namespace

// The scene as it is, each object at its start shape (by name) where it has one of its size.
Scene Session::reset_scene() const {
  Scene s = doc_.scene;
  for (SceneObject& o : s.objects) {
    const auto it = start_shapes_.find(o.name);
    if (it != start_shapes_.end() && it->second.index() == o.shape.index() &&
        vertex_count_of(it->second) == vertex_count_of(o.shape))
      o.shape = it->second;
  }
  return s;
}

void Session::objects_changed() {
  // The state of each body now, by name: velocities and pins from the last snapshot, or from the
  // state offered and not landed yet (its positions are the scene's shapes already).
  struct Kept {
    int count = 0;
    std::vector<double> velocities;  // count × dimension
    std::vector<int> pinned;         // local indices
  };
  std::map<std::string, Kept> kept;
  bool playing = options_.start_playing;
  double time = -1;
  const int old_dim = dim_;
  if (simulating() && snapshot_ && snapshot_->point_dimension == dim_) {
    const bool pending = state_pending();
    const HapticSnapshot& snap = *snapshot_;
    const std::vector<double>& velocities = pending ? offered_.velocities : snap.velocities;
    std::vector<std::uint8_t> pins(snap.flags.size(), 0);
    if (pending) {
      for (int v : offered_.pinned)
        if (v >= 0 && static_cast<std::size_t>(v) < pins.size()) pins[static_cast<std::size_t>(v)] = 1;
    } else {
      for (std::size_t v = 0; v < pins.size(); ++v) pins[v] = snap.flags[v] & 1;
    }
    playing = pending ? offered_.play : snap.status.playing;
    time = pending ? offered_.time : snap.status.sim_time;
    for (std::size_t o = 0; o < body_names_.size(); ++o) {
      if (first_[o] < 0) continue;
      Kept k;
      k.count = count_[o];
      const auto at = static_cast<std::size_t>(first_[o]) * static_cast<std::size_t>(dim_);
      const auto n = static_cast<std::size_t>(count_[o]) * static_cast<std::size_t>(dim_);
      if (at + n <= velocities.size())
        k.velocities.assign(velocities.begin() + static_cast<std::ptrdiff_t>(at),
                            velocities.begin() + static_cast<std::ptrdiff_t>(at + n));
      else
        k.velocities.assign(n, 0.0);
      for (int i = 0; i < count_[o]; ++i) {
        const auto v = static_cast<std::size_t>(first_[o] + i);
        if (v < pins.size() && pins[v]) k.pinned.push_back(i);
      }
      kept.emplace(body_names_[o], std::move(k));
    }
  }
  std::erase_if(start_shapes_, [&](const auto& e) {  // removed: a later namesake starts afresh
    return std::none_of(doc_.scene.objects.begin(), doc_.scene.objects.end(),
                        [&](const SceneObject& o) { return o.name == e.first; });
  });
  for (const SceneObject& o : doc_.scene.objects) start_shapes_.emplace(o.name, o.shape);  // new: as added
  close();
  start(false);
  if (!handover_ || dim_ != old_dim) return;
  auto state = std::make_unique<WorldState>();
  state->play = playing;
  state->time = time;  // the clock goes on
  // Every simulated body's points: surfaces', or curves' when the knots are the bodies.
  state->positions = body_positions(doc_.scene, first_, dim_);
  for (std::size_t o = 0; o < doc_.scene.objects.size(); ++o) {
    if (first_[o] < 0) continue;
    const SceneObject& obj = doc_.scene.objects[o];
    const auto it = kept.find(obj.name);
    const bool same = it != kept.end() && it->second.count == count_[o] &&
                      it->second.velocities.size() == static_cast<std::size_t>(count_[o] * dim_);
    if (same) {
      state->velocities.insert(state->velocities.end(), it->second.velocities.begin(), it->second.velocities.end());
      for (int i : it->second.pinned) state->pinned.push_back(first_[o] + i);
    } else {
      state->velocities.resize(state->velocities.size() + static_cast<std::size_t>(count_[o] * dim_), 0.0);
    }
  }
  offer_state(std::move(state));
}

void Session::add_object(SceneObject obj, const std::string& label) {
  Scene trial = doc_.scene;
  trial.objects.push_back(obj);
  const int dim = simulation_dimension(trial);
  try {
    if (dim == 3) build_world<3>(trial);
    else if (dim == 4) build_world<4>(trial);
  } catch (const std::exception& e) {
    throw Error("cannot add " + obj.name + ": " + e.what());
  }
  record(label);
  doc_.scene.objects.push_back(std::move(obj));
  objects_changed();
}

void Session::start(bool start_playing) {
  physics_error_.clear();
  device_error_.clear();
  rates_ = {};
  offered_revision_ = 0;
  offered_ = {};
  dim_ = simulation_dimension(doc_.scene);
  body_vertex_ranges(doc_.scene, first_, count_);
  body_names_.clear();
  for (const SceneObject& o : doc_.scene.objects) body_names_.push_back(o.name);
  triangles_.clear();
  std::unique_ptr<HapticScene> live;
  if (dim_ == 0) {  // curves only: nothing to simulate, but the hand still sketches through the loop
    start_loop(std::make_unique<CurveSketchScene>());
    return;
  }
  try {
    LiveOptions lo;
    lo.async_physics = options_.async_physics;
    lo.start_playing = start_playing;
    lo.frame = doc_.scene.frame;
    lo.button = device_button_;
    lo.button_carry = device_carry_;
    const Scene reset_to = reset_scene();
    lo.reset_to = &reset_to;
    const Scenario* sc = doc_.scenario ? &*doc_.scenario : nullptr;
    live = make_live_simulation(doc_.scene, sc, lo);
  } catch (const std::exception& e) {
    physics_error_ = e.what();
    return;
  }
  handover_ = dynamic_cast<LiveHandover*>(live.get());
  start_loop(std::move(live));

  std::vector<Vec4> initial;
  std::vector<Triangle> tris;
  MonitorCurves curves;
  for (std::size_t o = 0; o < doc_.scene.objects.size(); ++o) {
    if (first_[o] < 0) continue;
    for_each_point(doc_.scene.objects[o].shape, [&](const auto& p) {
      Vec4 q = Vec4::Zero();
      q.head(p.size()) = p;
      initial.push_back(q);
    });
    std::visit([&](const auto& s) {
      using T = std::decay_t<decltype(s)>;
      if constexpr (std::is_same_v<T, Surface<T::kDim>>) {
        for (const Triangle& t : s.triangles)
          if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
            tris.push_back({t[0] + first_[o], t[1] + first_[o], t[2] + first_[o]});
      } else {
        int at = first_[o];
        for (const auto& c : s.components) {
          const int n = static_cast<int>(c.points.size()), m = static_cast<int>(c.segment_count());
          const int id = static_cast<int>(curves.chains.size());
          curves.chains.push_back(make_chain(m, c.closed, c.length(), doc_.scene.physics.thickness));
          for (int k = 0; k < m; ++k) {
            curves.segments.push_back({at + k, at + (k + 1) % n});
            curves.places.push_back({id, k});
          }
          at += n;
        }
      }
    }, doc_.scene.objects[o].shape);
  }
  triangles_ = tris;
  monitor_ = std::make_unique<SessionMonitor>(std::move(tris), std::move(curves), dim_,
                                              2 * doc_.scene.physics.thickness, doc_.scenario ? &*doc_.scenario : nullptr,
                                              first_, count_, std::move(initial));
  rate_wall_ = std::chrono::steady_clock::now();
  rate_sim_time_ = 0;  // the new World starts at t = 0
  rate_steps_ = 0;
  rate_revision_ = 0;
  last_submit_ = rate_wall_;
}

void Session::refresh() {
  if (!loop_) {
    snapshot_ = nullptr;
    return;
  }
  {
    // Objects added or removed since the simulation started (a sketched knot, a knot from the
    // table, a deleted one): the World takes up the scene as it is now.
    std::vector<int> first, count;
    body_vertex_ranges(doc_.scene, first, count);
    if ((first != first_ || count != count_ || simulation_dimension(doc_.scene) != dim_) && !held()) {
      const bool paused = snapshot_ && snapshot_->status.simulating && !snapshot_->status.playing;
      rebuild();
      if (!loop_) return;
      if (paused) send(live::Pause{});
    }
  }
  const HapticSnapshot& snap = loop_->snapshot();
  snapshot_ = &snap;
  const int d = snap.point_dimension;
  // Until the World has taken a handed-over state (an undo, an edit), the scene shows that state,
  // not the one before it.
  const std::size_t bodies = state_pending() ? 0 : std::min(doc_.scene.objects.size(), first_.size());
  if (bodies > 0)
    copy_positions_into(std::span(first_).first(bodies), count_, snap.points, d, doc_.scene);
  const auto now = std::chrono::steady_clock::now();
  if (snap.status.sim_steps < rate_steps_ || snap.status.sim_time < rate_sim_time_ ||
      snap.status.state_revision != rate_revision_) {
    // A reset, or a state put in (an undo, a body added): measure afresh, never across the jump.
    rate_wall_ = now;
    rate_steps_ = snap.status.sim_steps;
    rate_sim_time_ = snap.status.sim_time;
    rate_revision_ = snap.status.state_revision;
  }
  const double wall = std::chrono::duration<double>(now - rate_wall_).count();
  if (wall >= 1.0) {
    rates_.real_time_ratio = (snap.status.sim_time - rate_sim_time_) / wall;
    rates_.steps_per_second = static_cast<double>(snap.status.sim_steps - rate_steps_) / wall;
    rate_wall_ = now;
    rate_sim_time_ = snap.status.sim_time;
    rate_steps_ = snap.status.sim_steps;
  }
  refresh_crossings();
  if (monitor_ && std::chrono::duration<double>(now - last_submit_).count() >= 0.2) {
    monitor_->submit(snap.points, snap.status.sim_time);
    last_submit_ = now;
  }
}

// While exploring, the explorer needs the shadow's curves of the surface as it is now: rebuilt a
// few times a second, and at once when the view turns.
void Session::refresh_crossings() {
  if (!handover_ || !snapshot_ || !snapshot_->status.exploring || snapshot_->point_dimension != 4) return;
  const auto now = std::chrono::steady_clock::now();
  const bool turned = (doc_.scene.frame.matrix() - crossings_frame_.matrix()).cwiseAbs().maxCoeff() > 1e-12 ||
                      doc_.scene.frame.perspective() != crossings_frame_.perspective();
  if (!turned && now - last_crossings_ < std::chrono::milliseconds(250)) return;
  std::vector<Vec4> x(snapshot_->points.size() / 4);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < 4; ++k) x[i][k] = snapshot_->points[4 * i + static_cast<std::size_t>(k)];
  try {
    handover_->offer_crossings(
        std::make_unique<CrossingTable>(build_crossing_table(handover_->triangles(), x, doc_.scene.frame)));
  } catch (const std::exception&) {  // a state the finder cannot read: keep the last table
  }
  crossings_frame_ = doc_.scene.frame;
  last_crossings_ = now;
}

bool Session::offer_curve_image(std::unique_ptr<CurveImage> image) {
  if (!handover_ || !image) return false;
  handover_->offer_curve_image(std::move(image));
  return true;
}

std::vector<SceneEvent> Session::take_events() {
  std::vector<SceneEvent> out;
  if (!snapshot_) return out;
  const SceneStatus& st = snapshot_->status;
  constexpr auto ring = static_cast<std::uint64_t>(SceneStatus::kRecentEvents);
  if (st.event_count < events_seen_) events_seen_ = 0;  // a new simulation
  if (st.event_count - events_seen_ > ring) {
    lost_events_ += st.event_count - events_seen_ - ring;
    events_seen_ = st.event_count - ring;
  }
  for (; events_seen_ < st.event_count; ++events_seen_) out.push_back(st.events[events_seen_ % ring]);
  return out;
}

SessionFile Session::save_state() const {
  SessionFile f;
  f.scene = doc_.scene;
  f.scene.view.fit_radius = 0;
  f.opened = doc_.spec;
  if (snapshot_) {
    f.simulation.dim = snapshot_->point_dimension;
    f.simulation.time = snapshot_->status.sim_time;
    if (state_pending()) {
      if (offered_.time >= 0) f.simulation.time = offered_.time;
      f.simulation.positions = offered_.positions;
      f.simulation.velocities = offered_.velocities;
      if (f.simulation.velocities.empty()) f.simulation.velocities.assign(offered_.positions.size(), 0.0);
      f.simulation.pinned = offered_.pinned;
      f.simulation.playing = offered_.play;
    } else {
      f.simulation.positions = snapshot_->points;
      f.simulation.velocities = snapshot_->velocities;
      for (std::size_t v = 0; v < snapshot_->flags.size(); ++v)
        if (snapshot_->flags[v] & 1) f.simulation.pinned.push_back(static_cast<int>(v));
      f.simulation.playing = snapshot_->status.playing;
      if (snapshot_->status.held_vertex >= 0) f.simulation.held.push_back(snapshot_->status.held_vertex);
    }
  }
  if (save_window) save_window(f);
  // The view's rotation is in the scene's frame already (the window writes it in each frame).
  f.view.base_frame = doc_.scene.frame;
  f.view.trackball = doc_.scene.view.trackball;
  f.view.zoom = doc_.scene.view.zoom;
  // Shared, not copied: the autosave takes it every interval.
  History::Saved h = history_.to_save();
  f.history = std::move(h.labels);
  f.history_states = std::move(h.states);
  f.history_head = static_cast<int>(h.head);
  f.saved_at = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  return f;
}

void Session::open_saved(const SessionFile& saved, const std::string& path, const SessionOptions& options) {
  Document d;
  d.scene = saved.scene;
  d.spec = path;
  if (is_scenario(d.scene)) d.scenario = scenario_of_scene(d.scene, path);
  SessionOptions o = options;
  o.start_playing = false;  // until the saved state is in place
  open(std::move(d), o);
  const SimulationState& sim = saved.simulation;
  if (handover_ && sim.dim == dim_ && !sim.positions.empty()) {
    auto w = std::make_unique<WorldState>();
    w->positions = sim.positions;
    w->velocities = sim.velocities;
    w->pinned = sim.pinned;
    for (int v : sim.held)
      if (std::find(w->pinned.begin(), w->pinned.end(), v) == w->pinned.end()) w->pinned.push_back(v);
    w->play = sim.playing;
    w->time = sim.time;
    w->reshape = curves_are_bodies(doc_.scene);
    offer_state(std::move(w));
  }
  // Undo goes on where it was left (a file without the states, from before version 3, has none).
  if (!saved.history_states.empty()) history_.load(saved.history, saved.history_states, static_cast<std::size_t>(saved.history_head));
}

void Session::offer_state(std::unique_ptr<WorldState> state) {
  if (!handover_ || !state) return;
  // An offer that replaces one not yet taken keeps its clock: an undo right after a session was
  // reopened (its history is saved with it) must not drop the simulated time the reopened state
  // carried, which the World would then start again from zero.
  if (state->time < 0 && state_pending() && offered_.time >= 0) state->time = offered_.time;
  state->revision = ++offered_revision_;
  offered_ = *state;
  handover_->offer_state(std::move(state));
}

bool Session::state_pending() const {
  return handover_ && offered_revision_ > 0 &&
         (!snapshot_ || snapshot_->status.state_revision < offered_revision_);
}

DocumentState Session::capture() const {
  DocumentState d;
  d.scene = doc_.scene;
  if (state_pending())
    d.pinned = offered_.pinned;
  else if (snapshot_)
    for (std::size_t v = 0; v < snapshot_->flags.size(); ++v)
      if (snapshot_->flags[v] & 1) d.pinned.push_back(static_cast<int>(v));
  if (capture_view) capture_view(d);
  return d;
}

void Session::record(const std::string& label) { history_.record(label, capture()); }

bool Session::undo() {
  auto s = history_.undo(capture());
  if (!s) return false;
  restore(std::move(*s));
  return true;
}

bool Session::redo() {
  auto s = history_.redo(capture());
  if (!s) return false;
  restore(std::move(*s));
  return true;
}

// The same bodies (object count, kinds, vertex counts): the running World is put in the state;
// otherwise (objects were created or deleted) the simulation restarts from the state's scene.
void Session::restore(DocumentState state) {
  std::vector<int> first, count;
  body_vertex_ranges(state.scene, first, count);
  const bool same_bodies = simulating() && first == first_ && count == count_ &&
                           state.scene.objects.size() == doc_.scene.objects.size() &&
                           simulation_dimension(state.scene) == dim_;
  const bool physics_changed = !(state.scene.physics == doc_.scene.physics);
  doc_.scene = std::move(state.scene);
  if (!same_bodies) {
    rebuild();
    if (loop_) send(live::Pause{});
  } else if (physics_changed) {
    send(live::SetPhysics::from(doc_.scene.physics));
  }
  if (handover_) {
    auto w = std::make_unique<WorldState>();
    w->positions = body_positions(doc_.scene, first_, dim_);
    w->pinned = state.pinned;
    if (curves_are_bodies(doc_.scene)) {  // clay: it rests as it was, and stays editable
      w->reshape = true;
      w->play = !snapshot_ || snapshot_->status.playing;
    }
    offer_state(std::move(w));
  }
  if (restore_view) restore_view(state);
}

void Session::shapes_edited() {
  if (!handover_) return;
  auto w = std::make_unique<WorldState>();
  w->positions = body_positions(doc_.scene, first_, dim_);
  w->reshape = true;
  w->play = !snapshot_ || snapshot_->status.playing;
  if (snapshot_)
    for (std::size_t v = 0; v < snapshot_->flags.size(); ++v)
      if (snapshot_->flags[v] & 1) w->pinned.push_back(static_cast<int>(v));
  offer_state(std::move(w));
}

MonitorResult Session::checks() const { return monitor_ ? monitor_->latest() : MonitorResult{}; }

void Session::run_owned_ticks(double seconds) {
  if (!loop_ || options_.threaded || loop_->running() || !(seconds > 0)) return;
  constexpr double kMostSeconds = 0.1;
  const double rate = loop_->config().rate_hz;
  owed_ticks_ = std::min(owed_ticks_ + seconds * rate, kMostSeconds * rate);
  const auto n = static_cast<std::uint64_t>(owed_ticks_);
  owed_ticks_ -= static_cast<double>(n);
  if (n > 0) loop_->run_ticks(n);
}

bool Session::send(const live::Request& request) { return loop_ && loop_->send(live::command(request)); }

void Session::set_device_button(DeviceButton action, int carry_rings) {
  if (action == device_button_ && carry_rings == device_carry_) return;
  device_button_ = action;
  device_carry_ = carry_rings;
  send(live::SetDeviceButton{action, carry_rings});
}

void Session::set_device(const std::string& spec) {
  auto device = open_device(spec);  // throws with the reason
  if (loop_) loop_->replace_device(std::move(device));
  options_.device = spec;
  device_error_.clear();
}

void Session::set_mapping(const DeviceMapping& m) {
  if (held()) return;
  mapping_ = m;
  send(live::SetMapping::from(m));
}

void Session::set_hand(const Vec3& p, bool pressed) { set_hand_buttons(p, pressed ? 1u : 0u); }

void Session::set_hand_buttons(const Vec3& p, std::uint32_t buttons) {
  if (loop_ && p.allFinite()) loop_->set_pointer(mapping_.to_device(p), buttons);
}

Vec3 Session::vertex_shadow(int v) const { return vertex_view(v).head<3>(); }

Vec4 Session::vertex_view(int v) const {
  const int o = object_of_vertex(v);
  if (o < 0 || o >= static_cast<int>(doc_.scene.objects.size()))
    return Vec4::Constant(std::numeric_limits<double>::quiet_NaN());
  // Indexed, not walked: the overlay asks for every pinned vertex each frame (a carried patch
  // pins hundreds).
  std::size_t local = static_cast<std::size_t>(v - first_[static_cast<std::size_t>(o)]);
  Vec4 at = Vec4::Constant(std::numeric_limits<double>::quiet_NaN());
  const auto view = [&](const auto& p) {
    if constexpr (std::decay_t<decltype(p)>::RowsAtCompileTime == 4) {
      const Vec4 q = doc_.scene.frame.to_view(p);
      at << doc_.scene.frame.project(q), q[3];
    } else {
      at << p, 0;
    }
  };
  std::visit([&](const auto& sh) {
    using T = std::decay_t<decltype(sh)>;
    if constexpr (std::is_same_v<T, Surface<T::kDim>>) {
      if (local < sh.vertices.size()) view(sh.vertices[local]);
    } else {
      for (const auto& c : sh.components) {
        if (local < c.points.size()) return view(c.points[local]);
        local -= c.points.size();
      }
    }
  }, doc_.scene.objects[static_cast<std::size_t>(o)].shape);
  return at;
}

int Session::first_vertex(int object) const {
  return object >= 0 && object < static_cast<int>(first_.size()) ? first_[static_cast<std::size_t>(object)] : -1;
}

int Session::vertex_count(int object) const {
  return object >= 0 && object < static_cast<int>(count_.size()) ? count_[static_cast<std::size_t>(object)] : 0;
}

int Session::object_of_vertex(int v) const {
  for (std::size_t o = 0; o < first_.size(); ++o)
    if (first_[o] >= 0 && v >= first_[o] && v < first_[o] + count_[o]) return static_cast<int>(o);
  return -1;
}

bool Session::pinned(int v) const {
  return snapshot_ && v >= 0 && v < static_cast<int>(snapshot_->flags.size()) && (snapshot_->flags[static_cast<std::size_t>(v)] & 1);
}

}  // namespace s4d
