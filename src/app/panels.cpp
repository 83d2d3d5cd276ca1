// [SECTION] Menu bar   [SECTION] View panel   [SECTION] Scene panel   [SECTION] Generator dialog
// [SECTION] Dialogs (open, save, screenshot, errors)
#include "app/panels.hpp"

#include <imgui.h>

#include <cmath>

#include "core/error.hpp"
#include "io/object_file.hpp"
#include "shape/describe.hpp"

namespace s4d {

namespace {

const std::vector<std::string> kOpenExtensions{".json", ".off", ".4off", ".noff", ".vect",
                                               ".4vect", ".txt", ".xyz", ".curve"};

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

}  // namespace

Panels::Panels()
    : open_browser_("Open scene, mesh or curve", kOpenExtensions, false),
      save_browser_("Save scene", {".json"}, true),
      shot_browser_("Save screenshot", {".png"}, true),
      stroke_browser_("Save last sketch stroke", {".txt"}, true) {}

void Panels::open(GuiModel& model, const std::string& spec) {
  try {
    Scene scene = load_scene_or_object(spec);
    model.scene = std::move(scene);
    model.view.reset(model.scene);
    const bool scene_file = spec.size() > 5 && spec.ends_with(".json");
    if (!scene_file && !model.scene.objects.empty() && ambient_dim(model.scene.objects[0].shape) == 4)
      model.view.turn_to_generic_view();
    model.status = "opened " + spec;
  } catch (const std::exception& e) {
    model.error = e.what();
  }
}

void Panels::draw(GuiModel& model, float fps) {
  menu_bar(model);
  view_panel(model, fps);
  scene_panel(model);
  generator_dialog(model);
  dialogs(model);
}

// [SECTION] Menu bar
void Panels::menu_bar(GuiModel& model) {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("New (empty scene)")) {
      model.scene = Scene{};
      model.view.reset(model.scene);
      model.status = "empty scene: Create adds objects, or sketch a knot";
    }
    if (ImGui::MenuItem("Open...")) open_browser_.open(S4D_SCENES_DIR);
    if (ImGui::MenuItem("Save scene...")) save_browser_.open(".");
    if (ImGui::MenuItem("Screenshot...", "F12")) shot_browser_.open(".");
    if (ImGui::MenuItem("Save last sketch stroke...", nullptr, false, !model.last_stroke.components.empty()))
      stroke_browser_.open(".");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("the cursor samples of the last sketch (x y u), for\n"
                        "shadow4d knot sketch FILE --knot --out KNOT");
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) model.quit = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Create")) {
    if (ImGui::MenuItem("Sketch a knot", "Esc stops", &model.sketching))
      model.status = model.sketching ? kSketchHelp : "";
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("draw a closed curve with the left button in the plane facing you;\n"
                        "where it crosses what is drawn it passes over, or under with shift held.\n"
                        "It becomes a knot of R^3, named live in the Scene panel.\n"
                        "(also: shadow4d knot sketch STROKE --knot --out KNOT)");
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
    if (ImGui::MenuItem("Haptics panel and workspace")) model.open_haptics = true;
    ImGui::EndMenu();
  }
  ImGui::TextDisabled("|  %s", model.status.c_str());
  ImGui::EndMainMenuBar();
}

// [SECTION] View panel
void Panels::view_panel(GuiModel& model, float fps) {
  ImGui::SetNextWindowPos(ImVec2(10, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(330, 510), ImGuiCond_FirstUseEver);
  ImGui::Begin("View");
  ImGui::Text("%.0f fps  (%.1f ms)", fps, fps > 0 ? 1000.0f / fps : 0.0f);
  ImGui::Separator();
  ImGui::TextUnformatted("4D rotation (degrees)");
  auto& angles = model.view.plane_angles();
  const auto planes = all_planes(4);
  for (std::size_t i = 0; i < planes.size(); ++i)
    ImGui::SliderFloat(plane_name(planes[i]).c_str(), &angles[i], -180.0f, 180.0f, "%.0f");
  if (ImGui::Button("Reset 4D rotation")) angles.fill(0.0f);
  ImGui::SameLine();
  if (ImGui::Button("Reset view")) model.view.reset(model.scene);
  ImGui::TextDisabled("drag: turn  shift-drag: xw/yw  ctrl-drag: zw  wheel: zoom");

  ImGui::Separator();
  ImGui::TextUnformatted("Drawing");
  ViewSettings& v = model.scene.view;
  ImGui::Checkbox("depth colour", &v.depth_colour);
  if (v.depth_colour) {
    int map = static_cast<int>(v.colour_map);
    ImGui::Combo("colour map", &map, "coolwarm\0rainbow\0grey\0");
    v.colour_map = static_cast<ColourMap>(map);
    legend(v.colour_map, model.scene);
  }
  ImGui::Checkbox("wireframe", &v.wireframe);
  ImGui::SameLine();
  ImGui::Checkbox("flat shadow", &v.shadow);
  float radius = static_cast<float>(v.tube_radius);
  if (ImGui::SliderFloat("tube radius", &radius, 0.002f, 0.3f, "%.3f", ImGuiSliderFlags_Logarithmic))
    v.tube_radius = radius;
  ImGui::Checkbox("intersections and crossings", &v.intersections);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("where the shadow crosses itself: yellow only in the shadow (the sheets are\n"
                      "apart in w), magenta where the surface truly meets itself in R^4;\n"
                      "for curves, a white dot on the over strand of each crossing of this view;\n"
                      "right-click a dot to change that crossing");
  if (v.intersections && model.intersections.computed) {
    ImGui::TextWrapped("%s", intersection_text(model.intersections).c_str());
    for (const std::string& code : model.intersections.gauss_codes) ImGui::TextWrapped("%s", code.c_str());
  }
  ImGui::End();
}

// [SECTION] Scene panel
void Panels::scene_panel(GuiModel& model) {
  ImGui::SetNextWindowPos(ImVec2(10, 550), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(330, 200), ImGuiCond_FirstUseEver);
  ImGui::Begin("Scene");
  if (model.scene.objects.empty()) ImGui::TextDisabled("empty: File > Open or Create");
  int remove = -1;
  for (std::size_t i = 0; i < model.scene.objects.size(); ++i) {
    const auto& obj = model.scene.objects[i];
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::SmallButton("x")) remove = static_cast<int>(i);
    ImGui::SameLine();
    ImGui::TextUnformatted(obj.name.c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s", describe_shape(obj.shape).c_str());
    ImGui::PopStyleColor();
    knot_name(obj);
    ImGui::PopID();
  }
  if (remove >= 0) model.scene.objects.erase(model.scene.objects.begin() + remove);
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
  const bool replace = ImGui::Button("Replace scene");
  ImGui::SameLine();
  const bool add = ImGui::Button("Add to scene");
  if (replace || add) {
    try {
      SceneObject obj;
      obj.generator = GeneratorCall{info->name, generator_params_};
      obj.shape = generate(info->name, generator_params_);
      obj.name = info->name + "-" + std::to_string(++model.created);
      if (replace) {
        model.scene.objects.clear();
        model.scene.frame = Frame<4>();
        model.view.reset(model.scene);
        if (info->dim == 4) model.view.turn_to_generic_view();
      }
      model.scene.objects.push_back(std::move(obj));
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
  if (auto p = save_browser_.draw()) {
    try {
      Scene to_save = model.scene;
      model.view.apply_to(to_save);
      auto path = *p;
      if (path.extension() != ".json") path += ".json";
      save_scene(to_save, path);
      model.status = "saved " + path.string();
    } catch (const std::exception& e) {
      model.error = e.what();
    }
  }
  if (auto p = stroke_browser_.draw()) {
    try {
      const auto path = p->extension() == ".txt" ? *p : std::filesystem::path(p->string() + ".txt");
      write_shape_file(model.last_stroke, path);
      model.status = "saved " + path.string() + " (shadow4d knot sketch " + path.filename().string() + " --knot)";
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
