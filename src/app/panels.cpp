// [SECTION] Opening   [SECTION] Menu bar   [SECTION] View panel   [SECTION] Scene panel
// [SECTION] Simulation panel   [SECTION] Scenario banner   [SECTION] Generator dialog
// [SECTION] Dialogs (open, save, screenshot, errors)
#include "app/panels.hpp"

#include <imgui.h>

#include <cmath>
#include <limits>

#include "app/tool_settings.hpp"
#include "core/error.hpp"
#include "interact/live_simulation.hpp"
#include "io/object_file.hpp"
#include "render/diagram_export.hpp"
#include "scenario/world_builder.hpp"
#include "shape/describe.hpp"

namespace s4d {

namespace {

// One change of a tool setting (a whole slider drag) is one undoable step holding the value before
// it: on the frame an edit starts, `swap` puts the old value in place for the record, then back.
// (The hand's parameters need no swap: the snapshot shows the old value until the loop has the
// new one.)
template <typename Swap>
void record_tool_setting(GuiModel& model, const std::string& label, Swap swap) {
  if (!ImGui::IsItemActivated()) return;
  swap();
  model.session.record(label);
  swap();
}

const std::vector<std::string> kOpenExtensions{".json", ".s4d", ".off", ".4off", ".noff", ".vect",
                                               ".4vect", ".txt", ".xyz", ".curve"};
constexpr const char* kIntegratorNames[] = {"symplectic-euler", "paper-euler"};

// Horizontal colour bar: far (blue) on the left, near (red) on the right. R^4 objects are coloured
// by w, R^3 ones by distance from the eye.
void legend(ColourMap map, const Scene& scene) {
  bool in_r4 = false, in_r3 = false;
  for (const SceneObject& obj : scene.objects) (ambient_dim(obj.shape) == 4 ? in_r4 : in_r3) = true;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const float w = ImGui::GetContentRegionAvail().x, h = 14;
  constexpr int kSteps = 32;
  for (int i = 0; i < kSteps; ++i) {
    const Vec3f c = map_colour(map, (i + 0.5) / kSteps);
    dl->AddRectFilled(ImVec2(p.x + w * i / kSteps, p.y), ImVec2(p.x + w * (i + 1) / kSteps, p.y + h),
                      ImGui::ColorConvertFloat4ToU32(ImVec4(c.x(), c.y(), c.z(), 1)));
  }
  ImGui::Dummy(ImVec2(w, h));
  const char* far = in_r4 ? "far (w -)" : "far from the eye";
  const char* near = in_r4 ? "near (w +)" : "near the eye";
  ImGui::TextUnformatted(far);
  ImGui::SameLine(w - ImGui::CalcTextSize(near).x);
  ImGui::TextUnformatted(near);
  if (in_r4 && in_r3) ImGui::TextDisabled("objects in R^3: by distance from the eye");
}

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f s", s);
  return b;
}

}  // namespace

// [SECTION] Opening
ViewFit fit_of(const Scene& scene) {
  ViewFit f;
  std::vector<Vec4> pts;
  for (const SceneObject& o : scene.objects)
    std::visit([&](const auto& s) {
      using T = std::decay_t<decltype(s)>;
      auto add = [&](const auto& p) {
        Vec4 q = Vec4::Zero();
        q.template head<T::kDim>() = p;
        pts.push_back(q);
      };
      if constexpr (std::is_same_v<T, Surface<T::kDim>>) {
        for (const auto& p : s.vertices) add(p);
      } else {
        for (const auto& c : s.components)
          for (const auto& p : c.points) add(p);
      }
    }, o.shape);
  if (pts.empty()) return f;
  Vec4 lo = pts[0], hi = pts[0];
  for (const Vec4& p : pts) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  f.centre = 0.5 * (lo + hi);
  for (const Vec4& p : pts) f.radius = std::max(f.radius, (p - f.centre).norm());
  if (!(f.radius > 0)) f.radius = 1;
  return f;
}

double probe_depth_fraction(const Scene& scene, const ViewFit& fit, const Vec3& toward_eye, bool on_curve,
                            double probe_w) {
  if (!(fit.radius > 0) || !std::isfinite(probe_w)) return 0.5;
  const double centre = on_curve ? toward_eye.dot(fit.centre.head<3>()) : scene.frame.to_view(fit.centre)(3);
  return std::clamp(0.5 + 0.5 * (probe_w - centre) / fit.radius, 0.0, 1.0);
}

void Panels::open(GuiModel& model, const std::string& spec) {
  try {
    if (spec.size() > 4 && spec.ends_with(".s4d")) {
      open_session(model, read_session(spec), spec);
      return;
    }
    open(model, load_document(spec));
  } catch (const std::exception& e) {
    model.error = e.what();
  }
}

void Panels::undo_or_redo(GuiModel& model, bool redo) {
  Session& session = model.session;
  if (Tool* tool = model.active_tool(); tool && tool->key(redo ? ToolKey::kRedo : ToolKey::kUndo, ToolInput{}, session)) {
    model.status = (redo ? "redo: " : "undo: ") + tool->take_message();
    return;
  }
  const History& h = session.history();
  const std::string label = redo ? (h.can_redo() ? h.undone_labels().front() : "") : (h.can_undo() ? h.done_labels().back() : "");
  if (redo ? session.redo() : session.undo()) model.status = (redo ? "redo: " : "undo: ") + label;
  else model.status = redo ? "nothing to redo" : "nothing to undo";
}

void Panels::open_session(GuiModel& model, const SessionFile& saved, const std::string& path) {
  model.session.open_saved(saved, path, model.session_options);
  model.view.reset(model.scene());
  model.view.set_base_frame(saved.view.base_frame);
  model.view.set(saved.view.angles, saved.view.trackball, saved.view.zoom);
  model.fit = fit_of(model.scene());
  ToolChoice chosen = ToolChoice::kTouch;
  const ToolChoice was = model.tool;
  for (ToolChoice c : {ToolChoice::kTouch, ToolChoice::kExplore, ToolChoice::kSketchRibbon, ToolChoice::kSketchKnot}) {
    model.tool = c;
    if (saved.tool == model.active_tool()->name()) chosen = c;
  }
  model.tool = was;
  model.choose(chosen);
  apply_tool_settings(model, saved.tool_settings);
  model.status = "opened the session " + path + " (saved from '" + saved.opened + "')";
  for (int v : saved.simulation.held)
    model.status += "; vertex " + std::to_string(v) + ", held when saved, is pinned where it was (P lets it go)";
  if (!model.session.physics_error().empty())
    model.status += " (not simulated: " + model.session.physics_error() + ")";
}

void Panels::open(GuiModel& model, Document doc) {
  const std::string spec = doc.spec;
  const bool scene_file = spec.size() > 5 && spec.ends_with(".json");
  const bool scenario = doc.scenario.has_value();
  SessionOptions options = model.session_options;
  options.start_playing = !scenario;  // a scenario opens paused in its start state
  model.session.open(std::move(doc), options);
  model.view.reset(model.scene());
  if (!scene_file && !model.scene().objects.empty() && ambient_dim(model.scene().objects[0].shape) == 4)
    model.view.turn_to_generic_view();
  model.fit = fit_of(model.scene());
  model.status = "opened " + spec;
  if (scenario) model.status += ": " + model.session.scenario()->instruction;
  else if (!model.scene().instruction.empty()) model.status += ": " + model.scene().instruction;
  if (!model.session.physics_error().empty())
    model.status += " (not simulated: " + model.session.physics_error() + ")";
  if (!model.session.device_error().empty()) model.error = model.session.device_error();
}

Scene scene_to_save(GuiModel& model) {
  Scene s = model.scene();
  model.view.apply_to(s);
  s.view.fit_radius = 0;
  // Simulated objects have moved: their shapes as they are now, not their generator's.
  for (std::size_t o = 0; o < s.objects.size(); ++o)
    if (model.session.simulating() && model.session.first_vertex(static_cast<int>(o)) >= 0) {
      s.objects[o].generator.reset();
      s.objects[o].source_path.clear();
      s.objects[o].placement = Placement{};
    }
  return s;
}

Panels::Panels()
    : open_browser_("Open scene, scenario, mesh or curve", kOpenExtensions, false),
      save_browser_("Save scene", {".json"}, true),
      session_browser_("Save session", {".s4d"}, true),
      shot_browser_("Save screenshot", {".png"}, true),
      stroke_browser_("Save last sketch stroke", {".txt"}, true),
      diagram_browser_("Export the crossing diagram (.svg, or .tex for TikZ)", {".svg", ".tex"}, true) {}

void Panels::draw(GuiModel& model, float fps) {
  menu_bar(model);
  view_panel(model, fps);
  scene_panel(model);
  simulation_panel(model);
  scenario_banner(model);
  ribbon_panel(model);
  history_panel(model);
  generator_dialog(model);
  dialogs(model);
}

// [SECTION] Menu bar
void Panels::menu_bar(GuiModel& model) {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("New (empty scene)")) {
      Document d;
      d.spec = "an empty scene";
      open(model, std::move(d));
      model.status = "empty scene: Create adds objects, or sketch a knot";
    }
    if (ImGui::MenuItem("Open...")) open_browser_.open(S4D_SCENES_DIR);
    if (ImGui::MenuItem("Open a scenario...")) open_browser_.open(S4D_SCENARIOS_DIR);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the paper's physical examples (scenarios/*.json), paused at their start");
    if (ImGui::MenuItem("Save scene...")) save_browser_.open(".");
    if (ImGui::MenuItem("Save session...")) session_browser_.open(".");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("everything as it is now: shapes, the simulation's state, pins, the view\n"
                        "(File > Open or shadow4d FILE.s4d takes it up again)");
    if (ImGui::MenuItem("Screenshot...", "F12")) shot_browser_.open(".");
    if (ImGui::MenuItem("Save last sketch stroke...", nullptr, false, model.knot.has_last_stroke()))
      stroke_browser_.open(".");
    if (ImGui::MenuItem("Export crossing diagram (SVG, TikZ)...", nullptr, false, has_curves(model.scene())))
      diagram_browser_.open(".");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("the cursor samples of the last sketch (x y u), for\n"
                        "shadow4d knot sketch FILE --knot --out KNOT");
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) model.quit = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    const History& h = model.session.history();
    const std::string undo = h.can_undo() ? "Undo " + h.done_labels().back() : "Undo";
    const std::string redo = h.can_redo() ? "Redo " + h.undone_labels().front() : "Redo";
    if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, h.can_undo() || model.knot.busy())) undo_or_redo(model, false);
    if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z", false, h.can_redo())) undo_or_redo(model, true);
    ImGui::MenuItem("History", nullptr, &model.show_history);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Tools")) {
    if (ImGui::MenuItem("Touch (grab and pull)", "T", model.tool == ToolChoice::kTouch)) model.choose(ToolChoice::kTouch);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("left-drag a surface, or a knot's strand: a rubber band pulls the point under the cursor\n"
                        "(Alt: along the shadow ray, w or a knot's depth; a knot never passes through itself);\n"
                        "Tab: the next sheet under the cursor; P or right click: pin / unpin;\n"
                        "the wheel while holding: the hand in depth. On empty space the drag turns the view.");
    if (ImGui::MenuItem("Explore (probe and sound)", "E", model.tool == ToolChoice::kExplore))
      model.choose(ToolChoice::kExplore);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("press on a surface of R^4 and move: the probe keeps to its sheet through the shadow's\n"
                        "self-intersections, the hand feels the navigation spring, and each curve passed\n"
                        "sounds: high where the probe's sheet is above in w, low where it is below\n"
                        "(also: shadow4d explore SCENE --through ...)");
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Create")) {
    bool sketching = model.sketching();
    if (ImGui::MenuItem("Sketch a knot", "K", &sketching)) model.choose(sketching ? ToolChoice::kSketchKnot : ToolChoice::kTouch);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("draw a closed curve with the left button in the plane facing you;\n"
                        "where it crosses what is drawn it passes over, or under with shift held.\n"
                        "It becomes a knot of R^3, named live in the Scene panel.\n"
                        "(also: shadow4d knot sketch STROKE --knot --out KNOT)");
    if (ImGui::MenuItem("Knot from the table...")) model.open_knot_table = true;
    if (ImGui::MenuItem("Exercise: untangle the unknot (Fig. 15)"))
      open(model, std::string(S4D_SCENES_DIR) + "/fig15-tangled-unknot.json");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("a tangled curve that is the unknot: show it by dragging strands (Alt: along the depth)\n"
                        "until its picture has no crossing; a drag never changes the knot\n"
                        "(also: shadow4d scenes/fig15-tangled-unknot.json)");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("3_1 ... 10_165, 11n_34, 12a_803, torus knots T(p,q), links; a relaxed 3D curve of it\n"
                        "(also: shadow4d knot make NAME --out K.curve)");
    bool ribbon = model.tool == ToolChoice::kSketchRibbon;
    if (ImGui::MenuItem("Sketch a ribbon", "R", &ribbon)) model.choose(ribbon ? ToolChoice::kSketchRibbon : ToolChoice::kTouch);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("draw a ribbon's centre line with the left button on the plane facing you (wheel: its\n"
                        "depth); where it passes another surface's shadow it goes above in w, or below with\n"
                        "shift held. It is smoothed in w keeping every choice, checked to be embedded and\n"
                        "simulated: above then below through a sphere links them.\n"
                        "(also: shadow4d sketch-ribbon SCENE STROKE --out OUT.json)");
    ImGui::Separator();
    for (const auto& g : generator_catalogue()) {
      const std::string label = g.name + (g.surface ? "  (surface, R^" : "  (curve, R^") +
                                std::to_string(g.dim) + ")";
      if (ImGui::MenuItem(label.c_str())) {
        generator_ = g.name;
        generator_params_.clear();
        for (const auto& p : g.params) generator_params_[p.name] = p.default_value;
        generator_dialog_open_ = true;
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", g.description.c_str());
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Haptics")) {
    if (ImGui::MenuItem("Haptics panel (device, loop, forces)")) model.open_haptics = true;
    ImGui::EndMenu();
  }
  ImGui::TextDisabled("|  %s", model.status.c_str());
  ImGui::EndMainMenuBar();
}

// [SECTION] View panel
void Panels::view_panel(GuiModel& model, float fps) {
  ImGui::SetNextWindowPos(ImVec2(10, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(330, 560), ImGuiCond_FirstUseEver);
  ImGui::Begin("View");
  ImGui::Text("%.0f fps  (%.1f ms)", fps, fps > 0 ? 1000.0f / fps : 0.0f);
  ImGui::Separator();
  ImGui::TextUnformatted("4D rotation (degrees)");
  auto& angles = model.view.plane_angles();
  const auto planes = all_planes(4);
  const auto angles_before = angles;
  // A turn is one undoable step, recorded with the angles it started from.
  auto record_turn = [&](const std::string& label) {
    const auto now = angles;
    angles = angles_before;
    model.session.record(label);
    angles = now;
  };
  for (std::size_t i = 0; i < planes.size(); ++i) {
    ImGui::SliderFloat(plane_name(planes[i]).c_str(), &angles[i], -180.0f, 180.0f, "%.0f");
    if (ImGui::IsItemActivated()) record_turn("turn " + plane_name(planes[i]));
  }
  if (ImGui::Button("Reset 4D rotation")) {
    model.session.record("reset the 4D rotation");
    angles.fill(0.0f);
  }
  ImGui::SameLine();
  if (ImGui::Button("Reset view")) model.view.reset(model.scene());
  ImGui::TextDisabled("drag empty space: turn  shift-drag: xw/yw  ctrl-drag: zw  wheel: zoom");

  ImGui::Separator();
  ImGui::TextUnformatted("Drawing");
  ViewSettings& v = model.scene().view;
  ViewSettings v_before = v;  // each change of the drawing is one undoable step (record_tool_setting)
  const auto drawn = [&] { record_tool_setting(model, "change the drawing", [&] { std::swap(v, v_before); }); };
  ImGui::Checkbox("depth colour", &v.depth_colour);
  drawn();
  if (v.depth_colour) {
    int map = static_cast<int>(v.colour_map);
    ImGui::Combo("colour map", &map, "coolwarm\0rainbow\0grey\0");
    drawn();
    v.colour_map = static_cast<ColourMap>(map);
    legend(v.colour_map, model.scene());
  }
  if (has_curves(model.scene())) {
    int mode = static_cast<int>(v.curve_mode);
    ImGui::TextUnformatted("curves:");
    ImGui::SameLine();
    ImGui::RadioButton("tubes", &mode, static_cast<int>(CurveMode::kTubes));
    drawn();
    ImGui::SameLine();
    ImGui::RadioButton("shadow", &mode, static_cast<int>(CurveMode::kShadow));
    drawn();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the plain image: no 3D cues at all");
    ImGui::SameLine();
    ImGui::RadioButton("diagram", &mode, static_cast<int>(CurveMode::kDiagram));
    drawn();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the crossing diagram: a gap in the under strand at each crossing");
    v.curve_mode = static_cast<CurveMode>(mode);
    ImGui::SameLine();
    ImGui::TextDisabled("(M)");
    ImGui::Checkbox("touch and sound only (H)", &model.touch_and_sound_only);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("hides the picture: explore the knot (E) by the force and the crossing cues alone;\n"
                        "the Gauss code is built up in the Explore panel as crossings are passed");
  }
  ImGui::Checkbox("wireframe", &v.wireframe);
  drawn();
  ImGui::SameLine();
  ImGui::Checkbox("flat shadow", &v.shadow);
  drawn();
  float radius = static_cast<float>(v.tube_radius);
  if (ImGui::SliderFloat("tube radius", &radius, 0.002f, 0.3f, "%.3f", ImGuiSliderFlags_Logarithmic))
    v.tube_radius = radius;
  drawn();
  float opacity = static_cast<float>(v.opacity);
  if (ImGui::SliderFloat("opacity", &opacity, 0.05f, 1.0f, "%.2f")) v.opacity = opacity;
  drawn();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("below 1 a sheet behind shows through the one in front");
  ImGui::Checkbox("intersections and crossings", &v.intersections);
  drawn();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("where the shadow crosses itself: yellow only in the shadow (the sheets are\n"
                      "apart in w), magenta where the surface truly meets itself in R^4;\n"
                      "for curves, a white dot on the over strand of each crossing of this view;\n"
                      "right-click a dot to change that crossing");
  if (v.intersections && model.intersections.computed) {
    ImGui::TextWrapped("%s", intersection_text(model.intersections).c_str());
    if (!model.touch_and_sound_only)  // the codes would give the knot away
      for (const std::string& code : model.intersections.gauss_codes) ImGui::TextWrapped("%s", code.c_str());
  }
  if (model.audio) {
    ImGui::Separator();
    bool mute = model.audio->muted();
    if (ImGui::Checkbox("mute", &mute)) model.audio->set_mute(mute);
    ImGui::SameLine();
    float volume = model.audio->volume();
    if (ImGui::SliderFloat("volume", &volume, 0.0f, 1.0f, "%.2f")) model.audio->set_volume(volume);
    ImGui::Checkbox("depth tone", &model.depth_tone);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("while exploring (E), a continuous tone whose pitch follows the probe's depth:\n"
                        "high where it is near the eye (a knot) or near in w (a surface), low where far");
    ImGui::TextDisabled("%s", model.audio->status().c_str());
  }
  ImGui::End();
}

// [SECTION] Scene panel
void Panels::scene_panel(GuiModel& model) {
  ImGui::SetNextWindowPos(ImVec2(10, 600), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(330, 190), ImGuiCond_FirstUseEver);
  ImGui::Begin("Scene");
  Scene& scene = model.scene();
  if (scene.objects.empty()) ImGui::TextDisabled("empty: File > Open or Create");
  int remove = -1;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const auto& obj = scene.objects[i];
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::SmallButton("x")) remove = static_cast<int>(i);
    ImGui::SameLine();
    // A table knot's object is called by its name: not shown when the knot is to be found by touch.
    const bool hide = model.touch_and_sound_only && std::holds_alternative<Curve<3>>(obj.shape);
    ImGui::TextUnformatted(hide ? "a curve" : obj.name.c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s", describe_shape(obj.shape).c_str());
    ImGui::PopStyleColor();
    if (!hide && !model.hidden_knot_names.count(obj.name)) knot_name(obj);
    ImGui::PopID();
  }
  if (remove >= 0) {
    model.session.record("delete " + scene.objects[static_cast<std::size_t>(remove)].name);
    scene.objects.erase(scene.objects.begin() + remove);
    model.session.objects_changed();  // the other bodies keep their motion and pins
  }
  ImGui::End();
}

// A curve's knot: named live when it is small (KnotNames), on request when it is not.
void Panels::knot_name(const SceneObject& obj) {
  if (!KnotNames::nameable(obj)) return;
  if (const std::string* line = knot_names_.live(obj)) {
    ImGui::TextWrapped("%s", line->c_str());
    return;
  }
  if (ImGui::SmallButton("name the knot")) knot_names_.name(obj);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("more than %d crossings: naming it may take a while\n"
                      "(also: shadow4d knot identify FILE)", KnotNames::kLiveCrossings);
}

void Panels::toggle_relax(GuiModel& model) {
  Session& s = model.session;
  if (!s.simulating() || !curves_are_bodies(model.scene())) {
    model.status = "relax works on knots: open, sketch or create one";
    return;
  }
  const bool on = s.snapshot() && s.snapshot()->status.relaxing;
  if (!on) s.record("relax the knot");
  s.send(live_relax(!on));
  model.status = on ? "relaxing stopped: the knot rests as it is"
                    : "relaxing the knot, live (L stops it); it never passes through itself, so its name stays";
}

// [SECTION] Simulation panel
void Panels::simulation_panel(GuiModel& model) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 350, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(340, 520), ImGuiCond_FirstUseEver);
  ImGui::Begin("Simulation");
  Session& session = model.session;
  if (!session.simulating()) {
    if (!session.physics_error().empty()) {
      ImGui::TextColored(ImVec4(1, 0.55f, 0.3f, 1), "not simulated:");
      ImGui::TextWrapped("%s", session.physics_error().c_str());
      ImGui::TextDisabled("the scene stays viewable");
    } else {
      ImGui::TextWrapped("nothing to simulate: sketch a knot (K), or open or create an object");
    }
    ImGui::End();
    return;
  }
  const HapticSnapshot* snap = session.snapshot();
  const SceneStatus st = snap ? snap->status : SceneStatus{};
  if (ImGui::Button(st.playing ? "Pause" : "Play")) session.send(live_command(st.playing ? LiveCode::kPause : LiveCode::kPlay));
  ImGui::SameLine();
  if (ImGui::Button("Step")) session.send(live_command(LiveCode::kStepOnce));
  ImGui::SameLine();
  if (ImGui::Button("Reset")) {
    session.record("reset the simulation");
    session.send(live_command(LiveCode::kReset));
  }
  if (session.scenario()) {
    ImGui::SameLine();
    if (!st.script_running) {
      if (ImGui::Button("Play script")) session.send(live_command(LiveCode::kPlayScript));
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("from the start, the scenario's scripted hand does it (as shadow4d run does)");
    } else if (ImGui::Button("Stop script")) {
      session.send(live_command(LiveCode::kStopScript));
    }
  }
  float scale_before = model.time_scale;
  if (ImGui::SliderFloat("time scale", &model.time_scale, 0.05f, 2.0f, "%.2fx", ImGuiSliderFlags_Logarithmic))
    session.send(live_time_scale(model.time_scale));
  record_tool_setting(model, "change the time scale", [&] { std::swap(model.time_scale, scale_before); });
  if (curves_are_bodies(model.scene())) {
    if (ImGui::Button(st.relaxing ? "Stop relaxing (L)" : "Relax (L)")) toggle_relax(model);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("the knot energy (repulsion, even spacing, bending) pulls the knot towards a round,\n"
                        "even shape, live, until stopped; collision avoidance keeps every strand from passing\n"
                        "through another, so the knot stays the same (also: shadow4d knot relax CURVE --out OUT)");
    ImGui::SameLine();
    ImGui::TextDisabled("drag a strand: an isotopy (Alt: along the depth)");
  }

  ImGui::Separator();
  ImGui::TextUnformatted("Physics (applied live)");
  PhysicsSettings& p = model.scene().physics;
  const PhysicsSettings before = p;
  bool changed = false, released = false;
  // One change of a setting (a whole slider drag) is one undoable step, with the value before it.
  auto record_setting = [&] {
    const PhysicsSettings now = p;
    p = before;
    session.record("change the physics");
    p = now;
  };
  auto edited = [&] {
    if (ImGui::IsItemActivated()) record_setting();
    changed = changed || ImGui::IsItemEdited();
    released = released || ImGui::IsItemDeactivatedAfterEdit();
  };
  bool gravity_on = p.gravity.norm() > 0;
  static Vec4 gravity_saved(0, -9.81, 0, 0);
  if (ImGui::Checkbox("gravity", &gravity_on)) {
    record_setting();
    if (gravity_on) p.gravity = gravity_saved;
    else {
      gravity_saved = p.gravity;
      p.gravity.setZero();
    }
    released = true;
  }
  if (gravity_on) {
    float g[4] = {static_cast<float>(p.gravity[0]), static_cast<float>(p.gravity[1]), static_cast<float>(p.gravity[2]),
                  static_cast<float>(p.gravity[3])};
    if (ImGui::DragFloat4("g (x y z w)", g, 0.05f, -50.0f, 50.0f, "%.2f")) p.gravity = Vec4(g[0], g[1], g[2], g[3]);
    edited();
  }
  auto slider = [&](const char* label, double& value, double lo, double hi, const char* format, bool log) {
    float f = static_cast<float>(value);
    if (ImGui::SliderFloat(label, &f, static_cast<float>(lo), static_cast<float>(hi), format,
                           log ? ImGuiSliderFlags_Logarithmic : 0))
      value = f;
    edited();
  };
  slider("friction", p.friction, 0.0, 2.0, "%.2f", false);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("0 = slippery: the cloth slides off the ribbon");
  slider("stiffness N/m", p.stiffness, 1.0, 5000.0, "%.0f", true);
  slider("thickness", p.thickness, 0.001, 0.2, "%.3f", true);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the contact layer δ collision avoidance keeps between sheets in R^4");
  slider("damping N s/m", p.damping, 0.0, 1.0, "%.3f", false);
  int integrator = p.integrator == "paper-euler" || p.integrator == "explicit-euler" ? 1 : 0;
  if (ImGui::Combo("integrator", &integrator, kIntegratorNames, 2)) {
    record_setting();
    p.integrator = kIntegratorNames[integrator];
    released = true;
  }
  const auto now = std::chrono::steady_clock::now();
  if (released || (changed && now - last_settings_send_ > std::chrono::milliseconds(150))) {
    session.send(live_settings(p));
    last_settings_send_ = now;
  }
  if (st.message[0]) ImGui::TextColored(ImVec4(1, 0.55f, 0.3f, 1), "%s", st.message);

  ImGui::Separator();
  ImGui::TextUnformatted("Hand");
  if (snap) {
    for (int i = 0; i < snap->param_count && i < kLiveParamCount; ++i) {
      const SceneParam& sp = snap->params[i];
      double v = sp.value;
      char label[64];
      std::snprintf(label, sizeof label, "%s##band%d", sp.name, i);
      if (ImGui::SliderScalar(label, ImGuiDataType_Double, &v, &sp.min, &sp.max, "%.3g")) session.loop()->set_param(i, v);
      record_tool_setting(model, std::string("change the hand's ") + sp.name, [] {});
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", sp.unit);
    }
  }
  {  // the Touch tool: pull one vertex on the band, or carry a patch that stays where it is left
    GrabTool& g = model.grab;
    bool carry_before = g.carry();
    double radius_before = g.carry_radius();
    const auto put_back = [&] {
      const bool c = g.carry();
      const double r = g.carry_radius();
      g.set_carry(carry_before);
      g.set_carry_radius(radius_before);
      carry_before = c;
      radius_before = r;
    };
    bool carry = g.carry();
    if (ImGui::Checkbox("carry a patch (C)", &carry)) g.set_carry(carry);
    record_tool_setting(model, "change the touch", put_back);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("on: a drag carries the patch around the vertex (its radius along the surface),\n"
                        "which stays held where it is let go (clear pins or P frees it; Ctrl+Z undoes it);\n"
                        "off: a drag pulls one vertex on the rubber band");
    if (g.carry()) {
      float r = static_cast<float>(g.carry_radius());
      if (ImGui::SliderFloat("radius ([ ])", &r, static_cast<float>(GrabTool::kMinCarryRadius),
                             static_cast<float>(GrabTool::kMaxCarryRadius), "%.3f", ImGuiSliderFlags_Logarithmic))
        g.set_carry_radius(r);
      record_tool_setting(model, "change the carry radius", put_back);
    }
  }
  ImGui::Text("pins: %d", st.pinned);
  ImGui::SameLine();
  if (ImGui::SmallButton("clear pins")) {
    session.record("clear the pins");
    session.send(live_command(LiveCode::kClearPins));
  }
  if (st.held_vertex >= 0)
    ImGui::Text("holding vertex %d %s: %.2f N", st.held_vertex,
                st.grab_mode == 1 ? (session.dimension() == 3 ? "(along the depth)" : "(along w)") : "", st.band_force);

  ImGui::Separator();
  const SimulationRates r = session.rates();
  ImGui::Text("t = %s, %lld steps (%s)", seconds(st.sim_time).c_str(), static_cast<long long>(st.sim_steps),
              st.playing ? "playing" : "paused");
  ImGui::Text("%.0f steps/s, real-time ratio %.2f", r.steps_per_second, r.real_time_ratio);
  if (st.lag > 0.05) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "the physics cannot keep up: slow motion");
  ImGui::Text("contacts %d, rollbacks %lld, fail-safe freezes %lld", st.contacts, static_cast<long long>(st.rollbacks),
              static_cast<long long>(st.ccd_freezes + st.global_freezes));
  const MonitorResult c = session.checks();
  if (c.valid) {
    const ImVec4 colour = c.true_intersections == 0 ? ImVec4(0.5f, 0.95f, 0.5f, 1) : ImVec4(1, 0.3f, 0.3f, 1);
    ImGui::TextColored(colour, "true intersections: %d", c.true_intersections);
    if (std::isfinite(c.min_gap)) {
      ImGui::SameLine();
      ImGui::Text("  smallest gap %.4f", c.min_gap);
    }
    ImGui::TextDisabled("checked at t = %.2f s (%.0f ms a check)", c.sim_time, c.check_ms);
  } else {
    ImGui::TextDisabled("checking...");
  }
  ImGui::End();
}

// [SECTION] Scenario banner
void Panels::scenario_banner(GuiModel& model) {
  const auto& sc = model.session.scenario();
  const std::string& what_to_do = model.scene().instruction;
  if (!sc && what_to_do.empty()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, 30), ImGuiCond_FirstUseEver, ImVec2(0.5f, 0));
  ImGui::SetNextWindowSizeConstraints(ImVec2(200, 0), ImVec2(std::max(200.0f, std::min(560.0f, display.x - 700)), 400));
  ImGui::Begin(sc ? "Scenario" : "What to do", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + std::max(200.0f, std::min(540.0f, display.x - 720)));
  if (!sc) {  // a scene that says what to do with it by hand
    ImGui::TextWrapped("%s", what_to_do.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
    return;
  }
  ImGui::TextWrapped("%s: %s", sc->name.c_str(), sc->instruction.c_str());
  ImGui::TextDisabled("Space plays, Play script shows it done; shadow4d run %s gives the same verdict",
                      sc->file.filename().string().c_str());
  const MonitorResult c = model.session.checks();
  if (c.verdict) {
    const bool pass = c.verdict->pass && c.true_intersections == 0;
    ImGui::TextColored(pass ? ImVec4(0.5f, 0.95f, 0.5f, 1) : ImVec4(1, 0.75f, 0.35f, 1), "%s", pass ? "PASS" : "not yet");
    ImGui::SameLine();
    ImGui::TextWrapped("%s", c.verdict->detail.c_str());
  }
  ImGui::PopTextWrapPos();
  ImGui::End();
}

// The ribbon tool's options, while it is the tool.
void Panels::ribbon_panel(GuiModel& model) {
  if (model.tool != ToolChoice::kSketchRibbon) return;
  ImGui::SetNextWindowPos(ImVec2(350, ImGui::GetIO().DisplaySize.y - 150), ImGuiCond_FirstUseEver);
  ImGui::Begin("Ribbon", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  RibbonSketchOptions& o = model.ribbon.options;
  RibbonSketchOptions before = o;
  const auto put_back = [&] { std::swap(o, before); };
  float width = static_cast<float>(o.width);
  if (ImGui::SliderFloat("width", &width, 0.0f, 1.0f, width > 0 ? "%.3f" : "from the view")) o.width = width;
  record_tool_setting(model, "change the ribbon's width", put_back);
  ImGui::Checkbox("closed (a loop)", &o.closed);
  record_tool_setting(model, "change the ribbon's ends", put_back);
  ImGui::SliderInt("across", &o.across, 2, 8);
  record_tool_setting(model, "change the ribbon's rows", put_back);
  if (const SketchedRibbon* r = model.ribbon.last()) {
    ImGui::Text("last: %zu rows, length %.2f, %zu passage(s)", r->w.size(), r->length, r->passages.size());
    for (const RibbonPassage& p : r->passages)
      ImGui::BulletText("%s %s (gap %.3f)", p.below ? "below" : "above",
                        p.surface < 0 ? "itself" : "another surface", p.gap);
  }
  ImGui::End();
}

// Every step done (oldest first) and undone (greyed, next to redo first); the buttons walk it.
void Panels::history_panel(GuiModel& model) {
  if (!model.show_history) return;
  ImGui::SetNextWindowSize(ImVec2(300, 300), ImGuiCond_FirstUseEver);
  ImGui::Begin("History", &model.show_history);
  Session& s = model.session;
  const History& h = s.history();
  if (ImGui::Button("Undo")) undo_or_redo(model, false);
  ImGui::SameLine();
  if (ImGui::Button("Redo")) undo_or_redo(model, true);
  ImGui::SameLine();
  ImGui::TextDisabled("%zu step(s), %.1f MB", h.done_labels().size() + h.undone_labels().size(),
                      static_cast<double>(h.bytes()) / (1 << 20));
  ImGui::Separator();
  const auto done = h.done_labels();
  for (std::size_t i = 0; i < done.size(); ++i) ImGui::Text("%zu  %s", i + 1, done[i].c_str());
  for (const std::string& l : h.undone_labels()) ImGui::TextDisabled("    %s (undone)", l.c_str());
  if (done.empty() && !h.can_redo()) ImGui::TextDisabled("nothing done yet");
  ImGui::TextDisabled("the last %zu steps or %zu MB are kept", History::kMaxSteps, History::kMaxBytes >> 20);
  ImGui::End();
}

// After a crash or a kill: the autosave the last run left, taken up or set aside.
void Panels::restore_dialog(GuiModel& model) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.3f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::Begin("Restore your work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
  const SessionFile& f = *model.pending_restore;
  const double ago = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count() - f.saved_at;
  ImGui::Text("The last run did not quit normally. Its autosave (from '%s', %.0f s ago) holds", f.opened.c_str(), ago);
  ImGui::Text("%zu object(s) and %d step(s) of work.", f.scene.objects.size(), f.history_head);
  if (ImGui::Button("Restore")) {
    const SessionFile saved = *model.pending_restore;
    model.pending_restore.reset();
    open_session(model, saved, model.autosave_path);
  }
  ImGui::SameLine();
  if (ImGui::Button("Start afresh")) {
    model.pending_restore.reset();
    model.status = "the autosave stays in " + model.autosave_path + " until the next one";
  }
  ImGui::End();
}

// [SECTION] Generator dialog
void Panels::generator_dialog(GuiModel& model) {
  if (!generator_dialog_open_) return;
  const GeneratorInfo* info = find_generator(generator_);
  if (!info) {
    generator_dialog_open_ = false;
    return;
  }
  ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_Appearing);
  ImGui::Begin(("Create " + info->name).c_str(), &generator_dialog_open_);
  ImGui::TextWrapped("%s", info->description.c_str());
  for (const auto& p : info->params) {
    double& value = generator_params_[p.name];
    if (p.integer) {
      int i = static_cast<int>(std::lround(value));
      ImGui::DragInt(p.name.c_str(), &i, 0.25f, static_cast<int>(p.min), static_cast<int>(p.max));
      value = i;
    } else {
      float f = static_cast<float>(value);
      ImGui::DragFloat(p.name.c_str(), &f, static_cast<float>((p.max - p.min) / 500.0),
                       static_cast<float>(p.min), static_cast<float>(p.max), "%.3f");
      value = f;
    }
    if (ImGui::IsItemHovered() && !p.help.empty()) ImGui::SetTooltip("%s", p.help.c_str());
  }
  // Where the object goes: its offset from where the generator puts it (usually the origin).
  float at[4] = {static_cast<float>(generator_offset_[0]), static_cast<float>(generator_offset_[1]),
                 static_cast<float>(generator_offset_[2]), static_cast<float>(generator_offset_[3])};
  const bool in_r4 = info->dim == 4;
  if (in_r4 ? ImGui::DragFloat4("position (x y z w)", at, 0.01f, -100.0f, 100.0f, "%.2f")
            : ImGui::DragFloat3("position (x y z)", at, 0.01f, -100.0f, 100.0f, "%.2f"))
    generator_offset_ = Vec4(at[0], at[1], at[2], in_r4 ? at[3] : 0.0f);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("added beside what is in the scene (also: a scene's \"offset\", or NAME:k=v@x,y,z[,w])");
  const bool replace = ImGui::Button("Replace scene");
  ImGui::SameLine();
  const bool add = ImGui::Button("Add to scene");
  if (replace || add) {
    try {
      SceneObject obj;
      obj.generator = GeneratorCall{info->name, generator_params_};
      obj.placement.offset = generator_offset_;
      obj.shape = placed(generate(info->name, generator_params_), obj.placement);
      obj.name = info->name + "-" + std::to_string(model.created + 1);
      if (replace) {
        Document d;
        d.spec = info->name;
        d.scene.objects.push_back(std::move(obj));
        open(model, std::move(d));
        if (info->dim == 4) model.view.turn_to_generic_view();
      } else {
        const std::string label = "create " + obj.name;
        model.session.add_object(std::move(obj), label);  // the bodies there keep their motion and pins
      }
      ++model.created;
      model.status = "created " + info->name;
    } catch (const std::exception& e) {
      model.error = e.what();
    }
  }
  ImGui::End();
}

// [SECTION] Dialogs (open, save, screenshot, errors)
void Panels::dialogs(GuiModel& model) {
  if (auto p = open_browser_.draw()) open(model, p->string());
  if (auto p = session_browser_.draw()) {
    try {
      auto path = *p;
      if (path.extension() != ".s4d") path += ".s4d";
      write_session(model.session.save_state(), path);
      model.status = "saved the session " + path.string();
    } catch (const std::exception& e) {
      model.error = e.what();
    }
  }
  if (model.pending_restore) restore_dialog(model);
  if (auto p = save_browser_.draw()) {
    try {
      auto path = *p;
      if (path.extension() != ".json") path += ".json";
      save_scene(scene_to_save(model), path);
      model.status = "saved " + path.string();
    } catch (const std::exception& e) {
      model.error = e.what();
    }
  }
  if (auto p = stroke_browser_.draw()) {
    try {
      const auto path = p->extension() == ".txt" ? *p : std::filesystem::path(p->string() + ".txt");
      write_shape_file(model.knot.last_stroke_curve(), path);
      model.status = "saved " + path.string() + " (shadow4d knot sketch " + path.filename().string() + " --knot)";
    } catch (const std::exception& e) {
      model.error = e.what();
    }
  }
  if (auto p = diagram_browser_.draw()) {
    try {
      const ImVec2 size = ImGui::GetIO().DisplaySize;
      const std::string written = export_diagram(scene_to_save(model), *p, static_cast<int>(size.x), static_cast<int>(size.y));
      model.status = "wrote the crossing diagram of this view to " + written;
    } catch (const std::exception& e) {
      model.error = e.what();
    }
  }
  if (auto p = shot_browser_.draw()) {
    model.screenshot_path = p->extension() == ".png" ? p->string() : p->string() + ".png";
    model.want_screenshot = true;
  }
  // A plain window, not a modal popup: ImGui 1.86 asserts when a window appears for the first
  // time (the auto-sized panels do on frame 2) while a modal is open, e.g. after a failed open.
  if (!model.error.empty()) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.4f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(480, 0), ImGuiCond_Appearing);
    bool open = true;
    ImGui::Begin("Error", &open, ImGuiWindowFlags_NoCollapse);
    ImGui::TextWrapped("%s", model.error.c_str());
    if (ImGui::Button("OK")) open = false;
    ImGui::End();
    if (!open) model.error.clear();
  }
}

}  // namespace s4d
