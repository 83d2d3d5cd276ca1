// The window loop: input (GLFW or the input file) -> session refresh -> the active tool or the
// view -> panels -> scene drawing and tool overlays -> ImGui -> swap.
//
// [SECTION] view rays and overlays   [SECTION] knot sketch and crossings   [SECTION] input routing
// [SECTION] scripted commands   [SECTION] the loop
#include "app/gui_app.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <thread>
#include <utility>
#include <nlohmann/json.hpp>

#include "app/haptics_window.hpp"
#include "app/knot_panels.hpp"
#include "app/panels.hpp"
#include "app/tool_settings.hpp"
#include "interact/knot_sketch_tool.hpp"
#include "app/window_input.hpp"
#include "interact/autosave.hpp"
#include "interact/live_simulation.hpp"
#include "io/image.hpp"
#include "render/renderer.hpp"
#include "interact/view_edit.hpp"

namespace s4d {

namespace {

// How long the input file waits for a restored state to reach the snapshot before going on (a
// physics thread that never answers must not hang a scripted run).
constexpr int kMaxStateWaitFrames = 600;

void glfw_error(int code, const char* text) { std::fprintf(stderr, "glfw error %d: %s\n", code, text); }

Vec2 window_size(GLFWwindow* window) {
  int w = 0, h = 0;
  glfwGetWindowSize(window, &w, &h);
  return Vec2(std::max(w, 1), std::max(h, 1));
}

// [SECTION] view rays and overlays
ToolView tool_view(const Camera& camera, const Vec2& cursor, const Vec2& window, const Frame<4>& frame) {
  ToolView v;
  const Eigen::Quaterniond q = camera.orientation.normalized();
  v.eye = camera.eye();
  v.right = q * Vec3::UnitX();
  v.up = q * Vec3::UnitY();
  v.toward_eye = q * Vec3::UnitZ();
  v.centre = camera.target;
  const double t = std::tan(camera.fov_y / 2);
  const Vec3 d_eye(camera.aspect * t * (2 * cursor.x() / window.x() - 1), t * (1 - 2 * cursor.y() / window.y()), -1);
  v.ray = (q * d_eye).normalized();
  v.pixel_size = 2 * camera.distance * t / window.y();
  v.cursor = cursor;
  v.window = window;
  v.frame = frame;
  v.camera = camera;
  return v;
}

bool to_screen(const Camera& camera, const Vec3& p, const Vec2& window, ImVec2& out);

// The input file's move-to-vertex: the pointer to the vertex's pixel now (the last frame's view).
void move_to_vertex(WindowInput& input, GuiModel& model, const InputEvent& e, const Camera& camera, const Vec2& window) {
  ImVec2 px;
  const Vec4 p = model.session.vertex_view(e.vertex);
  if (!p.allFinite() || !to_screen(camera, p.head<3>(), window, px)) {
    model.status = "the input file's vertex " + std::to_string(e.vertex) + " is not on the screen";
    return;
  }
  input.move_to(Vec2(px.x, px.y) + e.at);
  model.grab.prefer_depth(p.w());  // its sheet, where the shadow folds others onto it
}

bool to_screen(const Camera& camera, const Vec3& p, const Vec2& window, ImVec2& out) {
  if (!p.allFinite() || camera.view_depth(p) <= camera.near_plane) return false;
  const Vec2 n = camera.ndc(p);
  out = ImVec2(static_cast<float>((n.x() + 1) / 2 * window.x()), static_cast<float>((1 - n.y()) / 2 * window.y()));
  return true;
}

void draw_overlay(const Overlay& o, const Camera& camera, const Vec2& window) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  for (const auto& l : o.lines) {
    ImVec2 a, b;
    if (to_screen(camera, l.a, window, a) && to_screen(camera, l.b, window, b)) dl->AddLine(a, b, l.rgba, l.width);
  }
  for (const auto& d : o.dots) {
    ImVec2 a;
    if (!to_screen(camera, d.at, window, a)) continue;
    if (d.filled) dl->AddCircleFilled(a, d.radius, d.rgba, 16);
    else dl->AddCircle(a, d.radius, d.rgba, 24, 2.0f);
  }
  for (const auto& l : o.screen_lines)
    dl->AddLine(ImVec2(static_cast<float>(l.a.x()), static_cast<float>(l.a.y())),
                ImVec2(static_cast<float>(l.b.x()), static_cast<float>(l.b.y())), l.rgba, l.width);
}

// [SECTION] input routing
struct Routing {
  bool tool_drag = false;  // the left button belongs to the tool until it is released
  bool view_drag = false;  // ... or to the view
};

void route_input(GuiModel& model, Routing& r, const WindowInput& in, const ToolInput& ti, const Vec2& window,
                 const Camera& camera, KnotPanels& knots) {
  const ImGuiIO& io = ImGui::GetIO();
  Session& session = model.session;
  Tool* tool = model.active_tool();
  if (!io.WantTextInput) {
    if (in.key_pressed(GLFW_KEY_ESCAPE) && !(tool && tool->key(ToolKey::kEscape, ti, session))) {
      if (model.tool != ToolChoice::kTouch) model.choose(ToolChoice::kTouch);
    }
    if (in.ctrl() && in.key_pressed(GLFW_KEY_Q)) model.quit = true;
    if (in.ctrl() && in.key_pressed(GLFW_KEY_Z) && !r.tool_drag) Panels::undo_or_redo(model, in.shift());
    if (in.key_pressed(GLFW_KEY_F12)) model.want_screenshot = true;
    if (in.key_pressed(GLFW_KEY_SPACE) && session.snapshot()) {
      const bool playing = session.snapshot()->status.playing;
      session.send(live_command(playing ? LiveCode::kPause : LiveCode::kPlay));
      model.status = playing ? "paused (Space plays)" : "playing (Space pauses)";
    }
    if (!r.tool_drag) {
      if (in.key_pressed(GLFW_KEY_T)) model.choose(ToolChoice::kTouch);
      if (in.key_pressed(GLFW_KEY_E)) model.choose(ToolChoice::kExplore);
      if (in.key_pressed(GLFW_KEY_R)) model.choose(ToolChoice::kSketchRibbon);
      if (in.key_pressed(GLFW_KEY_K)) model.choose(ToolChoice::kSketchKnot);
    }
    if (in.key_pressed(GLFW_KEY_H)) {
      model.touch_and_sound_only = !model.touch_and_sound_only;
      model.status = model.touch_and_sound_only ? "touch and sound only: the picture is hidden (H shows it)" : "the picture is back";
    }
    if (in.key_pressed(GLFW_KEY_L) && !r.tool_drag) Panels::toggle_relax(model);  // the knot energy, live
    if (in.key_pressed(GLFW_KEY_M)) {  // the next curve display mode (Fig. 1 a, b, c)
      session.record("change the drawing");
      CurveMode& mode = model.scene().view.curve_mode;
      mode = mode == CurveMode::kTubes ? CurveMode::kShadow : mode == CurveMode::kShadow ? CurveMode::kDiagram : CurveMode::kTubes;
      model.status = std::string("curves drawn as: ") + curve_mode_name(mode);
    }
    tool = model.active_tool();
    if (tool && in.key_pressed(GLFW_KEY_TAB)) tool->key(ToolKey::kTab, ti, session);
    if (tool && in.key_pressed(GLFW_KEY_P)) tool->key(ToolKey::kPin, ti, session);
    if (tool && in.key_pressed(GLFW_KEY_BACKSPACE)) tool->key(ToolKey::kBackspace, ti, session);
    if (tool && in.key_pressed(GLFW_KEY_C)) tool->key(ToolKey::kCarry, ti, session);
    if (tool && in.key_pressed(GLFW_KEY_LEFT_BRACKET)) tool->key(ToolKey::kSmaller, ti, session);
    if (tool && in.key_pressed(GLFW_KEY_RIGHT_BRACKET)) tool->key(ToolKey::kLarger, ti, session);
    if (tool && (in.key_pressed(GLFW_KEY_ENTER) || in.key_pressed(GLFW_KEY_KP_ENTER)))
      tool->key(ToolKey::kEnter, ti, session);
  }
  // A device's button does what the active tool does with a press (grab, explore, or draw itself).
  session.set_device_button(tool ? tool->device_button() : DeviceButton::kNone, tool ? tool->device_carry_radius() : 0);
  if (tool) tool->update(ti, session);
  const bool captured = io.WantCaptureMouse && !r.tool_drag && !r.view_drag;
  if (in.released(0) || !in.down(0)) {
    if (r.tool_drag && tool) tool->release(ti, session);
    r.tool_drag = r.view_drag = false;
  }
  if (!captured) {
    if (in.wheel() != 0 && !(tool && tool->wheel(in.wheel(), ti, session))) model.view.scroll(in.wheel());
    if (in.pressed(1)) {
      std::string message;
      const auto c = crossing_under(ti.view, model.scene());
      const bool exercise = c && knots.exercise_crossing(model, c->object, c->over);
      if (change_crossing_under(ti.view, session, message)) model.status = exercise ? knots.exercise_message() : message;
      else if (tool) tool->right_click(ti, session);
    }
    {
      if (in.pressed(0)) {
        // Shift and Ctrl turn the view (in 4D), except that the ribbon sketch uses shift for
        // "below"; otherwise a press on a surface goes to the tool.
        const bool sketch = model.tool == ToolChoice::kSketchRibbon || model.tool == ToolChoice::kSketchKnot;
        const bool navigate = (in.shift() && !sketch) || in.ctrl();
        r.tool_drag = tool && !navigate && tool->press(ti, session);
        r.view_drag = !r.tool_drag;
        if (r.view_drag && navigate) session.record("turn in 4D");  // the 4D frame is the user's work
      } else if (in.down(0) && r.tool_drag) {
        tool->drag(ti, session);
      } else if (in.down(0) && r.view_drag) {
        const Vec2 d = in.cursor_delta();
        const DragMode mode = in.shift() ? DragMode::kRotateW : in.ctrl() ? DragMode::kRotateZW : DragMode::kTrackball;
        model.view.drag(mode, d.x(), d.y(), window.y());
      } else if (!in.down(0) && tool) {
        tool->hover(ti, session);
      }
    }
  }
  if (tool) {
    const std::string m = tool->take_message();
    if (!m.empty()) model.status = m;
  }
  // The explorer's passes as sound: high above in w, low below.
  for (const SceneEvent& e : model.explore.take_new_passes())
    if (model.audio) model.audio->play(e.kind == kEventPassedAbove    ? CueKind::curve_above
                                       : e.kind == kEventPassedBelow ? CueKind::curve_below
                                       : e.kind == kEventCrossedOver ? CueKind::crossing_over
                                                                     : CueKind::crossing_under);
  // ... and, asked for, the probe's depth as the pitch of a continuous tone while it explores.
  if (model.audio) {
    const HapticSnapshot* snap = session.snapshot();
    const bool tone = model.depth_tone && snap && snap->status.exploring;
    model.audio->set_depth_tone(tone);
    if (tone)
      model.audio->set_depth(probe_depth_fraction(model.scene(), model.fit, ti.view.toward_eye,
                                                  model.explore.on_curve(), snap->status.probe_w));
  }
}

// The knot explorer's Gauss code, built up as crossings are passed (the paper's students asked for
// it), large enough to read at a glance — also with the picture hidden.
void explore_panel(GuiModel& model) {
  if (model.tool != ToolChoice::kExplore || !model.explore.on_curve()) return;
  ImGui::SetNextWindowPos(ImVec2(360, 30), ImGuiCond_FirstUseEver);
  ImGui::Begin("Explore", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  const std::string code = model.explore.gauss_so_far();
  ImGui::SetWindowFontScale(1.6f);
  ImGui::TextUnformatted(code.empty() ? "(no crossing passed yet)" : code.c_str());
  ImGui::SetWindowFontScale(1.0f);
  ImGui::TextDisabled("%zu crossing(s) passed: + over, - under", model.explore.passes().size());
  ImGui::End();
}

// [SECTION] scripted commands
void save_shot(const Image& image, const std::string& path, GuiModel& model) {
  try {
    write_png(image, path);
    model.status = "saved " + path;
  } catch (const std::exception& e) {
    model.error = e.what();
  }
}

// The state a scripted test reads back: the simulation's status, the monitor's checks and every
// vertex where it is now (world coordinates), and where the view draws the shadow's pinch points.
void dump_state(GuiModel& model, const KnotPanels& knots, const std::string& path, const Camera& camera,
                const Vec2& window, int window_frame) {
  using Json = nlohmann::ordered_json;
  Json j;
  Session& s = model.session;
  // The frame and the wall clock (s): two dumps give the frame rate over the frames between them.
  j["window_frame"] = window_frame;
  j["wall_time"] = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  j["simulating"] = s.simulating();
  j["state_pending"] = s.state_pending();
  j["physics_error"] = s.physics_error();
  j["status"] = model.status;
  j["error"] = model.error;
  if (const HapticSnapshot* snap = s.snapshot()) {
    const SceneStatus& st = snap->status;
    j["sim_time"] = st.sim_time;
    j["sim_steps"] = st.sim_steps;
    j["playing"] = st.playing;
    j["held_vertex"] = st.held_vertex;
    j["grab_mode"] = st.grab_mode;
    j["pinned"] = st.pinned;
    j["contacts"] = st.contacts;
    j["rollbacks"] = st.rollbacks;
    j["device"] = snap->device_name;
    j["max_force_output"] = snap->max_force_output;
    j["safety_nonfinite"] = snap->safety.nonfinite;
    j["loop_period_p999_us"] = snap->period.p999_us;
    j["dim"] = snap->point_dimension;
    j["positions"] = snap->points;
    j["band_force"] = st.band_force;
    Json pins = Json::array();
    for (std::size_t v = 0; v < snap->flags.size(); ++v)
      if (snap->flags[v] & 1) pins.push_back(v);
    j["pinned_vertices"] = pins;
    j["carry_radius"] = st.carry_radius;
    // Where each vertex's shadow is on the screen (null when behind the eye), for tests that
    // press on a chosen vertex.
    Json pixels = Json::array();
    const int nv = snap->point_dimension > 0 ? static_cast<int>(snap->points.size()) / snap->point_dimension : 0;
    for (int v = 0; v < nv; ++v) {
      ImVec2 px;
      const Vec3 p = s.vertex_shadow(v);
      pixels.push_back(to_screen(camera, p, window, px) ? Json{px.x, px.y} : Json(nullptr));
    }
    j["vertex_pixels"] = pixels;
  }
  {  // the World's cells, so a test can check every saved state with a checker of its own
    Json tris = Json::array();
    for (const Triangle& t : s.triangles()) tris.push_back({t[0], t[1], t[2]});
    j["triangles"] = tris;
  }
  const MonitorResult c = s.checks();
  j["checked"] = c.valid;
  j["true_intersections"] = c.true_intersections;
  j["min_gap"] = std::isfinite(c.min_gap) ? Json(c.min_gap) : Json(nullptr);
  if (c.verdict) j["verdict"] = {{"pass", c.verdict->pass}, {"detail", c.verdict->detail}};
  const Frame<4>& f = model.scene().frame;
  Json frame = Json::array();
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) frame.push_back(f.matrix()(r, k));
  j["frame"] = frame;
  j["tool"] = model.active_tool()->name();
  j["objects"] = model.scene().objects.size();
  Json passes = Json::array();
  for (const SceneEvent& e : model.explore.passes())
    passes.push_back(e.kind == kEventPassedAbove ? "above" : e.kind == kEventPassedBelow ? "below" : e.kind == kEventCrossedOver ? "over" : "under");
  j["explore_gauss"] = model.explore.gauss_so_far();
  j["explore_passes"] = passes;
  if (const HapticSnapshot* snap = s.snapshot()) {
    j["exploring"] = snap->status.exploring;
    j["probe_w"] = snap->status.probe_w;
    j["relaxing"] = snap->status.relaxing;
  }
  if (const SketchedRibbon* r = model.ribbon.last()) {
    Json ps = Json::array();
    for (const RibbonPassage& p : r->passages) ps.push_back(p.below ? "below" : "above");
    j["ribbon_passages"] = ps;
  }
  j["hits_under_cursor"] = model.grab.hits().size();
  Json hits = Json::array();
  for (const SheetHit& h : model.grab.hits())
    hits.push_back({{"w", h.w}, {"vertex", s.first_vertex(h.object) < 0 ? -1 : s.first_vertex(h.object) + h.vertex}});
  j["hits"] = hits;
  {
    const SketchPublished& k = model.knot.published();
    j["sketch"] = {{"active", k.active},
                   {"drawing", k.drawing},
                   {"points", k.point_count},
                   {"components", k.component_count},
                   {"crossings_chosen", k.crossing_count},
                   {"blocked_ticks", k.status.blocked_ticks},
                   {"crossings_refused", k.status.crossings_refused},
                   {"max_repulsion", k.status.max_repulsion},
                   {"max_lag_near", k.status.max_lag_near},
                   {"last_gauss", model.knot.last_gauss()},
                   {"last_name", model.knot.last_name()}};
  }
  j["knot_panel_name"] = model.knot_panel_name;
  Json knot_panels = Json::object();
  knots.dump(knot_panels);
  j["knot_panels"] = knot_panels;
  j["depth_tone"] = model.depth_tone;
  if (model.intersections.computed) {
    Json pinch = Json::array();
    for (const Vec3& p : model.intersections.pinch_at) {
      ImVec2 px;
      const bool seen = to_screen(camera, p, window, px);
      pinch.push_back({{"at", {p.x(), p.y(), p.z()}}, {"pixel", seen ? Json{px.x, px.y} : Json(nullptr)}});
    }
    j["pinch_points"] = pinch;
    j["curve_length"] = model.intersections.length;
  }
  j["curve_mode"] = curve_mode_name(model.scene().view.curve_mode);
  j["touch_and_sound_only"] = model.touch_and_sound_only;
  j["sheet"] = model.grab.sheet();
  j["restore_offered"] = model.pending_restore.has_value();
  j["tool_settings"] = tool_settings(model);
  j["history"] = s.history().done_labels();
  std::ofstream out(path);
  out << j.dump(1) << "\n";
  if (!out) model.error = "cannot write " + path;
}

// Keeps the simulation's view of the hand in step with the picture: the 4D frame, and the device
// workspace laid onto the view's ball as zoomed (not while a vertex is held: the hand must not jump).
void sync_view(GuiModel& model, const Camera& camera, Frame<4>& sent_frame, DeviceMapping& sent_mapping) {
  Session& s = model.session;
  if (!s.loop() || !s.snapshot()) return;
  const Frame<4>& f = model.scene().frame;
  if ((f.matrix() - sent_frame.matrix()).cwiseAbs().maxCoeff() > 1e-12) {
    s.send(live_frame(f));
    sent_frame = f;
  }
  const DeviceCapabilities& caps = s.snapshot()->caps;
  const Mat<3> axes = camera.orientation.normalized().toRotationMatrix();
  // The workspace covers what the view shows: zoomed out, the hand reaches (and lifts) further.
  const double zoom = model.scene().view.zoom > 0 ? model.scene().view.zoom : 1.0;
  const DeviceMapping m = DeviceMapping::fit(model.scene().view.fit_centre, model.scene().view.fit_radius / zoom, axes,
                                             caps.workspace_centre(), 0.5 * (caps.workspace_max - caps.workspace_min));
  const bool changed = (m.centre - sent_mapping.centre).norm() + (m.axes - sent_mapping.axes).norm() +
                           std::abs(m.metres_per_unit - sent_mapping.metres_per_unit) >
                       1e-9;
  if (changed && !s.held() && !model.knot.busy()) {  // strokes keep the mapping they were drawn in
    s.set_mapping(m);
    sent_mapping = m;
  }
}

// The smallest ball of the two's centres' kind holding both (the view keeps what it showed).
ViewFit enclosing(const ViewFit& a, const ViewFit& b) {
  if (!(a.radius > 0)) return b;
  if (!(b.radius > 0)) return a;
  const double d = (b.centre - a.centre).norm();
  if (d + b.radius <= a.radius) return a;
  if (d + a.radius <= b.radius) return b;
  ViewFit f;
  f.radius = 0.5 * (d + a.radius + b.radius);
  f.centre = a.centre + (f.radius - a.radius) / d * (b.centre - a.centre);
  return f;
}

// The view's ball in the shadow: a ball of R^4 is seen through the frame (its shadow is a ball
// of the same radius); objects of R^3 are drawn as they are.
void frame_the_fit(GuiModel& model) {
  Scene& scene = model.scene();
  bool in_r4 = false;
  for (const SceneObject& o : scene.objects) in_r4 = in_r4 || ambient_dim(o.shape) == 4;
  scene.view.fit_centre = in_r4 ? Vec3(scene.frame.shadow(model.fit.centre)) : Vec3(model.fit.centre.head<3>());
  scene.view.fit_radius = model.fit.radius;
}

}  // namespace

// [SECTION] the loop
int run_gui_app(const GuiOptions& options) {
  std::vector<InputEvent> script;
  if (!options.input.empty()) {
    try {
      script = read_input_file(options.input);
    } catch (const std::exception& e) {
      std::cerr << "shadow4d: " << e.what() << "\n";
      return 1;
    }
  }
  glfwSetErrorCallback(glfw_error);
  // A busy X server can refuse a connection for a moment (seen once in 30 window runs under one
  // Xvfb, the next run connecting fine): two more tries half a second apart before giving up.
  bool initialised = glfwInit();
  for (int retry = 0; !initialised && retry < 2 && std::getenv("DISPLAY"); ++retry) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    initialised = glfwInit();
  }
  if (!initialised) {
    std::cerr << "shadow4d: cannot open a window (glfwInit failed); try `shadow4d demo`\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, "shadow4d", nullptr, nullptr);
  if (!window) {
    std::cerr << "shadow4d: cannot create an OpenGL 3.3 window; try `shadow4d demo`\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // layout is not persisted: every start looks the same
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, false);  // WindowInput installs the callbacks
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int exit_code = 0;
  {
    WindowInput input;
    input.attach(window);
    input.set_script(std::move(script));
    Renderer renderer;
    Panels panels;
    HapticsWindow haptics;
    KnotPanels knot_panels(options.exercise_seed);
    GuiModel model;
    model.audio = std::make_unique<AudioPlayer>();
    model.session.capture_view = [&model](DocumentState& d) {
      d.angles = model.view.plane_angles();
      d.trackball = model.view.trackball();
      d.zoom = model.view.zoom();
      d.settings = tool_settings(model);
    };
    model.session.restore_view = [&model](const DocumentState& d) {
      model.view.set(d.angles, d.trackball, d.zoom);
      apply_tool_settings(model, d.settings);
    };
    model.session.save_window = [&model](SessionFile& f) {
      f.view.base_frame = model.view.base_frame();
      f.view.angles = model.view.plane_angles();
      f.view.trackball = model.view.trackball();
      f.view.zoom = model.view.zoom();
      f.tool = model.active_tool()->name();
      f.tool_settings = tool_settings(model);
    };
    model.session_options.device = options.device.empty() ? "mouse" : options.device;
    Panels::open(model, options.open_spec.empty() ? "clifford-torus" : options.open_spec);
    if (!model.error.empty() && !options.open_spec.empty()) {
      std::cerr << "shadow4d: " << model.error << "\n";
      exit_code = 1;
    }
    if (model.session_options.device != "mouse") haptics.open() = true;
    Autosaver autosaver({options.autosave, options.autosave_seconds, 3});
    model.autosave_path = autosaver.path().string();
    {
      std::string why;
      if (auto saved = unfinished_autosave(autosaver.path(), &why)) {
        if (options.restore) Panels::open_session(model, *saved, autosaver.path().string());
        else model.pending_restore = std::move(saved);
      } else if (!why.empty()) {
        model.status = why;
      } else if (options.restore) {
        model.status = "nothing to restore: the last run quit normally (" + autosaver.path().string() + ")";
      }
    }
    Routing routing;
    Frame<4> sent_frame;
    sent_frame.rotate(Plane{0, 1}, 1.0);  // anything but the scene's: the first frame is sent
    DeviceMapping sent_mapping;
    sent_mapping.metres_per_unit = -1;
    std::vector<std::string> shots, dumps;
    std::size_t objects_seen = model.scene().objects.size();
    // The input file's clock: it stands still while a restored state (an undo, a redo) is on its
    // way to the simulation, as a user's next move comes after they see it, whatever the machine;
    // and while a `wait` holds for the panels' background work.
    int script_frame = 0, waited = 0;
    bool waiting = false;
    std::chrono::steady_clock::time_point wait_start{};
    for (int frame = 1; !glfwWindowShouldClose(window) && !model.quit; ++frame) {
      glfwPollEvents();
      if (waiting && (!knot_panels.busy() || std::chrono::steady_clock::now() - wait_start > std::chrono::seconds(60)))
        waiting = false;
      if (!waiting && (!model.session.state_pending() || ++waited > kMaxStateWaitFrames)) {
        ++script_frame;
        waited = 0;
      }
      for (const InputEvent& e : input.begin_frame(script_frame)) {
        if (e.kind == InputEvent::Kind::open) Panels::open(model, e.text);
        else if (e.kind == InputEvent::Kind::shot) shots.push_back(e.text);
        else if (e.kind == InputEvent::Kind::dump) dumps.push_back(e.text);
        else if (e.kind == InputEvent::Kind::quit) model.quit = true;
        else if (e.kind == InputEvent::Kind::wait) waiting = true, wait_start = std::chrono::steady_clock::now();
        else if (e.kind == InputEvent::Kind::move_to_vertex) move_to_vertex(input, model, e, renderer.camera(), window_size(window));
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      input.write_to_imgui();
      ImGui::NewFrame();

      model.session.refresh();
      if (!model.pending_settings.empty() && model.session.snapshot()) {  // a session's hand settings
        const ToolSettings pending = std::exchange(model.pending_settings, {});
        apply_tool_settings(model, pending);
      }
      if (model.scene().objects.size() != objects_seen) {  // a sketched ribbon: keep it in view
        objects_seen = model.scene().objects.size();
        model.fit = enclosing(model.fit, fit_of(model.scene()));
      }
      model.view.apply_to(model.scene());
      frame_the_fit(model);

      const Vec2 win = window_size(window);
      const Camera& camera = renderer.camera();
      ToolInput ti;
      ti.view = tool_view(camera, input.cursor(), win, model.scene().frame);
      ti.shift = input.shift();
      ti.ctrl = input.ctrl();
      ti.alt = input.alt();
      ti.time = glfwGetTime();
      sync_view(model, camera, sent_frame, sent_mapping);
      route_input(model, routing, input, ti, win, camera, knot_panels);
      panels.draw(model, ImGui::GetIO().Framerate);
      knot_panels.draw(model, Frame<3>(camera.orientation.normalized().toRotationMatrix()));
      if (model.open_knot_table) {
        model.open_knot_table = false;
        knot_panels.open_table();
      }
      if (model.open_haptics) {
        model.open_haptics = false;
        haptics.open() = true;
      }
      haptics.draw(model.session);
      explore_panel(model);
      if (Tool* tool = model.active_tool(); tool && !model.touch_and_sound_only) {
        Overlay overlay;
        tool->overlay(overlay, model.session);
        draw_overlay(overlay, camera, win);
      }
      knot_panels.overlay(model, camera, win);
      ImGui::Render();

      int fw = 0, fh = 0;
      glfwGetFramebufferSize(window, &fw, &fh);
      if (fw > 0 && fh > 0) {
        try {
          renderer.draw(model.scene(), fw, fh);
          model.intersections = renderer.intersections();
          if (model.touch_and_sound_only) {  // drawn for the panels' numbers, then hidden
            const Vec3f bg = model.scene().view.background;
            glClearColor(bg.x(), bg.y(), bg.z(), 1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
          }
        } catch (const std::exception& e) {
          model.error = e.what();
        }
        if (model.want_screenshot) {  // the picture without the panels
          model.want_screenshot = false;
          save_shot(renderer.read_pixels(fw, fh), model.screenshot_path, model);
        }
      }
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      const bool last = (options.frames > 0 && frame >= options.frames) || model.quit;
      if (last && !options.window_shot.empty()) shots.push_back(options.window_shot);
      for (const std::string& path : shots) {
        try {
          write_png(renderer.read_pixels(fw, fh), path);
          std::cout << path << "\n";
        } catch (const std::exception& e) {
          std::cerr << "shadow4d: " << e.what() << "\n";
          exit_code = 1;
        }
      }
      shots.clear();
      if (!model.pending_restore) autosaver.tick(model.session, std::chrono::steady_clock::now());
      model.knot_panel_name = knot_panels.shown_name();
      for (const std::string& path : dumps) dump_state(model, knot_panels, path, camera, win, frame);
      dumps.clear();
      glfwSwapBuffers(window);
      if (last) break;
    }
    if (!model.pending_restore && options.autosave_seconds > 0) autosaver.save_now(model.session, true);
    model.session.close();
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exit_code;
}

}  // namespace s4d
