// The ImGui panels of the window: menu bar, view (4D rotation, colour, style), scene list,
// simulation (play, settings, status, checks), the scenario's instruction and verdict, generator
// dialog, legend, status line. They edit a GuiModel; the window loop acts on its requests.
#pragma once
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/dock.hpp"
#include "app/file_browser.hpp"
#include "app/knot_names.hpp"
#include "app/tool_registry.hpp"
#include "io/recent_files.hpp"
#include "app/view_state.hpp"
#include "audio/audio_player.hpp"
#include "core/data_paths.hpp"
#include "interact/tools/explore_tool.hpp"
#include "interact/tools/grab_tool.hpp"
#include "interact/tools/knot_sketch_tool.hpp"
#include "interact/tools/ribbon_tool.hpp"
#include "interact/session/session.hpp"
#include "io/scene.hpp"
#include "render/scene_geometry.hpp"

namespace s4d {

enum class ToolChoice { kTouch, kExplore, kSketchRibbon, kSketchKnot };

// How the view frames the document: a ball fixed when it opens (its 4D centre is seen through the
// frame), so the picture holds still while the simulation moves the objects under the hand.
struct ViewFit {
  Vec4 centre = Vec4::Zero();
  double radius = 0;
};
ViewFit fit_of(const Scene& scene);

// The explore probe's depth for the depth tone, in [0, 1]: 0 at the far side of the view's ball,
// 1 at the near side — towards the eye for a knot (probe_w is then its view depth, the eye
// direction `toward_eye`), towards +w for a surface of R^4 (probe_w its w through scene.frame).
double probe_depth_fraction(const Scene& scene, const ViewFit& fit, const Vec3& toward_eye, bool on_curve,
                            double probe_w);

// What the window shows and edits: the document and its live simulation (session), how it is
// looked at (view), the active tool, and the requests the panels leave for the window loop.
struct GuiModel {
  Session session;
  SessionOptions session_options;
  ViewState view;
  ViewFit fit;
  std::string status;          // last message for the status line
  std::string error;           // shown until dismissed
  std::vector<std::string> messages;  // every status message, whole (the Messages panel)
  // [layout]
  Layout layout;               // this frame's (compute_layout)
  Dock dock;
  float ui_scale = 1;          // the monitor's content scale times ui_scale_setting
  float ui_scale_setting = 1;  // View > UI scale
  bool left_open = true, right_open = true;  // the panel columns (View > Panels)
  // [requests]
  bool quit = false;
  bool want_screenshot = false;
  std::string screenshot_path = "shadow4d-screenshot.png";
  bool open_haptics = false;   // show the haptics panel
  bool show_history = false;   // Edit > History
  bool show_messages = false;  // View > Messages
  bool want_frame = false;     // F, View > Frame all: fit every object in the view
  double perspective_distance = 0;  // the View panel's last 4D eye distance (0: none chosen yet)
  std::vector<std::pair<std::string, Rect>> view_controls;  // the View panel's perspective controls drawn this frame
  bool touch_and_sound_only = false;  // the picture hidden: the knot explored by feel and ear (H)
  bool open_knot_table = false;  // Create > Knot from the table
  bool open_same_knot = false;   // Exercises > Are these the same knot?
  bool open_unknot = false;      // Exercises > Unknot it by one crossing change
  bool show_keys = false;        // Help > Keys, ? and F1
  Rect slice_button;             // the status line's Slice button as drawn this frame (for dumps)
  bool start_page = false;       // the start page in the view's place (no file given; File > Start page)
  std::vector<std::pair<std::string, Rect>> start_cards;  // its cards and buttons, drawn this frame
  bool open_file_dialog = false; // File > Open, asked from elsewhere (the start page, Ctrl+O)
  bool save_session_dialog = false;  // File > Save session, asked by Ctrl+S
  std::optional<SessionFile> exercise_return;  // the scene an exercise left, to go back to
  bool leave_exercise = false;   // the exercise's "Leave" button
  // [hints] the scenario's markers (app/hint_markers.hpp)
  std::string hint_next;         // what Show me will show ("" when nothing is left to do)
  std::string hint_progress;     // the verdict's progress line, as shown
  bool show_me = false;          // the band's Show me button
  std::string knot_panel_name;   // what the Knot panel names the selected curve (for dumps)
  std::set<std::string> hidden_knot_names;  // objects whose knot name is an exercise's answer
  bool depth_tone = false;       // while exploring, a tone whose pitch follows the probe's depth
  std::optional<SessionFile> pending_restore;  // an unfinished run's autosave, offered at start
  std::string autosave_path;
  float time_scale = 1;          // the simulation's, sent live (Simulation panel)
  std::map<std::string, double> pending_settings;  // tool settings waiting for the loop (tool_settings.hpp)
  // [tools]
  ToolChoice tool = ToolChoice::kTouch;
  GrabTool grab;
  ExploreTool explore;
  RibbonTool ribbon;
  KnotSketchTool knot;
  // [drawn]
  IntersectionSummary intersections;  // of the last frame drawn (view.intersections)
  int created = 0;             // counter for unique object names

  std::unique_ptr<AudioPlayer> audio;  // the cues of exploring (silent when no device)

  Scene& scene() { return session.scene(); }
  // The tool the mouse drives now.
  Tool* active_tool() { return &tool_entry(tool).get(*this); }
  void choose(ToolChoice t) {
    if (tool == ToolChoice::kSketchKnot && t != tool) knot.leave(session);
    tool = t;
    if (Tool* a = active_tool()) status = a->help();
  }
  bool sketching() const { return tool == ToolChoice::kSketchKnot; }
};

class Panels {
 public:
  Panels();
  // Draws every panel for this frame; `fps` is shown in the view panel.
  void draw(GuiModel& model, float fps);

  // Replaces the document with what `spec` names (scene, scenario, mesh, curve or generator
  // call) and starts simulating it; a scenario opens paused. Errors go to model.error and leave
  // the current document untouched.
  static void open(GuiModel& model, const std::string& spec);
  // Takes a document already read (the window's start, a test).
  static void open(GuiModel& model, Document doc);
  // Ctrl+Z / Ctrl+Shift+Z, the Edit menu and the History panel: the active tool's unfinished work
  // first (strokes not yet a knot), then the session's history; the status line says what.
  static void undo_or_redo(GuiModel& model, bool redo);
  // Takes up a saved session (File > Open of a .s4d, the autosave after a crash).
  static void open_session(GuiModel& model, const SessionFile& saved, const std::string& path);
  // Relax (the knot energy driving the simulated knots, live) on or off (L, the Simulation
  // panel); starting it is one undoable step.
  static void toggle_relax(GuiModel& model);

 private:
  void menu_bar(GuiModel& model);
  void exercise_scene(GuiModel& model);
  void view_panel(GuiModel& model, float fps);
  void scene_panel(GuiModel& model);
  void simulation_panel(GuiModel& model);
  void physics_settings(GuiModel& model, const SceneStatus& st);
  void hand_settings(GuiModel& model, const SceneStatus& st);
  void simulation_status(GuiModel& model, const SceneStatus& st);
  void scenario_banner(GuiModel& model);
  void ribbon_panel(GuiModel& model);
  void history_panel(GuiModel& model);
  void messages_panel(GuiModel& model);
  void keys_panel(GuiModel& model);
  void restore_dialog(GuiModel& model);
  void knot_name(const SceneObject& obj);
  void generator_dialog(GuiModel& model);
  void dialogs(GuiModel& model);
  void open_dialog(GuiModel& model);

  FileBrowser open_browser_;
  FileBrowser save_browser_;
  FileBrowser session_browser_;
  FileBrowser shot_browser_;
  FileBrowser stroke_browser_;
  FileBrowser diagram_browser_;
  std::string generator_;      // generator whose dialog is open
  Params generator_params_;
  Vec4 generator_offset_ = Vec4::Zero();  // where Add to scene puts the object
  bool generator_dialog_open_ = false;
  KnotNames knot_names_;  // the Scene panel's named knots
  std::chrono::steady_clock::time_point last_settings_send_{};
};

// The document's scene with the live shapes as they are now, objects moved by the simulation
// turned into edited geometry (saved as meshes beside the scene file), the view's frame written in.
Scene scene_to_save(GuiModel& model);

// F and View > Frame all: every object in the view (the ball of their points, zoom 1, no pan);
// frame_on: the objects of `only` (a knot from the table, an exercise's knots).
void frame_all(GuiModel& model);

// The recent sessions and files (the start page's), kept beside the window's autosave.
RecentFiles recent_files(const GuiModel& model);
// The example scenes or scenarios of the program's data (core/data_paths.hpp), e.g.
// example_folder(model, &DataDirs::scenes); the working folder, the reason in the status line,
// when the data cannot be found.
std::filesystem::path example_folder(GuiModel& model, std::filesystem::path DataDirs::*folder);
void frame_on(GuiModel& model, const Scene& only);

// The scenario's name and instruction, or the scene's, for the band above the view; and how many
// lines it takes in a band `width` pixels wide (with the verdict's line), for the layout.
std::string instruction_text(GuiModel& model);
int instruction_lines(GuiModel& model, float width);

}  // namespace s4d
