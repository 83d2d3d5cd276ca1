// The window's panels: [SECTION] Opening   [SECTION] Menu bar   [SECTION] Dialogs (open, save,
// screenshot, errors). The view and scene panels are in panels_view.cpp; the simulation, scenario,
// ribbon, history and generator panels in panels_simulation.cpp.
#include "app/panels.hpp"

#include "app/slice_panel.hpp"

#include <imgui.h>

#include <cmath>

#include "app/browser.hpp"
#include "app/panel_settings.hpp"
#include "app/tool_settings.hpp"
#include "core/error.hpp"
#include "interact/live/live_simulation.hpp"
#include "io/object_file.hpp"
#include "io/recent_files.hpp"
#include "render/diagram_export.hpp"

namespace s4d {

using panel_detail::record_tool_setting;

namespace {

const std::vector<std::string> kOpenExtensions{".json", ".s4d", ".off", ".4off", ".noff", ".vect",
                                               ".4vect", ".txt", ".xyz", ".curve"};

}  // namespace

// [SECTION] Opening
ViewFit fit_of(const Scene& scene) {
  ViewFit f;
  std::vector<Vec4> pts;
  for (const SceneObject& o : scene.objects)
    for_each_point(o.shape, [&](const auto& p) {
      Vec4 q = Vec4::Zero();
      q.head(p.size()) = p;
      pts.push_back(q);
    });
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

void frame_on(GuiModel& model, const Scene& only) {
  if (only.objects.empty()) return;
  model.fit = fit_of(only);
  model.view.unzoom();
}

void frame_all(GuiModel& model) { frame_on(model, model.scene()); }

double probe_depth_fraction(const Scene& scene, const ViewFit& fit, const Vec3& toward_eye, bool on_curve,
                            double probe_w) {
  if (!(fit.radius > 0) || !std::isfinite(probe_w)) return 0.5;
  const double centre = on_curve ? toward_eye.dot(fit.centre.head<3>()) : scene.frame.to_view(fit.centre)(3);
  return std::clamp(0.5 + 0.5 * (probe_w - centre) / fit.radius, 0.0, 1.0);
}

namespace {

// A file opened or saved goes to the start page's recent list.
void remember(const GuiModel& model, const std::string& spec) {
  std::error_code ec;
  if (model.autosave_path.empty() || !std::filesystem::is_regular_file(spec, ec)) return;
  recent_files(model).add(spec);
}

}  // namespace

RecentFiles recent_files(const GuiModel& model) {
  return RecentFiles(std::filesystem::path(model.autosave_path).parent_path() / "recent.txt");
}

std::filesystem::path example_folder(GuiModel& model, std::filesystem::path DataDirs::*folder) {
  std::string why;
  if (const std::optional<DataDirs> d = try_data_dirs(&why)) return (*d).*folder;
  model.status = why;
  return ".";
}

void Panels::open(GuiModel& model, const std::string& spec) {
  try {
    if (spec.size() > 4 && spec.ends_with(".s4d")) {
      open_session(model, read_session(spec), spec);
      remember(model, spec);
      return;
    }
    open(model, load_document(spec));
    remember(model, spec);
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
  model.start_page = false;
  model.view.reset(model.scene());
  model.view.set_base_frame(saved.view.base_frame);
  model.view.set(saved.view.angles, saved.view.trackball, saved.view.zoom);
  model.view.set_perspective(saved.view.perspective);  // checked when read
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
  // A scenario opens paused in its start state; so does a scene under gravity with nothing
  // pinned (none can pin at open), which would otherwise fall out of view before it is seen.
  const bool would_fall = !scenario && doc.scene.physics.gravity.norm() > 0;
  options.start_playing = !scenario && !would_fall;
  model.session.open(std::move(doc), options);
  model.start_page = false;
  model.view.reset(model.scene());
  if (!scene_file && !model.scene().objects.empty() && ambient_dim(model.scene().objects[0].shape) == 4)
    model.view.turn_to_generic_view();
  model.fit = fit_of(model.scene());
  model.status = "opened " + spec;  // its instruction is in the band above the view
  if (would_fall && model.session.simulating())
    model.status += ": paused, since under gravity with nothing pinned everything falls (Space plays; "
                    "Simulation > Pin the top holds it up)";
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

// An exercise asked for from the menus or the start page has a scene of its own; the scene it
// left is kept whole (as a session) and comes back when the user leaves the exercise.
void Panels::exercise_scene(GuiModel& model) {
  if ((model.open_same_knot || model.open_unknot) && !model.exercise_return) {
    model.exercise_return = model.session.save_state();
    Document d;
    d.spec = "an exercise";
    open(model, std::move(d));
  }
  if (std::exchange(model.leave_exercise, false) && model.exercise_return) {
    const SessionFile back = std::move(*model.exercise_return);
    model.exercise_return.reset();
    open_session(model, back, "the scene before the exercise");
    model.status = "left the exercise: back to the scene before it";
  }
}

void Panels::draw(GuiModel& model, float fps) {
  menu_bar(model);
  exercise_scene(model);
  if (std::exchange(model.open_file_dialog, false)) open_dialog(model);
  if (std::exchange(model.save_session_dialog, false)) session_browser_.open(".");
  if (model.start_page) {  // the page is drawn by the window; only the menus and dialogs here
    dialogs(model);
    return;
  }
  view_panel(model, fps);
  scene_panel(model);
  simulation_panel(model);
  scenario_banner(model);
  ribbon_panel(model);
  history_panel(model);
  messages_panel(model);
  keys_panel(model);
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
    if (ImGui::MenuItem("Start page", nullptr, model.start_page)) model.start_page = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the paper's examples, the exercises, recent files, the keys");
    if (ImGui::MenuItem("Open...", "Ctrl+O")) open_dialog(model);
    if (ImGui::MenuItem("Open a scenario...")) open_browser_.open(example_folder(model, &DataDirs::scenarios));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the paper's physical examples (scenarios/*.json), paused at their start");
    if (ImGui::MenuItem("Save scene...")) save_browser_.open(".");
    if (ImGui::MenuItem("Save session...", "Ctrl+S")) session_browser_.open(".");
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
    if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z, Ctrl+Y", false, h.can_redo())) undo_or_redo(model, true);
    ImGui::MenuItem("History", nullptr, &model.show_history);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Frame all", "F")) model.want_frame = true;
    if (ImGui::MenuItem("Reset the 4D rotation")) {
      model.session.record("turn in 4D");
      model.view.plane_angles().fill(0.0f);
    }
    if (ImGui::MenuItem("Slice by w = c", "W", model.scene().view.slice, has_4d_surfaces(model.scene())))
      toggle_slice(model);
    ImGui::Separator();
    ImGui::MenuItem("Left panels", nullptr, &model.left_open);
    ImGui::MenuItem("Right panels", nullptr, &model.right_open);
    ImGui::MenuItem("Messages", nullptr, &model.show_messages);
    ImGui::SetNextItemWidth(120 * model.ui_scale);
    ImGui::SliderFloat("UI scale", &model.ui_scale_setting, 0.5f, 3.0f, "%.2f");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("times the monitor's own scale (also: shadow4d --ui-scale S)");
    ImGui::EndMenu();
  }
  for (const char* menu : {"Tools", "Create"}) {
    if (!ImGui::BeginMenu(menu)) continue;
    for (const ToolEntry& e : tool_entries()) {
      if (std::string_view(e.menu) != menu) continue;
      if (ImGui::MenuItem(e.label, e.key_name, model.tool == e.id)) model.choose(model.tool == e.id ? ToolChoice::kTouch : e.id);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.tooltip);
    }
    if (std::string_view(menu) == "Tools") {
      ImGui::EndMenu();
      continue;
    }
    if (ImGui::MenuItem("Knot from the table...")) model.open_knot_table = true;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("3_1 ... 10_165, 11n_34, 12a_803, torus knots T(p,q), links; a relaxed 3D curve of it\n"
                        "(also: shadow4d knot make NAME --out K.curve)");
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
  if (ImGui::BeginMenu("Exercises")) {
    if (ImGui::MenuItem("Untangle the unknot (Fig. 15)"))
      open(model, (example_folder(model, &DataDirs::scenes) / "fig15-tangled-unknot.json").string());
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("a tangled curve that is the unknot: show it by dragging strands (Alt: along the depth)\n"
                        "until its picture has no crossing; a drag never changes the knot\n"
                        "(also: shadow4d scenes/fig15-tangled-unknot.json)");
    if (ImGui::MenuItem("Are these the same knot?")) model.open_same_knot = true;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("two knots from the table side by side, the second turned: say whether they are the same\n"
                        "(also: shadow4d knot exercise same)");
    if (ImGui::MenuItem("Unknot it by one crossing change")) model.open_unknot = true;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("a knot of unknotting number one: right-click the crossing that unknots it\n"
                        "(also: shadow4d knot exercise unknot)");
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Haptics")) {
    if (ImGui::MenuItem("Haptics panel (device, loop, forces)")) model.open_haptics = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Keys", "? F1", &model.show_keys)) {}
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

// Every message of the status line, whole and newest last (the status line shows one, cut to fit).
void Panels::messages_panel(GuiModel& model) {
  if (!model.show_messages || !model.dock.begin(Side::kLeft, "Messages", &model.show_messages)) return;
  if (ImGui::SmallButton("Clear")) model.messages.clear();
  ImGui::BeginChild("log", ImVec2(0, 10 * ImGui::GetTextLineHeightWithSpacing()), true);
  ImGui::PushTextWrapPos(0);
  for (const std::string& m : model.messages) ImGui::TextUnformatted(m.c_str());
  ImGui::PopTextWrapPos();
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);  // follow the newest
  ImGui::EndChild();
  model.dock.end();
}

// Help > Keys, ? and F1: the window's keys, then the active tool's.
void Panels::keys_panel(GuiModel& model) {
  if (!model.show_keys || !model.dock.begin(Side::kRight, "Keys", &model.show_keys)) return;
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
    for (const KeyHelp& k : window_keys()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(k.keys);
      ImGui::TableNextColumn();
      ImGui::PushTextWrapPos(0);
      ImGui::TextUnformatted(k.what);
      ImGui::PopTextWrapPos();
    }
    ImGui::EndTable();
  }
  ImGui::Separator();
  ImGui::Text("%s (the active tool):", model.active_tool()->name());
  ImGui::PushTextWrapPos(0);
  ImGui::TextUnformatted(model.active_tool()->help().c_str());
  ImGui::PopTextWrapPos();
  model.dock.end();
}

// [SECTION] Dialogs (open, save, screenshot, errors)
// File > Open: in the web page the browser's own file picker (the chosen file comes back as a
// dropped one does, app/browser.hpp); on the desktop the window's browser, at the example scenes.
void Panels::open_dialog(GuiModel& model) {
  if (choose_file_to_open(kOpenExtensions)) {
    model.status = "choose a file in the browser's dialog";
    return;
  }
  open_browser_.open(example_folder(model, &DataDirs::scenes));
}

void Panels::dialogs(GuiModel& model) {
  if (auto p = open_browser_.draw()) open(model, p->string());
  if (auto p = session_browser_.draw()) {
    try {
      auto path = *p;
      if (path.extension() != ".s4d") path += ".s4d";
      write_session(model.session.save_state(), path);
      model.status = "saved the session " + path.string();
      if (offer_download(path.string())) model.status += " (and downloaded)";
      remember(model, path.string());
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
      if (offer_download(path.string())) model.status += " (and downloaded)";
    } catch (const std::exception& e) {
      model.error = e.what();
    }
  }
  if (auto p = stroke_browser_.draw()) {
    try {
      const auto path = p->extension() == ".txt" ? *p : std::filesystem::path(p->string() + ".txt");
      write_shape_file(model.knot.last_stroke_curve(), path);
      offer_download(path.string());
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
