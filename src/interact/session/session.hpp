// Session: what the window (and the headless tests) work on — the document (a scene, or a
// scenario's scene with its script and verdict), its live simulation run by the haptic loop,
// and the monitor's independent checks. The UI thread owns the Session; the loop thread owns
// the World; they meet only in live::Requests and snapshots (docs/architecture.md).
#pragma once
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "haptics/haptic_loop.hpp"
#include "interact/session/history.hpp"
#include "interact/live/live_simulation.hpp"
#include "interact/session/session_monitor.hpp"
#include "io/scene.hpp"
#include "io/session_file.hpp"
#include "scenario/scenario.hpp"

namespace s4d {

struct CurveImage;
class CurveSketch;
class SketchHost;

struct SessionOptions {
  std::string device = "mouse";  // the haptic loop's device (--device): mouse, sim, replay:FILE, ...
  bool threaded = true;          // run the loop's thread; false: the caller steps it (run_ticks)
  bool async_physics = true;     // step the World on its own thread (see live_simulation.hpp)
  bool start_playing = true;
  bool realtime_priority = true;
};

// A document read from what a user opens: a scene, a scenario, a mesh, a curve or a generator.
struct Document {
  Scene scene;
  std::optional<Scenario> scenario;
  std::string spec;  // what was opened
};
// "knot:NAME" opens a knot or link of the table (3_1, 10_123, L6a4, T(2,5), m3_1) as a curve.
// Throws s4d::Error / ParseError with the reason; nothing is changed then.
inline constexpr std::string_view kTableKnotPrefix = "knot:";
Document load_document(const std::string& spec);

// Timings the window shows, measured over the last second of snapshots.
struct SimulationRates {
  double steps_per_second = 0;
  double real_time_ratio = 0;  // simulated seconds per wall second
};

class Session {
 public:
  Session() = default;
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Takes the document and starts simulating its surfaces (or its curves, when it has no surface:
  // knots are edited as chains in World<3>). A scene whose physics cannot run
  // stays viewable: physics_error() says why and nothing simulates. A device that cannot be
  // opened falls back to the mouse, with the reason in device_error().
  void open(Document doc, const SessionOptions& options);
  // Starts the simulation again from the scene's current shapes; velocities are lost, the view
  // is kept.
  void rebuild();
  // After objects were added to or removed from the scene: simulates the scene as it is now, the
  // bodies still there (matched by name) keeping their velocities and pins and going on playing
  // as they were, the new ones at rest. Reset then returns the old bodies to their start and the
  // new ones to where they were added.
  void objects_changed();
  // Adds `obj` to the scene as one undoable step called `label` (objects_changed). Throws
  // s4d::Error with the reason the scene cannot be simulated with it (it meets a surface already
  // there): nothing changes then.
  void add_object(SceneObject obj, const std::string& label);
  void close();

  Scene& scene() { return doc_.scene; }
  const Scene& scene() const { return doc_.scene; }
  const Document& document() const { return doc_; }
  const std::optional<Scenario>& scenario() const { return doc_.scenario; }

  // A World runs (the loop may also run for the sketch alone: loop() is then set, this is false).
  bool simulating() const { return loop_ != nullptr && dim_ > 0; }
  const std::string& physics_error() const { return physics_error_; }
  const std::string& device_error() const { return device_error_; }
  HapticLoop* loop() { return loop_.get(); }
  int dimension() const { return dim_; }

  // UI thread, once a frame: reads the loop's newest snapshot, copies its positions into the
  // scene's objects, updates the rates and hands the state to the monitor.
  void refresh();
  // Without the loop's thread (options.threaded false, as in the web page, which has no threads):
  // runs the loop's ticks for `seconds` of wall time on the calling thread, the owner's frame loop.
  // At most 0.1 s of ticks a call: a page slower than real time falls behind it, it never stalls
  // catching up. Nothing when the loop has its thread.
  void run_owned_ticks(double seconds);
  // The snapshot of the last refresh (nullptr when not simulating).
  const HapticSnapshot* snapshot() const { return snapshot_; }
  SimulationRates rates() const { return rates_; }
  MonitorResult checks() const;

  // Sends a request to the live simulation (false when not simulating or the queue is full).
  bool send(const live::Request& request);
  // The scene's simulated shapes were edited in place (a crossing changed): the World takes them
  // as they are now, its springs resting there. Until it has, refresh() keeps the edit shown.
  void shapes_edited();
  // The knots' image for the curve explorer (false when not simulating).
  bool offer_curve_image(std::unique_ptr<CurveImage> image);
  // What a device's first button does (the active tool's choice); kept across rebuilds.
  void set_device_button(DeviceButton action, int carry_rings = 0);
  // Replaces the loop's device (throws s4d::Error with the reason; the old one keeps running).
  void set_device(const std::string& spec);
  const std::string& device_spec() const { return options_.device; }

  // [undo] Every user action is one step: a tool calls record() just before it acts (one drag is
  // one step). undo()/redo() put the document, the pins and the view back; a running simulation
  // pauses at the restored state. False when there is nothing to undo / redo.
  void record(const std::string& label);
  bool undo();
  bool redo();
  const History& history() const { return history_; }
  // The document as it is now (shapes from the last refresh, pins from the snapshot).
  DocumentState capture() const;
  // The window's part of a state: its 4D rotation, trackball and zoom.
  std::function<void(DocumentState&)> capture_view;
  std::function<void(const DocumentState&)> restore_view;
  // The window's part of a saved session (its view, the active tool, the tool settings).
  std::function<void(SessionFile&)> save_window;

  // [sessions] The work as it is now (File > Save session, the autosave): the scene with its
  // current shapes, the simulation's state from the last snapshot, the view, the undo history.
  SessionFile save_state() const;
  // Opens a saved session: its document, then the World put in the saved state, and its undo
  // history (within the History's bounds). A vertex the hand held when it was saved is pinned
  // where it was (no hand holds it now; P lets it go).
  void open_saved(const SessionFile& saved, const std::string& path, const SessionOptions& options);

  // The device's workspace laid onto the view (sent to the simulation; the window refits it
  // when the view turns). Kept while a vertex is held, so the hand does not jump.
  void set_mapping(const DeviceMapping& mapping);
  const DeviceMapping& mapping() const { return mapping_; }
  // The mouse's hand: a shadow point the mouse proxy follows, and whether the button is down.
  void set_hand(const Vec3& shadow_point, bool pressed);
  // The same with every button bit (the sketch reads modifiers as buttons: curve_sketch_scene.hpp).
  void set_hand_buttons(const Vec3& shadow_point, std::uint32_t buttons);
  // The loop's sketch (the live simulation's sketch mode, or the sketch scene of a document with
  // nothing to simulate); nullptr when no loop runs.
  CurveSketch* curve_sketch();

  // The simulated World's triangles (global vertex indices, body order); empty when not simulating.
  const std::vector<Triangle>& triangles() const { return triangles_; }
  // World vertices of scene object o: [first_vertex(o), first_vertex(o) + vertex_count(o)).
  int first_vertex(int object) const;
  int vertex_count(int object) const;
  int object_of_vertex(int vertex) const;  // -1 when none
  bool pinned(int vertex) const;
  // Where world vertex v is drawn (shadow space, from the last refresh); NaN when unknown.
  Vec3 vertex_shadow(int vertex) const;
  // The same with its depth in w (0 for objects of R^3).
  Vec4 vertex_view(int vertex) const;
  bool held() const { return snapshot_ && snapshot_->status.held_vertex >= 0; }
  // A state was handed to the simulation (an undo, a redo, a restored session) and the snapshot
  // does not show it yet: until it does, the scene keeps the restored shapes (refresh() copies
  // nothing over them) and capture() and save_state() take the state handed over.
  bool state_pending() const;
  bool exploring() const { return snapshot_ && snapshot_->status.exploring; }
  // The events (passes above / below) the loop reported since the last call, oldest first; events
  // older than the snapshot's ring are lost (counted in lost_events()).
  std::vector<SceneEvent> take_events();
  std::uint64_t lost_events() const { return lost_events_; }

 private:
  void start(bool start_playing);
  void start_loop(std::unique_ptr<HapticScene> scene);
  Scene reset_scene() const;
  void restore(DocumentState state);
  void offer_state(std::unique_ptr<WorldState> state);

  Document doc_;
  SessionOptions options_;
  std::unique_ptr<HapticLoop> loop_;
  std::unique_ptr<SessionMonitor> monitor_;
  std::string physics_error_, device_error_;
  std::vector<int> first_, count_;
  std::vector<Triangle> triangles_;
  std::vector<std::string> body_names_;          // per scene object when the simulation started
  std::map<std::string, Shape> start_shapes_;    // by object name: where Reset puts it
  DeviceButton device_button_ = DeviceButton::kGrab;
  int device_carry_ = 0;
  int dim_ = 0;
  const HapticSnapshot* snapshot_ = nullptr;
  SimulationRates rates_;
  std::chrono::steady_clock::time_point rate_wall_;
  double rate_sim_time_ = 0;
  std::int64_t rate_steps_ = 0;
  std::uint64_t rate_revision_ = 0;  // the state revision the rates were measured in
  std::chrono::steady_clock::time_point last_submit_;
  double owed_ticks_ = 0;  // run_owned_ticks: the fraction of a tick carried to the next call
  DeviceMapping mapping_;
  History history_;
  LiveHandover* handover_ = nullptr;  // the live simulation, owned by the loop
  std::uint64_t offered_revision_ = 0;  // the last state offered to this simulation (0: none)
  WorldState offered_;                  // a copy of it, while state_pending()
  SketchHost* sketch_host_ = nullptr;  // the loop's scene, when it can sketch
  std::uint64_t events_seen_ = 0, lost_events_ = 0;
  std::chrono::steady_clock::time_point last_crossings_{};
  Frame<4> crossings_frame_;
  void refresh_crossings();
};

}  // namespace s4d
