// The ImGui panels of the window: menu bar, view (4D rotation, colour, style), scene list,
// generator dialog, legend, status line. They edit a GuiModel; the window loop acts on requests.
#pragma once
#include <optional>
#include <string>

#include "app/file_browser.hpp"
#include "app/knot_names.hpp"
#include "app/view_state.hpp"
#include "io/scene.hpp"
#include "render/scene_geometry.hpp"

namespace s4d {

// The status line while sketching (Create > Sketch a knot).
inline constexpr const char* kSketchHelp =
    "sketch: drag to draw a closed curve; hold shift where it passes under; Esc stops";

struct GuiModel {
  Scene scene;                 // what is shown (its frame/view are rewritten from `view` each frame)
  ViewState view;
  std::string status;          // last message for the status line
  std::string error;           // shown in a modal until dismissed
  bool quit = false;
  bool want_screenshot = false;
  std::string screenshot_path = "shadow4d-screenshot.png";
  int created = 0;             // counter for unique object names
  bool open_haptics = false;   // request from the menu: show the haptics panel (starts the loop)
  IntersectionSummary intersections;  // of the last frame drawn (view.intersections)
  bool sketching = false;      // Create > Sketch a knot: the left button draws (SketchTool)
  Curve<3> last_stroke;        // the last sketch's stroke (stroke_as_curve), for File > Save
};

class Panels {
 public:
  Panels();
  // Draws every panel for this frame; `fps` is shown in the view panel.
  void draw(GuiModel& model, float fps);

  // Replaces the scene with what `spec` names (file or generator call); errors go to model.error
  // and leave the current scene untouched.
  static void open(GuiModel& model, const std::string& spec);

 private:
  void menu_bar(GuiModel& model);
  void view_panel(GuiModel& model, float fps);
  void scene_panel(GuiModel& model);
  void knot_name(const SceneObject& obj);
  void generator_dialog(GuiModel& model);
  void dialogs(GuiModel& model);

  FileBrowser open_browser_;
  FileBrowser save_browser_;
  FileBrowser shot_browser_;
  FileBrowser stroke_browser_;
  std::string generator_;      // generator whose dialog is open
  Params generator_params_;
  bool generator_dialog_open_ = false;
  KnotNames knot_names_;  // the Scene panel's named knots
};

}  // namespace s4d
