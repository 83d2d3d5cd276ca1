// The window's input: the keys of the window and of the active tool, the mouse on the view (the
// tool's drag, turning, panning, the right click), and the status line's tool buttons.
// Sections: [SECTION] input routing, [SECTION] status line.
#include "app/window_routing.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/knot_panels.hpp"
#include "app/panels.hpp"
#include "app/slice_panel.hpp"
#include "app/tool_registry.hpp"
#include "interact/live/live_simulation.hpp"
#include "interact/tools/view_edit.hpp"

namespace s4d {

namespace {

// [SECTION] input routing
// Moves the picture by (dx, dy) pixels of the view.
void pan_pixels(GuiModel& model, const ToolView& v, double dx, double dy) {
  const double r = model.fit.radius > 0 ? model.fit.radius : 1;
  model.view.pan_by(dx * v.pixel_size / r, -dy * v.pixel_size / r);
}

// The keys of the whole window: quitting, undo, play, the tools' keys, framing and panning.
void window_keys(GuiModel& model, const Routing& r, const WindowInput& in, const ToolInput& ti) {
  Session& session = model.session;
  Tool* tool = model.active_tool();
  if (in.key_pressed(GLFW_KEY_ESCAPE)) {  // drops what the tool has under way, and always back to Touch
    const bool dropped = tool && tool->key(ToolKey::kEscape, ti, session);
    if (model.tool != ToolChoice::kTouch) {
      const std::string said = dropped ? tool->take_message() : std::string();
      model.choose(ToolChoice::kTouch);
      if (!said.empty()) model.status = said + "; back to Touch";
    }
  }
  if (in.ctrl() && in.key_pressed(GLFW_KEY_Q)) model.quit = true;
  if (in.ctrl() && in.key_pressed(GLFW_KEY_O)) model.open_file_dialog = true;
  if (in.ctrl() && in.key_pressed(GLFW_KEY_S)) model.save_session_dialog = true;
  if (in.ctrl() && in.key_pressed(GLFW_KEY_Z) && !r.tool_drag) Panels::undo_or_redo(model, in.shift());
  if (in.ctrl() && in.key_pressed(GLFW_KEY_Y) && !r.tool_drag) Panels::undo_or_redo(model, true);
  if (in.key_pressed(GLFW_KEY_F12)) model.want_screenshot = true;
  if (in.key_pressed(GLFW_KEY_F1) || in.key_pressed(GLFW_KEY_SLASH)) model.show_keys = !model.show_keys;
  if (in.key_pressed(GLFW_KEY_SPACE) && session.snapshot()) {
    const bool playing = session.snapshot()->status.playing;
    session.send(playing ? live::Request(live::Pause{}) : live::Request(live::Play{}));
    model.status = playing ? "paused (Space plays)" : "playing (Space pauses)";
  }
  if (!r.tool_drag && !in.ctrl())
    for (const ToolEntry& e : tool_entries())
      if (in.key_pressed(e.key)) model.choose(e.id);
  if (in.key_pressed(GLFW_KEY_F) && !in.ctrl()) model.want_frame = true;
  const double step = 0.08 * ti.view.window.y();  // an arrow key pans by a twelfth of the view
  if (in.key_pressed(GLFW_KEY_LEFT)) pan_pixels(model, ti.view, -step, 0);
  if (in.key_pressed(GLFW_KEY_RIGHT)) pan_pixels(model, ti.view, step, 0);
  if (in.key_pressed(GLFW_KEY_UP)) pan_pixels(model, ti.view, 0, -step);
  if (in.key_pressed(GLFW_KEY_DOWN)) pan_pixels(model, ti.view, 0, step);
  if (in.key_pressed(GLFW_KEY_H)) {
    model.touch_and_sound_only = !model.touch_and_sound_only;
    model.status = model.touch_and_sound_only ? "touch and sound only: the picture is hidden (H shows it)" : "the picture is back";
  }
  if (in.key_pressed(GLFW_KEY_W) && !in.ctrl()) toggle_slice(model);  // the slice w = c (Slice panel)
  if (in.key_pressed(GLFW_KEY_L) && !r.tool_drag) Panels::toggle_relax(model);  // the knot energy, live
  if (in.key_pressed(GLFW_KEY_M)) {  // the next curve display mode (Fig. 1 a, b, c)
    session.record("change the drawing");
    CurveMode& mode = model.scene().view.curve_mode;
    mode = mode == CurveMode::kTubes ? CurveMode::kShadow : mode == CurveMode::kShadow ? CurveMode::kDiagram : CurveMode::kTubes;
    model.status = std::string("curves drawn as: ") + curve_mode_name(mode);
  }
}

// The keys the active tool takes.
void tool_keys(Tool& tool, const WindowInput& in, const ToolInput& ti, Session& session) {
  static constexpr std::pair<int, ToolKey> kKeys[] = {
      {GLFW_KEY_TAB, ToolKey::kTab},          {GLFW_KEY_P, ToolKey::kPin},
      {GLFW_KEY_BACKSPACE, ToolKey::kBackspace}, {GLFW_KEY_C, ToolKey::kCarry},
      {GLFW_KEY_LEFT_BRACKET, ToolKey::kSmaller}, {GLFW_KEY_RIGHT_BRACKET, ToolKey::kLarger},
      {GLFW_KEY_ENTER, ToolKey::kEnter},      {GLFW_KEY_KP_ENTER, ToolKey::kEnter}};
  for (const auto& [key, what] : kKeys)
    if (in.key_pressed(key) && !in.ctrl()) tool.key(what, ti, session);
}

// The right button: a click (released where it was pressed) changes the crossing under it or goes
// to the tool (pin); a drag pans, as the middle button's does.
void right_and_middle(GuiModel& model, Routing& r, const WindowInput& in, const ToolInput& ti, bool captured,
                      KnotPanels& knots) {
  Session& session = model.session;
  if (in.pressed(1) && !captured) {
    r.right_down = true, r.right_panned = false;
    r.right_at = in.cursor();
  }
  if (in.pressed(2) && !captured) r.middle_pan = true;
  const Vec2 d = in.cursor_delta();
  if (r.right_down && in.down(1) && (r.right_panned || (in.cursor() - r.right_at).norm() > 4)) {
    pan_pixels(model, ti.view, r.right_panned ? d.x() : (in.cursor() - r.right_at).x(),
               r.right_panned ? d.y() : (in.cursor() - r.right_at).y());
    r.right_panned = true;
  }
  if (r.middle_pan && in.down(2)) pan_pixels(model, ti.view, d.x(), d.y());
  if (!in.down(2)) r.middle_pan = false;
  if (r.right_down && (in.released(1) || !in.down(1))) {
    r.right_down = false;
    if (r.right_panned) return;
    std::string message;
    const auto c = crossing_under(ti.view, model.scene());
    const bool exercise = c && knots.exercise_crossing(model, c->object, c->over);
    if (change_crossing_under(ti.view, session, message)) model.status = exercise ? knots.exercise_message() : message;
    else if (Tool* tool = model.active_tool()) tool->right_click(ti, session);
  }
}

}  // namespace

void route_input(GuiModel& model, Routing& r, const WindowInput& in, const ToolInput& ti, KnotPanels& knots) {
  const ImGuiIO& io = ImGui::GetIO();
  Session& session = model.session;
  if (!io.WantTextInput) {
    window_keys(model, r, in, ti);
    if (Tool* tool = model.active_tool()) tool_keys(*tool, in, ti, session);
  }
  Tool* tool = model.active_tool();
  // A device's button does what the active tool does with a press (grab, explore, or draw itself).
  session.set_device_button(tool ? tool->device_button() : DeviceButton::kNone, tool ? tool->device_carry_rings() : 0);
  if (tool) tool->update(ti, session);
  const bool over_view = model.layout.view.contains(static_cast<float>(in.cursor().x()), static_cast<float>(in.cursor().y()));
  const bool captured = (io.WantCaptureMouse || !over_view) && !r.tool_drag && !r.view_drag;
  if (in.released(0) || !in.down(0)) {
    if (r.tool_drag && tool) tool->release(ti, session);
    r.tool_drag = r.view_drag = false;
  }
  right_and_middle(model, r, in, ti, captured, knots);
  if (!captured) {
    if (in.wheel() != 0 && in.alt() && model.scene().view.slice) step_slice(model, in.wheel());
    else if (in.wheel() != 0 && !(tool && tool->wheel(in.wheel(), ti, session))) model.view.scroll(in.wheel());
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
      model.view.drag(mode, d.x(), d.y(), ti.view.window.y());
    } else if (!in.down(0) && tool) {
      tool->hover(ti, session);
    }
  }
  if (tool) {
    const std::string m = tool->take_message();
    if (!m.empty()) model.status = m;
    if (tool->take_finished()) {  // a sketch made its object: back to Touch, with it in view
      const std::string made = model.status;
      model.choose(ToolChoice::kTouch);
      model.status = made + " (the tool is Touch again)";
      model.want_frame = true;
    }
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

// [SECTION] status line
// The status line: the tools (the active one lit), then the last message, cut to fit (whole in
// its tooltip and in View > Messages).
void status_line(GuiModel& model) {
  const Rect& r = model.layout.status;
  if (r.empty()) return;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4 * model.ui_scale, 2 * model.ui_scale));
  ImGui::Begin("##status line", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                             ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::PopStyleVar();
  for (const ToolEntry& e : tool_entries()) {
    const bool active = model.tool == e.id;
    if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyle().Colors[ImGuiCol_ButtonActive]);
    const std::string label = std::string(e.label) + " (" + e.key_name + ")";
    if (ImGui::SmallButton(label.c_str())) model.choose(active ? ToolChoice::kTouch : e.id);
    if (active) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.tooltip);
    ImGui::SameLine();
  }
  model.slice_button = Rect{};
  if (has_4d_surfaces(model.scene())) {  // the slice w = c: not a tool, a way of looking, lit while on
    const bool on = model.scene().view.slice;
    if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyle().Colors[ImGuiCol_ButtonActive]);
    if (ImGui::SmallButton("Slice (W)")) toggle_slice(model);
    if (on) ImGui::PopStyleColor();
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    model.slice_button = Rect{a.x, a.y, b.x - a.x, b.y - a.y};
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("the surfaces cut by the hyperplane w = c of the 4D view, drawn on the shadow and named\n"
                        "as a link in the Slice panel (Alt+wheel moves c)");
    ImGui::SameLine();
  }
  ImGui::TextDisabled("|");
  ImGui::SameLine();
  const float room = ImGui::GetContentRegionAvail().x;
  std::string shown = model.status;
  if (ImGui::CalcTextSize(shown.c_str()).x > room) {
    while (!shown.empty() && ImGui::CalcTextSize((shown + "...").c_str()).x > room) shown.pop_back();
    shown += "...";
  }
  ImGui::TextUnformatted(shown.c_str());
  if (ImGui::IsItemHovered() && shown != model.status) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40);
    ImGui::TextUnformatted(model.status.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  if (ImGui::IsItemClicked()) model.show_messages = true;
  ImGui::End();
}

}  // namespace s4d
