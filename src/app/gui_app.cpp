// The window loop: input (GLFW or the input file) -> session refresh -> the active tool or the
// view -> panels -> scene drawing and tool overlays -> ImGui -> swap.
//
// [SECTION] view rays and overlays   [SECTION] scripted commands   [SECTION] the loop
// The keys, the mouse and the status line are in window_routing.cpp.
#include "app/gui_app.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>
#include <utility>
#include <nlohmann/json.hpp>

#include "app/browser.hpp"
#include "app/dock.hpp"
#include "app/haptics_window.hpp"
#include "app/hint_markers.hpp"
#include "app/knot_panels.hpp"
#include "app/panels.hpp"
#include "app/screen.hpp"
#include "app/slice_panel.hpp"
#include "app/start_page.hpp"
#include "app/tool_registry.hpp"
#include "app/tool_settings.hpp"
#include "app/window_routing.hpp"
#include "app/window_dump.hpp"
#include "interact/tools/knot_sketch_tool.hpp"
#include "app/window_input.hpp"
#include "core/camera.hpp"
#include "core/stop_signal.hpp"
#include "core/threads.hpp"
#include "interact/session/autosave.hpp"
#include "interact/live/live_simulation.hpp"
#include "io/image.hpp"
#include "render/renderer.hpp"
#include "shape/shape.hpp"
#include "interact/tools/view_edit.hpp"

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
// The tools see the 3D view's rectangle as their window: pixels from its corner.
ToolView tool_view(const Camera& camera, const Vec2& cursor, const Rect& view, const Frame<4>& frame) {
  ToolView v;
  const Vec2 size(std::max(view.w, 1.0f), std::max(view.h, 1.0f));
  const Vec2 local = cursor - Vec2(view.x, view.y);
  const Eigen::Quaterniond q = camera.orientation.normalized();
  v.eye = camera.eye();
  v.right = q * Vec3::UnitX();
  v.up = q * Vec3::UnitY();
  v.toward_eye = q * Vec3::UnitZ();
  v.centre = camera.target;
  const double t = std::tan(camera.fov_y / 2);
  const Vec3 d_eye(camera.aspect * t * (2 * local.x() / size.x() - 1), t * (1 - 2 * local.y() / size.y()), -1);
  v.ray = (q * d_eye).normalized();
  v.pixel_size = 2 * camera.distance * t / size.y();
  v.cursor = local;
  v.window = size;
  v.frame = frame;
  v.camera = camera;
  return v;
}

// The input file's move-to-vertex: the pointer to the vertex's pixel now (the last frame's view).
void move_to_vertex(WindowInput& input, GuiModel& model, const InputEvent& e, const Camera& camera) {
  ImVec2 px;
  const Vec4 p = model.session.vertex_view(e.vertex);
  if (!p.allFinite() || !to_screen(camera, p.head<3>(), model.layout.view, px)) {
    model.status = "the input file's vertex " + std::to_string(e.vertex) + " is not on the screen";
    return;
  }
  input.move_to(Vec2(px.x, px.y) + e.at);
  model.grab.prefer_depth(p.w());  // its sheet, where the shadow folds others onto it
}

// The input file's move-view: a point of the view in half-sides (of its smaller side) from its
// centre, Y up: the view's ball, which the projection fits to that side, spans the same.
void move_to_view_point(WindowInput& input, const Rect& view, const Vec2& at) {
  const double half = std::min(view.w, view.h) / 2;
  input.move_to(Vec2(view.x + view.w / 2 + at.x() * half, view.y + view.h / 2 - at.y() * half));
}

void draw_overlay(const Overlay& o, const Camera& camera, const Rect& view) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  dl->PushClipRect(ImVec2(view.x, view.y), ImVec2(view.right(), view.bottom()), true);
  for (const auto& l : o.lines) {
    ImVec2 a, b;
    if (to_screen(camera, l.a, view, a) && to_screen(camera, l.b, view, b)) dl->AddLine(a, b, l.rgba, l.width);
  }
  for (const auto& d : o.dots) {
    ImVec2 a;
    if (!to_screen(camera, d.at, view, a)) continue;
    if (d.filled) dl->AddCircleFilled(a, d.radius, d.rgba, 16);
    else dl->AddCircle(a, d.radius, d.rgba, 24, 2.0f);
  }
  for (const auto& l : o.screen_lines)  // in the view's pixels
    dl->AddLine(ImVec2(view.x + static_cast<float>(l.a.x()), view.y + static_cast<float>(l.a.y())),
                ImVec2(view.x + static_cast<float>(l.b.x()), view.y + static_cast<float>(l.b.y())), l.rgba, l.width);
  dl->PopClipRect();
}

// The knot explorer's Gauss code, built up as crossings are passed (the paper's students asked for
// it), large enough to read at a glance — also with the picture hidden.
void explore_panel(GuiModel& model) {
  if (model.tool != ToolChoice::kExplore || !model.explore.on_curve()) return;
  if (!model.dock.begin(Side::kRight, "Explore")) return;
  const std::string code = model.explore.gauss_so_far();
  ImGui::SetWindowFontScale(1.6f);
  ImGui::TextWrapped("%s", code.empty() ? "(no crossing passed yet)" : code.c_str());
  ImGui::SetWindowFontScale(1.0f);
  ImGui::TextDisabled("%zu crossing(s) passed: + over, - under", model.explore.passes().size());
  model.dock.end();
}

// F12's screenshot: the picture without the panels.
void save_shot(const Image& image, const std::string& path, GuiModel& model) {
  try {
    write_png(image, path);
    model.status = "saved " + path;
  } catch (const std::exception& e) {
    model.error = e.what();
  }
}

// Keeps the simulation's view of the hand in step with the picture: the 4D frame, and the device
// workspace laid onto the view's ball as zoomed (not while a vertex is held: the hand must not jump).
void sync_view(GuiModel& model, const Camera& camera, Frame<4>& sent_frame, DeviceMapping& sent_mapping) {
  Session& s = model.session;
  if (!s.loop() || !s.snapshot()) return;
  const Frame<4>& f = model.scene().frame;
  if ((f.matrix() - sent_frame.matrix()).cwiseAbs().maxCoeff() > 1e-12 || f.perspective() != sent_frame.perspective()) {
    s.send(live::SetFrame::from(f));
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

// The view's ball in the 4D perspective: the ball of the objects' shadows as they are (and of the
// view's ball at its own depth, which holds the markers' targets), within Frame::shadow_radius of
// the shadow of the view's ball (which reaches nearer the eye than any object). Found again only
// when the frame, the perspective or the view's ball change, so the view holds still under the hand.
struct PerspectiveFit {
  Mat<4> frame = Mat<4>::Zero();
  double eye = 0;
  ViewFit fit;
  BoundingSphere shadow;

  const BoundingSphere& of(const Scene& scene, const ViewFit& ball) {
    const Frame<4>& f = scene.frame;
    if (f.matrix() == frame && f.perspective() == eye && ball.centre == fit.centre && ball.radius == fit.radius)
      return shadow;
    frame = f.matrix();
    eye = f.perspective();
    fit = ball;
    std::vector<Vec3> points;
    for (const SceneObject& o : scene.objects)
      for_each_point(o.shape, [&](const auto& p) {
        if constexpr (std::decay_t<decltype(p)>::RowsAtCompileTime == 4) points.push_back(f.shadow(p));
        else points.push_back(p);
      });
    const Vec4 q = f.to_view(ball.centre);
    for (int i = 0; i < 3; ++i)
      for (double s : {-1.0, 1.0}) points.push_back(f.project(q + s * ball.radius * Vec4::Unit(i)));
    shadow = bounding_sphere(points);
    shadow.radius = std::min(shadow.radius, f.shadow_radius(q, ball.radius));
    return shadow;
  }
};

// The view's ball in the shadow: a ball of R^4 is seen through the frame (orthographic, its shadow
// is a ball of the same radius; in perspective, PerspectiveFit); objects of R^3 are drawn as they are.
void frame_the_fit(GuiModel& model, PerspectiveFit& perspective) {
  Scene& scene = model.scene();
  bool in_r4 = false;
  for (const SceneObject& o : scene.objects) in_r4 = in_r4 || ambient_dim(o.shape) == 4;
  if (in_r4 && scene.frame.is_perspective()) {
    const BoundingSphere& b = perspective.of(scene, model.fit);
    scene.view.fit_centre = b.centre;
    scene.view.fit_radius = b.radius > 0 ? b.radius : model.fit.radius;
  } else {
    scene.view.fit_centre = in_r4 ? Vec3(scene.frame.shadow(model.fit.centre)) : Vec3(model.fit.centre.head<3>());
    scene.view.fit_radius = model.fit.radius;
  }
  scene.view.fit_centre += model.view.pan_offset(scene.view.fit_radius);
}

// [SECTION] the loop
// The window's parts that live as long as it does, and one frame of its loop.
class GuiApp {
 public:
  GuiApp(GLFWwindow* window, const GuiOptions& options, std::vector<InputEvent> script)
      : window_(window), options_(options), knot_panels_(options.exercise_seed),
        autosaver_({options.autosave, options.autosave_seconds, 3}) {
    autosaver_.set_written(persist_browser_files);  // the web page's autosaves go on to IndexedDB
    input_.attach(window);
    // In the page, the canvas and the window take the browser window's size as it changes.
    follow_browser_window();
    input_.set_script(std::move(script));
    connect_session();
    model_.autosave_path = autosaver_.path().string();
    open_first();
    offer_unfinished_autosave();
    sent_frame_.rotate(Plane{0, 1}, 1.0);  // anything but the scene's: the first frame is sent
    sent_mapping_.metres_per_unit = -1;
    objects_seen_ = model_.scene().objects.size();
  }

  // One frame of the loop: false when the window is done (closed, quit, the frame count reached,
  // a signal), finish() then ends it. The web page's frame loop calls this from the browser's.
  bool frame() {
    if (glfwWindowShouldClose(window_) || model_.quit) return false;
    const int frame = ++frames_;
    if (stop_requested()) {  // SIGINT, SIGTERM, SIGHUP: a last autosave, marked unfinished to be offered back
      const bool save = !model_.pending_restore && options_.autosave_seconds > 0;
      if (save) autosaver_.save_now(model_.session, false, signal_name(stop_signal()));
      std::cerr << "shadow4d: " << signal_name(stop_signal()) << ": the window closed"
                << (save ? "; its work is in " + autosaver_.path().string() : std::string()) << "\n";
      stopped_ = true;
      return false;
    }
    glfwPollEvents();
    update_ui_scale();
    take_script_events();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    input_.write_to_imgui();
    ImGui::NewFrame();
    lay_out(window_size(window_));
    update_session();
    const ToolInput ti = tool_input();
    sync_view(model_, renderer_.camera(), sent_frame_, sent_mapping_);
    take_marked_sheet();
    route_input(model_, routing_, input_, ti, knot_panels_);
    take_touch_gesture_now();
    draw_panels();
    keep_messages();
    ImGui::Render();
    const bool last = (options_.frames > 0 && frame >= options_.frames) || model_.quit;
    draw_scene_and_shots(last);
    if (!model_.pending_restore) autosaver_.tick(model_.session, std::chrono::steady_clock::now());
    model_.knot_panel_name = knot_panels_.shown_name();
    for (const std::string& path : dumps_)
      dump_state(model_, knot_panels_, slice_panel_, hints_, path, renderer_.camera(), frame);
    dumps_.clear();
    glfwSwapBuffers(window_);
    return !last;
  }

  // After the last frame: the autosave of a clean quit (not after a signal, whose was written),
  // and the simulation stopped. Returns the process exit code.
  int finish() {
    if (!stopped_ && !model_.pending_restore && options_.autosave_seconds > 0)
      autosaver_.save_now(model_.session, true);
    model_.session.close();
    return exit_code_;
  }

 private:
  // The session asks the window for what it keeps beside the document: the view and the tools'
  // settings, for undo steps and saved sessions.
  void connect_session() {
    model_.audio = std::make_unique<AudioPlayer>();
    if (!model_.audio->available()) std::cerr << "shadow4d: " << model_.audio->status() << "\n";  // once, not ALSA's lines
    model_.session.capture_view = [this](DocumentState& d) {
      d.angles = model_.view.plane_angles();
      d.trackball = model_.view.trackball();
      d.zoom = model_.view.zoom();
      d.settings = tool_settings(model_);
    };
    model_.session.restore_view = [this](const DocumentState& d) {
      model_.view.set(d.angles, d.trackball, d.zoom);
      apply_tool_settings(model_, d.settings);
    };
    model_.session.save_window = [this](SessionFile& f) {
      f.view.base_frame = model_.view.base_frame();
      f.view.angles = model_.view.plane_angles();
      f.view.trackball = model_.view.trackball();
      f.view.zoom = model_.view.zoom();
      f.view.perspective = model_.view.perspective();
      f.tool = model_.active_tool()->name();
      f.tool_settings = tool_settings(model_);
    };
    model_.session_options.device = options_.device.empty() ? "mouse" : options_.device;
    // Without threads (the web page) the frame loop steps the haptic loop and the World.
    model_.session_options.threaded = kHaveThreads;
    model_.session_options.async_physics = kHaveThreads;
  }

  void open_first() {
    if (options_.open_spec.empty()) {  // no file: the start page, over an empty scene
      Document d;
      d.spec = "an empty scene";
      Panels::open(model_, std::move(d));
      model_.start_page = true;
      model_.status = "choose an example, an exercise or a sketch; F1 lists the keys";
      return;
    }
    Panels::open(model_, options_.open_spec);
    if (!model_.error.empty() && !options_.open_spec.empty()) {
      std::cerr << "shadow4d: " << model_.error << "\n";
      exit_code_ = 1;
    }
    if (model_.session_options.device != "mouse") haptics_.open() = true;
  }

  // A run that did not quit normally left an autosave: offered (or, with --restore, taken up).
  // Only the work of windows no longer running: the slot this window claimed (autosave.hpp).
  void offer_unfinished_autosave() {
    model_.autosave_path = autosaver_.path().string();
    if (const auto& saved = autosaver_.unfinished()) {
      if (options_.restore) Panels::open_session(model_, *saved, autosaver_.path().string());
      else model_.pending_restore = saved;
    } else if (!autosaver_.note().empty()) {
      model_.status = autosaver_.note();
    } else if (options_.restore) {
      model_.status = "nothing to restore: no window left unfinished work (autosave: " + autosaver_.path().string() + ")";
    }
    if (const int more = autosaver_.others_unfinished(); more > 0)
      model_.status += "; " + std::to_string(more) + " more window(s) left unfinished work: each new window offers one";
  }

  // [SECTION] scripted commands
  // The input file's clock stands still while a restored state (an undo, a redo) is on its way to
  // the simulation, as a user's next move comes after they see it, whatever the machine; and while
  // a `wait` holds for the panels' background work.
  void take_script_events() {
    const bool timed_out = std::chrono::steady_clock::now() - wait_start_ > std::chrono::seconds(60);
    if (waiting_ && ((!knot_panels_.busy() && !slice_panel_.busy()) || timed_out)) waiting_ = false;
    if (wait_until_ >= 0) {
      const HapticSnapshot* snap = model_.session.snapshot();
      if (timed_out || (snap && snap->status.sim_time >= wait_until_)) wait_until_ = -1;
    }
    if (!waiting_ && wait_until_ < 0 && (!model_.session.state_pending() || ++waited_ > kMaxStateWaitFrames)) {
      ++script_frame_;
      waited_ = 0;
    }
    for (std::string& path : take_chosen_files()) {  // File > Open in the page: as a dropped file
      InputEvent chosen;
      chosen.kind = InputEvent::Kind::open;
      chosen.text = std::move(path);
      input_.live(chosen);
    }
    for (const InputEvent& e : input_.begin_frame(script_frame_)) {
      if (e.kind == InputEvent::Kind::open) Panels::open(model_, e.text);
      else if (e.kind == InputEvent::Kind::shot) shots_.push_back(e.text);
      else if (e.kind == InputEvent::Kind::dump) dumps_.push_back(e.text);
      else if (e.kind == InputEvent::Kind::quit) model_.quit = true;
      else if (e.kind == InputEvent::Kind::wait) waiting_ = true, wait_start_ = std::chrono::steady_clock::now();
      else if (e.kind == InputEvent::Kind::wait_time) wait_for(e);
      else if (e.kind == InputEvent::Kind::move_to_vertex) move_to_vertex(input_, model_, e, renderer_.camera());
      else if (e.kind == InputEvent::Kind::move_view) move_to_view_point(input_, model_.layout.view, e.at);
      else if (e.kind == InputEvent::Kind::move_to_hint) move_to_hint(e);
    }
  }

  // The monitor's content scale (or --ui-scale) times View > UI scale: the font is rasterised at
  // that size and the style's sizes follow, before the frame begins.
  void update_ui_scale() {
    float sx = 1, sy = 1;
#if GLFW_VERSION_MAJOR * 100 + GLFW_VERSION_MINOR >= 303  // emscripten's GLFW is 3.2: a page's canvas is in CSS pixels
    glfwGetWindowContentScale(window_, &sx, &sy);
#endif
    const float monitor = options_.ui_scale > 0 ? options_.ui_scale : std::max(1.0f, std::max(sx, sy));
    if (!std::isfinite(model_.ui_scale_setting)) model_.ui_scale_setting = 1;
    model_.ui_scale_setting = std::clamp(model_.ui_scale_setting, 0.5f, 3.0f);
    const float scale = std::clamp(monitor * model_.ui_scale_setting, 0.5f, 4.0f);
    if (std::abs(scale - applied_scale_) < 0.01f) return;
    applied_scale_ = scale;
    model_.ui_scale = scale;
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    ImFontConfig font;
    font.SizePixels = std::round(13.0f * scale);
    io.Fonts->AddFontDefault(&font);
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.Colors[ImGuiCol_WindowBg].w = 1.0f;  // the panels are beside the view, not over it
    style.ScaleAllSizes(scale);
    // The layout gives the status line and a folded column less than ImGui's default least window
    // (32 px): at that size they reached past the window's edge.
    style.WindowMinSize = ImVec2(4 * scale, 4 * scale);
    ImGui::GetStyle() = style;
  }

  // This frame's layout: the columns, the instruction band (as many lines as the text needs), the
  // status line and the view.
  void lay_out(const Vec2& win) {
    LayoutInput in;
    in.width = static_cast<float>(win.x());
    in.height = static_cast<float>(win.y());
    in.scale = model_.ui_scale;
    in.menu_height = ImGui::GetFrameHeight();
    in.line_height = ImGui::GetTextLineHeightWithSpacing();
    in.left_open = model_.left_open && model_.dock.wanted(Side::kLeft) && !model_.start_page;
    in.right_open = model_.right_open && model_.dock.wanted(Side::kRight) && !model_.start_page;
    in.start_page = model_.start_page;
    const Layout first = compute_layout(in);
    in.band_lines = model_.start_page ? 0 : instruction_lines(model_, first.view.w);
    model_.layout = compute_layout(in);
    model_.dock.place(model_.layout);
  }

  // Over a scenario's marker, Touch takes the marked sheet (where the shadow folds others onto it).
  void take_marked_sheet() {
    if (model_.tool != ToolChoice::kTouch || routing_.tool_drag) return;
    const int m = hints_.marker_under(model_, renderer_.camera(), model_.layout.view, input_.cursor());
    if (m < 0 || hints_.steps()[static_cast<std::size_t>(m)].vertices.empty()) return;
    const double w = hints_.marked_w(model_, m);
    if (std::isfinite(w)) model_.grab.prefer_depth(w);
    // Where no sheet is under the marker's pixel (a thin edge), the marker itself is the handle.
    const int v = hints_.steps()[static_cast<std::size_t>(m)].vertices.front();
    const int o = model_.session.object_of_vertex(v);
    if (o < 0) return;
    SheetHit h;
    h.object = o;
    h.vertex = v - model_.session.first_vertex(o);
    h.point = model_.session.vertex_shadow(v);
    h.w = model_.session.vertex_view(v)(3);
    h.distance = (h.point - renderer_.camera().eye()).norm();
    if (h.point.allFinite()) model_.grab.offer_handle(h);
  }

  void keep_messages() {
    if (model_.status == last_status_) return;
    last_status_ = model_.status;
    if (!last_status_.empty()) model_.messages.push_back(last_status_);
    if (model_.messages.size() > 500) model_.messages.erase(model_.messages.begin());
  }

  void wait_for(const InputEvent& e) {
    const HapticSnapshot* snap = model_.session.snapshot();
    wait_until_ = e.scroll + (e.text == "wait-sim" && snap ? snap->status.sim_time : 0.0);
    wait_start_ = std::chrono::steady_clock::now();
  }

  // The input file's move-to-hint: the pointer to where a marker (or its target) is drawn now.
  void move_to_hint(const InputEvent& e) {
    const auto& steps = hints_.steps();
    ImVec2 px;
    if (e.vertex >= 1 && e.vertex <= static_cast<int>(steps.size())) {
      const HintMarkers::Step& s = steps[static_cast<std::size_t>(e.vertex - 1)];
      const Vec4 at = e.text == "target" ? s.target : hints_.centre(model_, s);
      if (to_screen(renderer_.camera(), HintMarkers::shadow_of(model_, at), model_.layout.view, px)) {
        input_.move_to(Vec2(px.x, px.y) + e.at);
        return;
      }
    }
    model_.status = "the input file's marker " + std::to_string(e.vertex) + " is not on the screen";
  }

  void update_session() {
    const double now = glfwGetTime();  // without threads the frame loop steps the simulation
    model_.session.run_owned_ticks(now - last_frame_time_);
    last_frame_time_ = now;
    model_.session.refresh();
    hints_.update(model_, now);
    if (!model_.pending_settings.empty() && model_.session.snapshot()) {  // a session's hand settings
      const ToolSettings pending = std::exchange(model_.pending_settings, {});
      apply_tool_settings(model_, pending);
    }
    if (model_.scene().objects.size() != objects_seen_) {  // a sketched ribbon: keep it in view
      objects_seen_ = model_.scene().objects.size();
      model_.fit = enclosing(model_.fit, fit_of(model_.scene()));
    }
    if (std::exchange(model_.want_frame, false)) frame_all(model_);
    model_.view.apply_to(model_.scene());
    frame_the_fit(model_, perspective_fit_);
  }

  ToolInput tool_input() {
    ToolInput ti;
    ti.view = tool_view(renderer_.camera(), input_.cursor(), model_.layout.view, model_.session.scene().frame);
    ti.shift = input_.shift();
    ti.ctrl = input_.ctrl();
    ti.alt = input_.alt();
    ti.time = glfwGetTime();
    return ti;
  }

  // Two fingers on a touch screen (the page): turn the view as a drag of empty space does, and
  // zoom as the wheel does (one wheel step zooms 1.1 times).
  void take_touch_gesture_now() {
    const TouchGesture g = take_touch_gesture();
    if (g.dx != 0 || g.dy != 0) model_.view.drag(DragMode::kTrackball, g.dx, g.dy, model_.layout.view.h);
    if (g.scale != 1) model_.view.scroll(std::log(g.scale) / std::log(1.1));
  }

  void draw_panels() {
    const Camera& camera = renderer_.camera();
    const Rect& view = model_.layout.view;
    panels_.draw(model_, ImGui::GetIO().Framerate);
    if (model_.start_page) {
      if (!start_loaded_) start_page_.load(example_folder(model_, &DataDirs::scenarios), recent_files(model_));
      start_loaded_ = true;
      start_page_.draw(model_);
      status_line(model_);
      return;
    }
    start_loaded_ = false;  // read again (the recent files) when it comes back
    knot_panels_.draw(model_, Frame<3>(camera.orientation.normalized().toRotationMatrix()));
    slice_panel_.draw(model_, camera);
    if (model_.open_knot_table) {
      model_.open_knot_table = false;
      knot_panels_.open_table();
    }
    if (model_.open_haptics) {
      model_.open_haptics = false;
      haptics_.open() = true;
    }
    haptics_.draw(model_.session, model_.dock);
    explore_panel(model_);
    model_.dock.draw_strips(model_.left_open, model_.right_open);
    status_line(model_);
    if (Tool* tool = model_.active_tool(); tool && !model_.touch_and_sound_only) {
      Overlay overlay;
      tool->overlay(overlay, model_.session);
      draw_overlay(overlay, camera, view);
    }
    hints_.draw(model_, camera, view, glfwGetTime());
    knot_panels_.overlay(model_, camera, view);
  }

  // The scene, then the panels over it; the screenshots asked for this frame.
  void draw_scene_and_shots(bool last) {
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    glViewport(0, 0, fw, fh);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // The view's rectangle in framebuffer pixels (a HiDPI framebuffer is larger than the window).
    const Vec2 win = window_size(window_);
    const double kx = fw / win.x(), ky = fh / win.y();
    const Rect& v = model_.layout.view;
    const int vx = static_cast<int>(std::lround(v.x * kx)), vw = static_cast<int>(std::lround(v.w * kx));
    const int vh = static_cast<int>(std::lround(v.h * ky)), vy = fh - static_cast<int>(std::lround(v.y * ky)) - vh;
    if (vw > 0 && vh > 0) {
      try {
        renderer_.draw(model_.scene(), vw, vh, vx, vy);
        model_.intersections = renderer_.intersections();
        if (model_.touch_and_sound_only) {  // drawn for the panels' numbers, then hidden
          const Vec3f bg = model_.scene().view.background;
          glEnable(GL_SCISSOR_TEST);
          glScissor(vx, vy, vw, vh);
          glClearColor(bg.x(), bg.y(), bg.z(), 1.0f);
          glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
          glDisable(GL_SCISSOR_TEST);
        }
      } catch (const std::exception& e) {
        model_.error = e.what();
      }
      if (model_.want_screenshot) {  // the picture without the panels
        model_.want_screenshot = false;
        save_shot(renderer_.read_pixels(vw, vh, vx, vy), model_.screenshot_path, model_);
      }
    }
    glViewport(0, 0, fw, fh);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (last && !options_.window_shot.empty()) shots_.push_back(options_.window_shot);
    for (const std::string& path : shots_) {
      try {
        write_png(renderer_.read_pixels(fw, fh), path);
        std::cout << path << "\n";
      } catch (const std::exception& e) {
        std::cerr << "shadow4d: " << e.what() << "\n";
        exit_code_ = 1;
      }
    }
    shots_.clear();
  }

  GLFWwindow* window_;
  const GuiOptions& options_;
  WindowInput input_;
  Renderer renderer_;
  Panels panels_;
  HapticsWindow haptics_;
  KnotPanels knot_panels_;
  SlicePanel slice_panel_;
  GuiModel model_;
  StartPage start_page_;
  HintMarkers hints_;
  bool start_loaded_ = false;
  Autosaver autosaver_;
  Routing routing_;
  Frame<4> sent_frame_;
  DeviceMapping sent_mapping_;
  std::vector<std::string> shots_, dumps_;
  std::size_t objects_seen_ = 0;
  PerspectiveFit perspective_fit_;  // the view's ball in the 4D perspective, kept while nothing turns
  float applied_scale_ = 0;
  std::string last_status_;
  int script_frame_ = 0, waited_ = 0;
  bool waiting_ = false;
  double wait_until_ = -1;  // wait-time: the simulated time the script waits for
  std::chrono::steady_clock::time_point wait_start_{};
  int exit_code_ = 0;
  int frames_ = 0;
  bool stopped_ = false;         // a signal ended the run (its autosave is written)
  double last_frame_time_ = 0;   // glfwGetTime() of the last frame, for run_owned_ticks
};

// A window with an OpenGL 3.3 core context, or null (said on stderr).
GLFWwindow* create_window(const GuiOptions& options) {
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
    return nullptr;
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
    return nullptr;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  return window;
}

}  // namespace

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
  install_stop_signals();  // before SDL starts (audio): it would install its own
  GLFWwindow* window = create_window(options);
  if (!window) return 1;
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // layout is not persisted: every start looks the same
  ImGui_ImplGlfw_InitForOpenGL(window, false);  // WindowInput installs the callbacks
  // The ImGui backend's shaders: GLSL 3.30 on the desktop, GLSL ES 3.00 in the web page.
#ifdef S4D_GLES
  ImGui_ImplOpenGL3_Init("#version 300 es");
#else
  ImGui_ImplOpenGL3_Init("#version 330 core");
#endif
  // The window lives as long as its loop: until run_frames returns on the desktop, as long as
  // the page in a browser (where run_frames returns at once and the browser calls the frames).
  auto* app = new GuiApp(window, options, std::move(script));
  auto exit_code = std::make_shared<int>(0);
  run_frames([app] { return app->frame(); },
             [app, window, exit_code] {
               *exit_code = app->finish();
               delete app;
               ImGui_ImplOpenGL3_Shutdown();
               ImGui_ImplGlfw_Shutdown();
               ImGui::DestroyContext();
               glfwDestroyWindow(window);
               glfwTerminate();
             });
  return *exit_code;  // the page's: 0, its window still running
}

}  // namespace s4d
