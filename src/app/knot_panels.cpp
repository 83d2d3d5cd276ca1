// [SECTION] Knot panel   [SECTION] Knot from the table   [SECTION] Are these the same knot?
// [SECTION] Unknot it by one crossing change   [SECTION] dump
#include "app/knot_panels.hpp"

#include "app/dock.hpp"
#include "app/screen.hpp"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstring>
#include <functional>
#include <nlohmann/json.hpp>

#include "app/knot_edit_step.hpp"
#include "app/panels.hpp"
#include "core/threads.hpp"
#include "knots/curve_edits.hpp"
#include "knots/knot_diagram.hpp"
#include "view/view_crossings.hpp"

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

int object_named(const Scene& scene, const std::string& name) {
  for (std::size_t o = 0; o < scene.objects.size(); ++o)
    if (scene.objects[o].name == name && std::holds_alternative<Curve<3>>(scene.objects[o].shape))
      return static_cast<int>(o);
  return -1;
}

std::vector<int> curve_objects(const Scene& scene) {
  std::vector<int> curves;
  for (std::size_t o = 0; o < scene.objects.size(); ++o)
    if (std::holds_alternative<Curve<3>>(scene.objects[o].shape)) curves.push_back(static_cast<int>(o));
  return curves;
}

std::string lower_case(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void mix(std::size_t& h, double x) { h = h * 1000003u ^ std::hash<double>()(x); }

std::size_t points_hash(const Curve<3>& c, const Frame<3>& view) {
  std::size_t h = 0;
  for (const auto& comp : c.components)
    for (const Vec3& p : comp.points) mix(h, p.x()), mix(h, p.y()), mix(h, p.z());
  for (int i = 0; i < 9; ++i) mix(h, view.matrix()(i / 3, i % 3));
  return h;
}

// Every curve of the scene as one curve, to place a new one beside them.
Curve<3> all_curves(const Scene& scene) {
  Curve<3> all;
  for (const SceneObject& o : scene.objects)
    if (const auto* c = std::get_if<Curve<3>>(&o.shape))
      all.components.insert(all.components.end(), c->components.begin(), c->components.end());
  return all;
}

void remove_objects(GuiModel& model, const std::vector<std::string>& names) {
  auto& objects = model.scene().objects;
  std::erase_if(objects, [&](const SceneObject& o) {
    return std::find(names.begin(), names.end(), o.name) != names.end();
  });
}

constexpr const char* kPairA = "knot A";
constexpr const char* kPairB = "knot B";
constexpr const char* kExerciseKnot = "exercise knot";
const ImVec4 kGood(0.45f, 0.9f, 0.45f, 1), kBad(1, 0.5f, 0.3f, 1);

}  // namespace

KnotPanels::KnotPanels(unsigned exercise_seed)
    : rng_(exercise_seed ? exercise_seed : std::random_device{}()), names_(knot_table_names()) {}

std::string KnotPanels::shown_name() const { return shown_ && shown_->info ? shown_->info->name : ""; }

namespace {

// A table knot comes at its own size (relaxed: tens of units); in a scene it takes the size of
// what is there, as a sketched knot would have.
void match_size(const Scene& scene, Curve<3>& c) {
  if (scene.objects.empty()) return;
  Scene alone;
  alone.objects.push_back(SceneObject{});
  alone.objects[0].shape = c;
  const ViewFit own = fit_of(alone), there = fit_of(scene);
  if (!(own.radius > 0) || !(there.radius > 0)) return;
  const double k = there.radius / own.radius;
  for (Polyline<3>& p : c.components)
    for (Vec3& q : p.points) q = own.centre.head<3>() + k * (q - own.centre.head<3>());
}

}  // namespace

bool KnotPanels::busy() const {
  const auto latest = worker_.latest();
  const bool naming = submitted_ > 0 && (!latest || latest->request < submitted_);
  return naming || made_.valid() || pair_.valid() || same_.valid() || unknot_make_.valid() || unknot_.valid();
}

bool KnotPanels::button(const char* label) {
  const bool pressed = ImGui::Button(label);
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  buttons_[label] = {a.x, a.y, b.x, b.y};
  return pressed;
}

// An exercise's knots fill the view: the window keeps every object in view when one is added, so
// this comes a frame later.
void KnotPanels::focus(GuiModel& model, const Frame<3>& view) {
  if (focus_.empty()) return;
  Scene only;
  for (const SceneObject& o : model.scene().objects)
    if (std::find(focus_.begin(), focus_.end(), o.name) != focus_.end()) only.objects.push_back(o);
  focus_.clear();
  frame_on(model, only);
}

// An exercise begun from the menus has its own scene: this goes back to the one it left.
void KnotPanels::leave_button(GuiModel& model) {
  if (!model.exercise_return) return;
  if (button("Leave the exercise")) {
    model.leave_exercise = true;
    same_open_ = unknot_open_ = false;
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to the scene you had before the exercise");
}

void KnotPanels::new_pair() {
  if (pair_.valid()) return;
  same_error_.clear();
  pair_ = run_in_background([seed = rng_()] { return make_same_knot_exercise(seed); });
}

void KnotPanels::start_unknot(GuiModel& model) {
  if (!unknot_open_ && !unknot_name_.empty() && object_named(model.scene(), kExerciseKnot) >= 0) {
    unknot_open_ = true;  // back to the one under way
  } else if (!unknot_make_.valid()) {
    unknot_open_ = true;
    unknot_make_ = run_in_background([seed = rng_()] {
      const std::string name = pick_unknotting_exercise(seed);
      return std::pair{name, make_table_knot(name)};
    });
  }
}

void KnotPanels::draw(GuiModel& model, const Frame<3>& view) {
  if (std::exchange(model.open_same_knot, false)) {  // from the menus: a pair at once
    same_open_ = true;
    new_pair();
  }
  if (std::exchange(model.open_unknot, false)) start_unknot(model);
  focus(model, view);
  buttons_.clear();
  name_hidden_ = false;
  model.hidden_knot_names.clear();
  if (pair_names_ && !pair_answered_) model.hidden_knot_names = {kPairA, kPairB};
  info_panel(model, view);
  table_dialog(model);
  same_dialog(model);
  unknot_dialog(model, view);
}

// [SECTION] Knot panel
void KnotPanels::info_panel(GuiModel& model, const Frame<3>& view) {
  const Scene& scene = model.scene();
  const std::vector<int> curves = curve_objects(scene);
  if (curves.empty()) return;
  if (std::find(curves.begin(), curves.end(), selected_) == curves.end()) selected_ = curves.front();
  if (!model.dock.begin(Side::kRight, "Knot")) return;
  if (model.touch_and_sound_only) {
    // The name and the codes would give the knot away: only what the hand and ear have found.
    name_hidden_ = true;
    ImGui::TextWrapped("Touch and sound only: the knot's name and codes are hidden. Explore it (E); its "
                       "Gauss code is built up as you pass crossings (+ over, - under):");
    const std::string code = model.explore.gauss_so_far();
    ImGui::SetWindowFontScale(1.5f);
    ImGui::TextWrapped("%s", code.empty() ? "(no crossing passed yet)" : code.c_str());
    ImGui::SetWindowFontScale(1.0f);
    model.dock.end();
    return;
  }
  if (button("Knot from the table...")) table_open_ = true;
  same_line_if_fits("Are these the same knot?");
  if (button("Are these the same knot?")) same_open_ = true;
  same_line_if_fits("Unknot it...");
  if (button("Unknot it...")) start_unknot(model);
  if (ImGui::BeginCombo("curve", scene.objects[static_cast<std::size_t>(selected_)].name.c_str())) {
    for (int o : curves)
      if (ImGui::Selectable(scene.objects[static_cast<std::size_t>(o)].name.c_str(), o == selected_)) selected_ = o;
    ImGui::EndCombo();
  }
  toolbar(model);
  const Curve<3>& c = *curve_of(scene, selected_);
  const std::size_t h = points_hash(c, view);
  if (h != submitted_hash_) {  // it moved or the view turned: ask again (older requests are dropped)
    submitted_hash_ = h;
    submitted_ = worker_.submit(c, view);
  }
  if (auto r = worker_.latest()) shown_ = r;
  const std::string& object = scene.objects[static_cast<std::size_t>(selected_)].name;
  if (model.hidden_knot_names.count(object)) {
    name_hidden_ = true;
    ImGui::TextWrapped("Hidden until you answer \"Are these the same knot?\".");
  } else if (!shown_) {
    ImGui::TextDisabled("naming...");
  } else if (!shown_->info) {
    ImGui::TextWrapped("%s", shown_->error.c_str());
  } else {
    const KnotInfo& k = *shown_->info;
    ImGui::TextWrapped("%s%s", k.name.c_str(), k.proven ? "  (proven)" : "");
    ImGui::TextWrapped("%s", k.chirality.c_str());
    if (k.components > 1) {
      std::string parts;
      for (const auto& c : k.identification.components) parts += (parts.empty() ? "" : ", ") + c.name;
      ImGui::TextWrapped("components: %s", parts.c_str());
    }
    if (k.candidates.size() > 1) {
      std::string all;
      for (const std::string& n : k.candidates) all += (all.empty() ? "" : ", ") + n;
      ImGui::TextWrapped("candidates: %s", all.c_str());
    }
    if (!k.decided_by.empty()) {
      std::string by;
      for (const std::string& d : k.decided_by) by += (by.empty() ? "" : "; ") + d;
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
      ImGui::TextWrapped("decided by: %s", by.c_str());
      ImGui::PopStyleColor();
    }
    // What was tried without deciding, as `knot info` prints it: the user sees how far the tools went.
    std::string tried;
    for (const std::string& u : k.further_used) tried += (tried.empty() ? "" : "; ") + u;
    if (!tried.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
      ImGui::TextWrapped("further invariants tried: %s", tried.c_str());
      ImGui::PopStyleColor();
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
  model.dock.end();
}

// The diagram toolbar (as KnotFolio's): each edit one undoable step (also: shadow4d knot mirror,
// reverse, delete-component).
void KnotPanels::toolbar(GuiModel& model) {
  const Curve<3>& c = *curve_of(model.scene(), selected_);
  const int n = static_cast<int>(c.components.size());
  component_ = std::clamp(component_, 1, n);
  const int o = selected_, k = component_ - 1;
  if (button("Mirror")) model.status = edit_curve_object(model.session, o, "mirror", mirrored_curve);
  same_line_if_fits("Reverse component");
  if (button("Reverse component"))
    model.status = edit_curve_object(model.session, o, "reverse component " + std::to_string(component_) + " of",
                                     [k](const Curve<3>& x) { return with_component_reversed(x, k); });
  if (n > 1) {
    same_line_if_fits("Delete component");
    if (button("Delete component"))
      model.status = edit_curve_object(model.session, o, "delete component " + std::to_string(component_) + " of",
                                       [k](const Curve<3>& x) { return with_component_deleted(x, k); });
    same_line_if_fits(90 + ImGui::CalcTextSize("component").x);
    ImGui::SetNextItemWidth(90);
    ImGui::InputInt("component", &component_);
    component_ = std::clamp(component_, 1, n);
  }
}

// [SECTION] Knot from the table
void KnotPanels::table_dialog(GuiModel& model) {
  if (ready(made_)) {
    try {
      SceneObject o;
      o.name = making_ + (mirror_ ? " mirror" : "");
      Curve<3> c = made_.get();
      match_size(model.scene(), c);
      place_beside(all_curves(model.scene()), c);  // next to what is there, not on top of it
      o.shape = std::move(c);
      model.session.record("create " + o.name);
      model.scene().objects.push_back(std::move(o));
      selected_ = static_cast<int>(model.scene().objects.size()) - 1;  // the Knot panel names it
      model.scene().view.intersections = true;
      model.session.rebuild();
      model.status = "made " + making_ + " from the table";
      model.want_frame = true;
      table_error_.clear();
    } catch (const std::exception& e) {
      table_error_ = e.what();
    }
    making_.clear();
  }
  const bool appearing = table_open_ && !table_was_open_;
  table_was_open_ = table_open_;
  if (!table_open_) return;
  if (!model.dock.begin(Side::kRight, "Knot from the table", &table_open_)) return;
  if (appearing) ImGui::SetKeyboardFocusHere();  // type the name at once
  ImGui::InputText("name", filter_, sizeof filter_);
  ImGui::SameLine();
  ImGui::Checkbox("mirror", &mirror_);
  ImGui::BeginChild("names", ImVec2(0, 12 * ImGui::GetTextLineHeightWithSpacing()), true);
  int shown = 0;
  const std::string filter = lower_case(filter_);
  for (const TableName& n : names_) {
    if (!filter.empty() && lower_case(n.name).find(filter) == std::string::npos &&
        lower_case(n.alias).find(filter) == std::string::npos)
      continue;
    if (++shown > 300) {
      ImGui::TextDisabled("... type more of the name");
      break;
    }
    char label[128];
    std::snprintf(label, sizeof label, "%s%s%s   (%d crossings, %s)", n.name.c_str(), n.alias.empty() ? "" : "  ",
                  n.alias.c_str(), n.crossings, n.source.c_str());
    if (ImGui::Selectable(label, n.name == filter_)) std::snprintf(filter_, sizeof filter_, "%s", n.name.c_str());
  }
  ImGui::EndChild();
  const bool busy = made_.valid();
  if (button(busy ? "making..." : "Create") && !busy && filter_[0]) {
    making_ = filter_;
    const std::string spec = making_ + (mirror_ ? " mirror" : "");
    made_ = run_in_background([spec] { return make_table_knot(spec); });
  }
  ImGui::SameLine();
  ImGui::TextDisabled("(also: shadow4d knot make NAME --out K.curve)");
  if (!table_error_.empty()) ImGui::TextColored(kBad, "%s", table_error_.c_str());
  model.dock.end();
}

// [SECTION] Are these the same knot?
void KnotPanels::add_pair(GuiModel& model, SameKnotExercise pair) {
  model.session.record("a pair for 'are these the same knot?'");
  remove_objects(model, {kPairA, kPairB});
  const Curve<3> others = all_curves(model.scene());
  if (!others.components.empty()) {  // both beside what is there, keeping their own placement
    Curve<3> both = pair.a;
    both.components.insert(both.components.end(), pair.b.components.begin(), pair.b.components.end());
    place_beside(others, both);
    const std::size_t na = pair.a.components.size();
    pair.a.components.assign(both.components.begin(), both.components.begin() + static_cast<std::ptrdiff_t>(na));
    pair.b.components.assign(both.components.begin() + static_cast<std::ptrdiff_t>(na), both.components.end());
  }
  for (auto [name, curve] : {std::pair{kPairA, &pair.a}, std::pair{kPairB, &pair.b}}) {
    SceneObject o;
    o.name = name;
    o.shape = std::move(*curve);
    model.scene().objects.push_back(std::move(o));
  }
  model.session.rebuild();
  selected_ = object_named(model.scene(), kPairA);
  other_ = object_named(model.scene(), kPairB);
  pair_names_ = pair.names;
  pair_answered_ = false;
  focus_ = {kPairA, kPairB};
  same_answer_.reset();
  judgement_.reset();
  model.status = "knot A and knot B: are they the same knot? Answer in the panel.";
}

void KnotPanels::same_dialog(GuiModel& model) {
  if (ready(pair_)) {
    try {
      add_pair(model, pair_.get());
    } catch (const std::exception& e) {
      same_error_ = e.what();
    }
  }
  if (ready(same_)) {
    try {
      same_answer_ = same_.get();
      if (user_says_same_) {
        judgement_ = judge_same_answer(*same_answer_, *user_says_same_);
        pair_answered_ = true;
      }
    } catch (const std::exception& e) {
      same_error_ = e.what();
    }
  }
  if (!same_open_) return;
  const Scene& scene = model.scene();
  if (!model.dock.begin(Side::kRight, "Are these the same knot?", &same_open_)) return;
  leave_button(model);
  if (button(pair_.valid() ? "making a pair..." : "New pair from the table")) new_pair();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("two knots from the table side by side, the second turned: mirror images, redrawings,\n"
                      "knots that share a polynomial (also: shadow4d knot compare A B --answer same)");
  const std::vector<int> curves = curve_objects(scene);
  if (curves.size() < 2) {
    ImGui::TextWrapped("Or put two curves in the scene (from the table, files or sketches) to compare them.");
    model.dock.end();
    return;
  }
  if (std::find(curves.begin(), curves.end(), selected_) == curves.end()) selected_ = curves.front();
  if (std::find(curves.begin(), curves.end(), other_) == curves.end() || other_ == selected_)
    other_ = curves[curves[0] == selected_ ? 1 : 0];
  const std::string& name_a = scene.objects[static_cast<std::size_t>(selected_)].name;
  ImGui::Text("'%s' and", name_a.c_str());
  ImGui::SameLine();
  ImGui::SetNextItemWidth(140);
  if (ImGui::BeginCombo("##other", scene.objects[static_cast<std::size_t>(other_)].name.c_str())) {
    for (int o : curves)
      if (o != selected_ && ImGui::Selectable(scene.objects[static_cast<std::size_t>(o)].name.c_str(), o == other_))
        other_ = o;
    ImGui::EndCombo();
  }
  auto check = [&](std::optional<bool> says_same) {
    if (same_.valid()) return;
    same_answer_.reset();
    judgement_.reset();
    same_error_.clear();
    user_says_same_ = says_same;
    const Curve<3> a = *curve_of(scene, selected_), b = *curve_of(scene, other_);
    same_ = run_in_background([a, b] { return same_knot(a, b); });
  };
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("Look (turn the view, explore them), decide, then answer:");
  ImGui::PopStyleColor();
  if (button("They are the same")) check(true);
  ImGui::SameLine();
  if (button("They are different")) check(false);
  if (button("Just tell me")) check(std::nullopt);
  if (same_.valid()) ImGui::TextDisabled("checking by invariants...");
  if (judgement_) {
    ImGui::PushStyleColor(ImGuiCol_Text, !judgement_->decided ? ImGui::GetStyle().Colors[ImGuiCol_Text]
                                         : judgement_->right  ? kGood
                                                              : kBad);
    ImGui::TextWrapped("%s", judgement_->text.c_str());
    ImGui::PopStyleColor();
  } else if (same_answer_) {
    ImGui::Text("%s", same_answer_name(same_answer_->answer));
    ImGui::TextWrapped("%s", same_answer_->reason.c_str());
  }
  if (pair_names_ && pair_answered_ && (name_a == kPairA || name_a == kPairB))
    ImGui::TextDisabled("knot A was %s, knot B %s (turned)", pair_names_->a.c_str(), pair_names_->b.c_str());
  if (!same_error_.empty()) ImGui::TextColored(kBad, "%s", same_error_.c_str());
  model.dock.end();
}

// [SECTION] Unknot it by one crossing change
void KnotPanels::add_exercise_knot(GuiModel& model, Curve<3> curve) {
  model.session.record("a knot for 'unknot it by one crossing change'");
  remove_objects(model, {kExerciseKnot});
  place_beside(all_curves(model.scene()), curve);
  SceneObject o;
  o.name = kExerciseKnot;
  o.shape = std::move(curve);
  model.scene().objects.push_back(std::move(o));
  model.scene().view.intersections = true;
  model.session.rebuild();
  selected_ = object_named(model.scene(), kExerciseKnot);
  focus_ = {kExerciseKnot};
  unknot_report_.reset();
  unknot_key_ = 0;
  changed_at_.reset();
  exercise_message_ = "Which crossing's change makes it the unknot? Right-click that crossing.";
  model.status = exercise_message_;
}

void KnotPanels::unknot_dialog(GuiModel& model, const Frame<3>& view) {
  if (ready(unknot_make_)) {
    try {
      auto [name, curve] = unknot_make_.get();
      unknot_name_ = name;
      add_exercise_knot(model, std::move(curve));
    } catch (const std::exception& e) {
      exercise_message_ = e.what();
    }
  }
  if (ready(unknot_)) {
    try {
      unknot_report_ = unknot_.get();
    } catch (const std::exception& e) {
      exercise_message_ = e.what();
    }
  }
  const int o = object_named(model.scene(), kExerciseKnot);
  if (o < 0) {
    unknot_report_.reset();
  } else {
    // Undoing the change brings the exercise back; turning the view asks again for its crossings.
    if (changed_at_ && model.session.history().done_labels().size() < *changed_at_) {
      changed_at_.reset();
      exercise_message_ = "Put back: try another crossing.";
    }
    // Keyed on the diagram, not the points: a simulated knot moves a little at every step (its
    // springs settle), and its crossings, their numbers and the verdicts change only with it.
    std::size_t key = unknot_key_;
    try {
      key = std::hash<std::string>{}(diagram_from_curve(*curve_of(model.scene(), o), view).signed_gauss_code());
      for (int i = 0; i < 9; ++i) key = key * 1000003u ^ std::hash<double>{}(view.matrix()(i / 3, i % 3));
    } catch (const std::exception&) {  // a view that shows no diagram now: keep the last answer
    }
    if (!changed_at_ && key != unknot_key_ && !unknot_.valid()) {
      unknot_key_ = key;
      unknot_ = run_in_background([c = *curve_of(model.scene(), o), view] { return unknotting_crossings(c, view); });
    }
  }
  if (!unknot_open_) return;
  if (!model.dock.begin(Side::kRight, "Unknot it by one crossing change", &unknot_open_)) return;
  leave_button(model);
  if (button(unknot_make_.valid() ? "making a knot..." : "New knot") && !unknot_make_.valid())
    unknot_make_ = run_in_background([seed = rng_()] {
      const std::string name = pick_unknotting_exercise(seed);
      return std::pair{name, make_table_knot(name)};
    });
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("a knot of unknotting number one from the table\n"
                      "(also: shadow4d knot unknotting --exercise SEED --out K.curve, then --try N)");
  ImGui::TextWrapped("A knot whose unknotting number is one: changing one crossing of this picture, over "
                     "to under, makes it the unknot. Its crossings are numbered in the view; right-click "
                     "the one you choose.");
  if (o < 0) {
    ImGui::TextDisabled("(no exercise knot in the scene)");
  } else if (changed_at_) {
    ImGui::TextWrapped("%s", exercise_message_.c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("It was %s. Ctrl+Z puts the crossing back, to try another.", unknot_name_.c_str());
    ImGui::PopStyleColor();
  } else if (unknot_.valid() || !unknot_report_) {
    ImGui::TextDisabled("working out every crossing of this view...");
  } else {
    ImGui::TextWrapped("%s", exercise_message_.c_str());
  }
  model.dock.end();
}

void KnotPanels::overlay(GuiModel& model, const Camera& camera, const Rect& view) {
  labels_.clear();
  const int o = object_named(model.scene(), kExerciseKnot);
  // Kept after the user's change (dimmer), so that the crossings the verdict names can be found.
  if (o < 0 || !unknot_report_ || unknot_.valid() || model.touch_and_sound_only) return;
  const UnknottingReport& r = *unknot_report_;
  const ScreenCrossings sc = screen_crossings(model.scene(), camera);
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  for (const ScreenCrossing& c : sc.crossings) {
    if (c.object != o || camera.view_depth(c.over) <= camera.near_plane) continue;
    const int label = nearest_crossing(r, r.frame.to_view(c.over).head<2>());
    if (label <= 0) continue;
    ImVec2 px;
    if (!to_screen(camera, c.over, view, px)) continue;
    const ImVec2 at(px.x + 9, px.y - 9);
    const std::string text = std::to_string(label);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    dl->AddRectFilled(ImVec2(at.x - 3, at.y - 2), ImVec2(at.x + size.x + 3, at.y + size.y + 2),
                      IM_COL32(20, 20, 30, 210), 4.0f);
    dl->AddText(at, changed_at_ ? IM_COL32(170, 170, 170, 255) : IM_COL32(255, 230, 120, 255), text.c_str());
    labels_.push_back({label, px.x, px.y});
  }
}

bool KnotPanels::exercise_crossing(GuiModel& model, int object, const Vec3& over_point) {
  if (!unknot_report_ || changed_at_ || unknot_.valid() || object != object_named(model.scene(), kExerciseKnot))
    return false;
  const UnknottingReport& r = *unknot_report_;
  const int label = nearest_crossing(r, r.frame.to_view(over_point).head<2>());
  const std::string verdict = unknotting_verdict(r, label);
  if (verdict.empty()) return false;
  exercise_message_ = verdict;
  changed_at_ = model.session.history().done_labels().size() + 1;  // the change the window makes next
  model.status = exercise_message_;
  return true;
}

// [SECTION] dump
void KnotPanels::dump(nlohmann::ordered_json& out) const {
  using Json = nlohmann::ordered_json;
  Json buttons = Json::object();
  for (const auto& [label, r] : buttons_) buttons[label] = {r[0], r[1], r[2], r[3]};
  out["buttons"] = buttons;
  out["name_hidden"] = name_hidden_;
  // The name as the panel shows it, with its "(proven)" state (the page's tests compare both).
  if (shown_ && shown_->info) out["shown"] = {{"name", shown_->info->name}, {"proven", shown_->info->proven}};
  Json same = Json::object();
  if (pair_names_) same["pair"] = {pair_names_->a, pair_names_->b, pair_names_->same};
  if (same_answer_) {
    same["answer"] = same_answer_name(same_answer_->answer);
    same["reason"] = same_answer_->reason;
  }
  if (judgement_) same["judgement"] = {{"decided", judgement_->decided}, {"right", judgement_->right},
                                       {"text", judgement_->text}};
  out["same"] = same;
  Json unknot = Json::object();
  unknot["knot"] = unknot_name_;
  unknot["message"] = exercise_message_;
  unknot["changed"] = changed_at_.has_value();
  if (unknot_report_) unknot["unknotting"] = unknot_report_->unknotting;
  Json labels = Json::array();
  for (const ShownLabel& l : labels_) labels.push_back({{"label", l.label}, {"x", l.x}, {"y", l.y}});
  unknot["labels"] = labels;
  out["unknot"] = unknot;
}

}  // namespace s4d
