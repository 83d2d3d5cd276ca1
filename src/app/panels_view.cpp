// The view panel (4D rotation, drawing, sound) and the scene panel (objects, their knot names).
// Sections: [SECTION] View panel, [SECTION] Scene panel
#include "app/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "app/panel_settings.hpp"
#include "interact/live/live_simulation.hpp"
#include "io/object_file.hpp"
#include "render/diagram_export.hpp"
#include "scenario/world_builder.hpp"
#include "shape/describe.hpp"

namespace s4d {

using panel_detail::record_tool_setting;

namespace {

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

// The 4D perspective (as KnotPlot and Meshview offer it): the shadow seen from an eye at distance d
// along w, nearer in w drawn larger. The distance is in scene units, offered from half the view's
// ball to a hundred times it; the last one chosen comes back when it is turned on again.
void perspective_controls(GuiModel& model) {
  const double r = model.fit.radius > 0 && std::isfinite(model.fit.radius) ? model.fit.radius : 1.0;
  const double hi = std::min(100 * r, Frame<4>::kMaxPerspective), lo = std::min(0.5 * r, 0.5 * hi);
  bool on = model.view.perspective() > 0;
  if (!(model.perspective_distance > 0)) model.perspective_distance = std::clamp(4 * r, lo, hi);
  const auto drawn = [&](const char* name) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    model.view_controls.emplace_back(name, Rect{a.x, a.y, b.x - a.x, b.y - a.y});
  };
  if (ImGui::Checkbox("4D perspective", &on)) model.view.set_perspective(on ? model.perspective_distance : 0);
  drawn("4D perspective");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the shadow seen from a 4D eye at distance d along w: nearer in w is drawn larger\n"
                      "(shadow4d render --perspective D)");
  if (!on) return;
  float d = static_cast<float>(model.perspective_distance);
  if (ImGui::SliderFloat("eye distance", &d, static_cast<float>(lo), static_cast<float>(hi), "%.2f",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
    if (const std::string e = Frame<4>::perspective_error(d); e.empty()) {
      model.perspective_distance = d;
      model.view.set_perspective(d);
    } else {
      model.error = e;  // what was typed is refused; the view keeps its distance
    }
  }
  drawn("eye distance");
}

}  // namespace

// [SECTION] View panel
void Panels::view_panel(GuiModel& model, float fps) {
  model.view_controls.clear();
  if (!model.dock.begin(Side::kLeft, "View", nullptr, false)) return;
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
  perspective_controls(model);

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
  model.dock.end();
}

// [SECTION] Scene panel
void Panels::scene_panel(GuiModel& model) {
  if (!model.dock.begin(Side::kLeft, "Scene")) return;
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
  model.dock.end();
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
  s.send(on ? live::Request(live::StopRelaxing{}) : live::Request(live::StartRelaxing{}));
  model.status = on ? "relaxing stopped: the knot rests as it is"
                    : "relaxing the knot, live (L stops it); it never passes through itself, so its name stays";
}


}  // namespace s4d
