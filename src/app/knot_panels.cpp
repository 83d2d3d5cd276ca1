// [SECTION] Knot panel   [SECTION] Knot from the table   [SECTION] Are these the same knot?
// [SECTION] Unknot it by one crossing change
#include "app/knot_panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>

#include "app/panels.hpp"

namespace s4d {

namespace {

template <typename T>
bool ready(const std::future<T>& f) {
  return f.valid() && f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

const Curve<3>* curve_of(const Scene& scene, int o) {
  if (o < 0 || o >= static_cast<int>(scene.objects.size())) return nullptr;
  return std::get_if<Curve<3>>(&scene.objects[static_cast<std::size_t>(o)].shape);
}

std::size_t points_hash(const Curve<3>& c, const Frame<3>& view) {
  std::size_t h = 0;
  auto mix = [&](double x) { h = h * 1000003u ^ std::hash<double>()(x); };
  for (const auto& comp : c.components)
    for (const Vec3& p : comp.points) mix(p.x()), mix(p.y()), mix(p.z());
  for (int i = 0; i < 9; ++i) mix(view.matrix()(i / 3, i % 3));
  return h;
}

}  // namespace

KnotPanels::KnotPanels() : names_(knot_table_names()) {}

std::string KnotPanels::shown_name() const { return shown_ && shown_->info ? shown_->info->name : ""; }

void KnotPanels::draw(GuiModel& model, const Frame<3>& view) {
  info_panel(model, view);
  table_dialog(model);
  same_dialog(model);
}

// [SECTION] Knot panel
void KnotPanels::info_panel(GuiModel& model, const Frame<3>& view) {
  const Scene& scene = model.scene();
  std::vector<int> curves;
  for (std::size_t o = 0; o < scene.objects.size(); ++o)
    if (std::holds_alternative<Curve<3>>(scene.objects[o].shape)) curves.push_back(static_cast<int>(o));
  if (curves.empty()) return;
  if (std::find(curves.begin(), curves.end(), selected_) == curves.end()) selected_ = curves.front();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(350, display.y - 330), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(440, 320), ImGuiCond_FirstUseEver);
  ImGui::Begin("Knot");
  if (ImGui::BeginCombo("curve", scene.objects[static_cast<std::size_t>(selected_)].name.c_str())) {
    for (int o : curves)
      if (ImGui::Selectable(scene.objects[static_cast<std::size_t>(o)].name.c_str(), o == selected_)) selected_ = o;
    ImGui::EndCombo();
  }
  const Curve<3>& c = *curve_of(scene, selected_);
  const std::size_t h = points_hash(c, view);
  if (h != submitted_hash_) {  // it moved or the view turned: ask again (older requests are dropped)
    submitted_hash_ = h;
    worker_.submit(c, view);
  }
  if (auto r = worker_.latest()) shown_ = r;
  if (!shown_) {
    ImGui::TextDisabled("naming...");
  } else if (!shown_->info) {
    ImGui::TextWrapped("%s", shown_->error.c_str());
  } else {
    const KnotInfo& k = *shown_->info;
    ImGui::TextWrapped("%s%s", k.name.c_str(), k.proven ? "  (proven)" : "");
    ImGui::TextWrapped("%s", k.chirality.c_str());
    if (k.candidates.size() > 1) {
      std::string all;
      for (const std::string& n : k.candidates) all += (all.empty() ? "" : ", ") + n;
      ImGui::TextWrapped("candidates: %s", all.c_str());
    }
    if (!k.decided_by.empty()) {
      std::string by;
      for (const std::string& d : k.decided_by) by += (by.empty() ? "" : "; ") + d;
      ImGui::TextDisabled("decided by: %s", by.c_str());
    }
    ImGui::Separator();
    ImGui::Text("crossings: %d in this view, %d simplified; writhe %d", k.view_crossings, k.simplified_crossings,
                k.writhe);
    ImGui::TextWrapped("Gauss code: %s", k.gauss_code.c_str());
    if (k.components > 1)
      for (std::size_t i = 0; i < k.linking.size(); ++i)
        for (std::size_t j = i + 1; j < k.linking[i].size(); ++j)
          ImGui::Text("linking number of components %zu and %zu: %d", i + 1, j + 1, k.linking[i][j]);
    ImGui::TextWrapped("Alexander: %s", k.alexander.c_str());
    ImGui::TextWrapped("Jones: %s", k.jones.c_str());
    ImGui::TextWrapped("HOMFLY-PT: %s", k.homfly.c_str());
    ImGui::Text("determinant %lld   (%.1f ms)", static_cast<long long>(k.determinant), k.milliseconds);
  }
  ImGui::Separator();
  if (ImGui::Button("Knot from the table...")) table_open_ = true;
  ImGui::SameLine();
  if (ImGui::Button("Are these the same knot?")) same_open_ = true;
  ImGui::SameLine();
  if (ImGui::Checkbox("unknot it by one change", &unknot_on_)) {
    unknot_report_.reset();
    exercise_message_ = unknot_on_ ? "right-click the crossing whose change you think unknots it" : "";
    if (unknot_on_) unknot_ = std::async(std::launch::async, [c, view] { return unknotting_crossings(c, view); });
  }
  if (unknot_on_) {
    if (ready(unknot_)) {
      try {
        unknot_report_ = unknot_.get();
      } catch (const std::exception& e) {
        exercise_message_ = e.what();
        unknot_on_ = false;
      }
    }
    ImGui::TextWrapped("%s", unknot_report_ ? exercise_message_.c_str() : "working out every crossing...");
  }
  ImGui::End();
}

bool KnotPanels::exercise_crossing(GuiModel& model, int object, const Vec3& over_point) {
  if (!unknot_on_ || !unknot_report_ || object != selected_) return false;
  const UnknottingReport& r = *unknot_report_;
  const Vec3 q = r.frame.to_view(over_point);
  const int label = nearest_crossing(r, q.head<2>());
  if (label <= 0) return false;
  std::string others;
  for (int l : r.unknotting) others += (others.empty() ? "" : ", ") + std::to_string(l);
  for (const CrossingChangeResult& c : r.crossings) {
    if (c.label != label) continue;
    exercise_message_ = std::string(c.unknots ? "Yes: " : "No: ") + "changing crossing " + std::to_string(label) +
                        " of " + r.knot + " gives " + c.result + ". " +
                        (r.unknotting.empty() ? "No single change unknots it."
                                              : "The crossings that unknot it: " + others + ".");
    model.status = exercise_message_;
    return true;
  }
  return false;
}

// [SECTION] Knot from the table
void KnotPanels::table_dialog(GuiModel& model) {
  if (ready(made_)) {
    try {
      SceneObject o;
      o.name = making_ + (mirror_ ? " mirror" : "");
      o.shape = made_.get();
      model.session.record("create " + o.name);
      model.scene().objects.push_back(std::move(o));
      model.scene().view.intersections = true;
      model.status = "made " + making_ + " from the table";
      table_error_.clear();
    } catch (const std::exception& e) {
      table_error_ = e.what();
    }
    making_.clear();
  }
  if (!table_open_) return;
  ImGui::SetNextWindowSize(ImVec2(360, 420), ImGuiCond_FirstUseEver);
  ImGui::Begin("Knot from the table", &table_open_);
  ImGui::InputText("name", filter_, sizeof filter_);
  ImGui::SameLine();
  ImGui::Checkbox("mirror", &mirror_);
  ImGui::BeginChild("names", ImVec2(0, -60), true);
  int shown = 0;
  for (const TableName& n : names_) {
    if (filter_[0] && n.name.find(filter_) == std::string::npos) continue;
    if (++shown > 300) {
      ImGui::TextDisabled("... type more of the name");
      break;
    }
    char label[96];
    std::snprintf(label, sizeof label, "%s   (%d crossings, %s)", n.name.c_str(), n.crossings, n.source.c_str());
    if (ImGui::Selectable(label, n.name == filter_)) std::snprintf(filter_, sizeof filter_, "%s", n.name.c_str());
  }
  ImGui::EndChild();
  const bool busy = made_.valid();
  if (ImGui::Button(busy ? "making..." : "Create") && !busy && filter_[0]) {
    making_ = filter_;
    const std::string spec = making_ + (mirror_ ? " mirror" : "");
    made_ = std::async(std::launch::async, [spec] { return make_table_knot(spec); });
  }
  ImGui::SameLine();
  ImGui::TextDisabled("(also: shadow4d knot make NAME --out K.curve)");
  if (!table_error_.empty()) ImGui::TextColored(ImVec4(1, 0.5f, 0.3f, 1), "%s", table_error_.c_str());
  ImGui::End();
}

// [SECTION] Are these the same knot?
void KnotPanels::same_dialog(GuiModel& model) {
  if (!same_open_) return;
  const Scene& scene = model.scene();
  ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("Are these the same knot?", &same_open_);
  std::vector<int> curves;
  for (std::size_t o = 0; o < scene.objects.size(); ++o)
    if (std::holds_alternative<Curve<3>>(scene.objects[o].shape)) curves.push_back(static_cast<int>(o));
  if (curves.size() < 2) {
    ImGui::TextWrapped("Put two curves in the scene (from the table, files or sketches) to compare them.");
    ImGui::End();
    return;
  }
  if (std::find(curves.begin(), curves.end(), other_) == curves.end() || other_ == selected_)
    other_ = curves[curves[0] == selected_ ? 1 : 0];
  ImGui::Text("'%s' and", scene.objects[static_cast<std::size_t>(selected_)].name.c_str());
  ImGui::SameLine();
  if (ImGui::BeginCombo("##other", scene.objects[static_cast<std::size_t>(other_)].name.c_str())) {
    for (int o : curves)
      if (o != selected_ && ImGui::Selectable(scene.objects[static_cast<std::size_t>(o)].name.c_str(), o == other_))
        other_ = o;
    ImGui::EndCombo();
  }
  ImGui::TextDisabled("decide first, then check:");
  if (ImGui::Button(same_.valid() ? "checking..." : "Check") && !same_.valid()) {
    same_answer_.reset();
    same_error_.clear();
    const Curve<3> a = *curve_of(scene, selected_), b = *curve_of(scene, other_);
    same_ = std::async(std::launch::async, [a, b] { return same_knot(a, b); });
  }
  if (ready(same_)) {
    try {
      same_answer_ = same_.get();
    } catch (const std::exception& e) {
      same_error_ = e.what();
    }
  }
  if (same_answer_) {
    ImGui::Text("%s", same_answer_name(same_answer_->answer));
    ImGui::TextWrapped("%s", same_answer_->reason.c_str());
  }
  if (!same_error_.empty()) ImGui::TextWrapped("%s", same_error_.c_str());
  ImGui::End();
}

}  // namespace s4d
