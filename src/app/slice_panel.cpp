// The Slice panel: the level, the live name, the critical levels, the curve it makes and the movie
// strip (see slice_panel.hpp).
// Sections: [SECTION] level, [SECTION] panel, [SECTION] movie strip.
#include "app/slice_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <nlohmann/json.hpp>

#include "app/panels.hpp"
#include "core/threads.hpp"
#include "render/curve_diagram.hpp"
#include "render/scene_geometry.hpp"
#include "shape/level_set.hpp"

namespace s4d {

namespace {

// A full sweep from the bottom of the range of w to its top takes this long.
constexpr double kSweepSeconds = 8;

std::string level_text(double c) {
  char b[32];
  std::snprintf(b, sizeof b, "%+.3f", c);
  return b;
}

std::size_t curve_hash(const Curve<3>& c) {
  std::size_t h = c.components.size();
  const std::hash<double> hd;
  for (const Polyline<3>& line : c.components) {
    h = h * 1000003u ^ (line.closed ? 1u : 2u);
    for (const Vec3& p : line.points)
      for (int k = 0; k < 3; ++k) h = (h ^ hd(p[k])) * 1099511628211u;
  }
  return h;
}

void disabled_wrapped(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

Curve<3> closed_part(const Curve<3>& c) {
  Curve<3> out;
  for (const Polyline<3>& line : c.components)
    if (line.closed) out.components.push_back(line);
  return out;
}

}  // namespace

// [SECTION] level
void toggle_slice(GuiModel& model) {
  ViewSettings& v = model.scene().view;
  if (!has_4d_surfaces(model.scene())) {
    model.status = "nothing to slice: the slice cuts surfaces of R^4 by w = c";
    return;
  }
  v.slice = !v.slice;
  const auto [lo, hi] = scene_depth_range(model.scene());
  if (v.slice && !(v.slice_level >= lo && v.slice_level <= hi)) v.slice_level = 0.5 * (lo + hi);
  model.status = v.slice ? "slice w = " + level_text(v.slice_level) + " (Alt+wheel moves it, W hides it)"
                         : "slice hidden (W shows it)";
}

void step_slice(GuiModel& model, double notches) {
  ViewSettings& v = model.scene().view;
  if (!v.slice || !std::isfinite(notches)) return;
  const auto [lo, hi] = scene_depth_range(model.scene());
  const double from = std::isfinite(v.slice_level) ? v.slice_level : 0.5 * (lo + hi);
  v.slice_level = std::clamp(from + notches * (hi - lo) / 40, lo, hi);
  model.status = "slice w = " + level_text(v.slice_level);
}

// [SECTION] panel
bool SlicePanel::button(const char* label) {
  const bool pressed = ImGui::Button(label);
  remember(label);
  return pressed;
}

void SlicePanel::remember(const char* label) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  buttons_[label] = {a.x, a.y, b.x, b.y};
}

bool SlicePanel::busy() const {
  const auto latest = worker_.latest();
  const bool naming = submitted_ > 0 && (!latest || latest->request < submitted_);
  return naming || movie_job_.valid();
}

std::string SlicePanel::shown_name() const {
  if (!on_) return "";
  if (components_ == 0) return open_ > 0 ? "open arcs only" : "empty";
  return shown_ && shown_->info ? shown_->info->name : "";
}

void SlicePanel::name_live(const SceneSlice& slice) {
  const Curve<3> closed = closed_part(slice.curve);
  components_ = static_cast<int>(closed.components.size());
  open_ = slice.open_components;
  if (closed.components.empty()) return;
  const std::size_t h = curve_hash(closed);
  if (h != submitted_hash_) {  // the level moved, the surface moved or the view turned: ask again
    submitted_hash_ = h;
    submitted_ = worker_.submit(closed, Frame<3>{});
  }
}

void SlicePanel::make_curve(GuiModel& model, const SceneSlice& slice) {
  Scene& scene = model.scene();
  // A knot of R^3 in the slice's own coordinates (the shadow's, as the panel named it: the same
  // chirality), so that the Knot panel names it and the knot tools act on it; set beside the
  // surfaces, centred there, so that it meets nothing.
  const ViewFit fit = fit_of(scene);
  SceneObject obj;
  obj.name = "slice w" + level_text(slice.level);
  Curve<3> knot = slice.curve;
  Vec3 centroid = Vec3::Zero();
  const std::size_t n = knot.point_count();
  for (const Polyline<3>& line : knot.components)
    for (const Vec3& p : line.points) centroid += p / static_cast<double>(n);
  const Vec3 beside = fit.centre.head<3>() + Vec3(2.2 * std::max(fit.radius, 0.1), 0, 0) - centroid;
  for (Polyline<3>& line : knot.components)
    for (Vec3& p : line.points) p += beside;
  obj.shape = std::move(knot);
  for (int k = 2; std::any_of(scene.objects.begin(), scene.objects.end(),
                              [&](const SceneObject& o) { return o.name == obj.name; });
       ++k)
    obj.name = "slice w" + level_text(slice.level) + " (" + std::to_string(k) + ")";
  try {
    const std::string name = obj.name;
    model.session.add_object(std::move(obj), "make the slice a curve");
    model.status = "'" + name + "' is a curve of the scene now, a knot of R^3 beside the surfaces (Ctrl+Z takes it back)";
  } catch (const std::exception& e) {
    model.error = e.what();
  }
}

void SlicePanel::draw(GuiModel& model, const Camera& camera) {
  buttons_.clear();
  drawn_ = false;
  Scene& scene = model.scene();
  if (!has_4d_surfaces(scene)) {
    on_ = false;
    return;
  }
  ViewSettings& v = scene.view;
  const auto [lo, hi] = scene_depth_range(scene);
  if (sweep_ && v.slice && hi > lo) {
    v.slice_level += sweep_direction_ * (hi - lo) * ImGui::GetIO().DeltaTime / kSweepSeconds;
    if (v.slice_level >= hi) v.slice_level = hi, sweep_direction_ = -1;
    if (v.slice_level <= lo) v.slice_level = lo, sweep_direction_ = 1;
  }
  on_ = v.slice;
  level_ = v.slice_level;
  // Only while the slice shows (the status line's Slice button, W, View > Slice turn it on), so
  // that the view keeps its room otherwise.
  if (!v.slice || !model.dock.begin(Side::kRight, "Slice")) return;
  drawn_ = true;
  bool on = v.slice;
  if (ImGui::Checkbox("slice by w = c (W)", &on)) toggle_slice(model);
  remember("slice");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the surfaces cut by the hyperplane w = c of the 4D view: a link of R^3, drawn on the\n"
                      "shadow in amber and named live; Alt+wheel over the view moves c");
  float level = static_cast<float>(std::isfinite(v.slice_level) ? v.slice_level : 0.5 * (lo + hi));
  if (ImGui::SliderFloat("c", &level, static_cast<float>(lo), static_cast<float>(hi), "%.3f")) {
    v.slice_level = level;
    if (!v.slice) toggle_slice(model);
  }
  remember("level");
  if (ImGui::Checkbox("sweep", &sweep_) && sweep_ && !v.slice) toggle_slice(model);
  remember("sweep");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the level runs up and down the range of w: the surface's movie");
  ImGui::SameLine();
  ImGui::Checkbox("fade the surfaces", &v.slice_fade);
  remember("fade");
  on_ = v.slice;
  level_ = v.slice_level;

  std::vector<CriticalPoint> points;
  for (const SceneCriticalPoint& p : scene_critical_points(scene)) points.push_back(p.point);
  critical_ = count_critical(points);
  if (v.slice) {
    try {
      const SceneSlice slice = scene_slice(scene, v.slice_level);
      name_live(slice);
      if (auto r = worker_.latest()) shown_ = r;
      const bool stale = shown_ && shown_->request < submitted_;
      if (components_ == 0) {
        ImGui::TextWrapped("%s", open_ > 0 ? "open arcs only (the surface's boundary)" : "empty: w = c misses the surfaces");
      } else if (!shown_) {
        ImGui::TextDisabled("naming...");
      } else if (!shown_->info) {
        ImGui::TextWrapped("not named: %s", shown_->error.c_str());
      } else {
        const KnotInfo& k = *shown_->info;
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(kSliceColour.x(), kSliceColour.y(), kSliceColour.z(), 1));
        ImGui::TextWrapped("%s%s", short_knot_name(k.identification, k.candidates).c_str(),
                           k.proven ? "  (proven)" : "  (not proven)");
        ImGui::PopStyleColor();
        if (stale) {
          ImGui::SameLine();
          ImGui::TextDisabled("...");
        }
        ImGui::TextWrapped("%d component%s%s", components_, components_ == 1 ? "" : "s",
                           open_ > 0 ? (", " + std::to_string(open_) + " open arc(s)").c_str() : "");
        if (k.components > 1) {
          std::string lk;
          for (std::size_t i = 0; i < k.linking.size(); ++i)
            for (std::size_t j = i + 1; j < k.linking[i].size(); ++j)
              lk += (lk.empty() ? "" : ", ") + std::string("lk(") + std::to_string(i + 1) + "," +
                    std::to_string(j + 1) + ") = " + std::to_string(k.linking[i][j]);
          ImGui::TextWrapped("linking numbers: %s", lk.c_str());
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", k.name.c_str());
        if (!k.decided_by.empty()) disabled_wrapped("decided by: " + k.decided_by.front());
      }
      if (components_ + open_ > 0 && button("Make it a curve")) make_curve(model, slice);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("adds the slice as a curve of the scene beside the surfaces, to sketch on, name or save\n"
                          "(one undoable step)");
    } catch (const std::exception& e) {
      ImGui::TextWrapped("cannot slice: %s", e.what());
    }
  }
  disabled_wrapped("critical levels: " + std::to_string(critical_.births) + " births, " +
                   std::to_string(critical_.saddles) + " saddles, " + std::to_string(critical_.deaths) +
                   " deaths (Euler characteristic " + std::to_string(critical_.euler_characteristic()) + ")");
  movie_open_ = ImGui::CollapsingHeader("Movie");
  remember("Movie");
  if (movie_open_) movie_strip(model, camera, lo, hi);
  model.dock.end();
}

// [SECTION] movie strip
void SlicePanel::movie_strip(GuiModel& model, const Camera& camera, double lo, double hi) {
  Scene& scene = model.scene();
  movie_levels_ = movie_levels(lo, hi, kMovieFrames);
  std::vector<SceneSlice> slices;
  std::size_t h = 0;
  for (double c : movie_levels_) {
    slices.push_back(scene_slice(scene, c));
    h = h * 31u + curve_hash(slices.back().curve);
  }
  movie_hash_ = h;
  if (movie_job_.valid() && movie_job_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    movie_names_ = movie_job_.get();
  }
  if (!movie_job_.valid() && movie_named_hash_ != movie_hash_) {
    movie_named_hash_ = movie_hash_;
    std::vector<Curve<3>> curves;
    for (const SceneSlice& s : slices) curves.push_back(s.curve);
    movie_job_ = run_in_background([curves = std::move(curves), levels = movie_levels_] {
      NamingOptions fast;
      fast.fast = true;  // nine at once, while the surface may be moving: the live line's mode
      std::vector<SliceNaming> names;
      for (std::size_t i = 0; i < curves.size(); ++i) names.push_back(name_slice(curves[i], levels[i], fast));
      return names;
    });
  }

  // The frames share one framing: the box of every frame's slice as the view's camera sees it.
  Vec2 box_lo = Vec2::Constant(1e300), box_hi = Vec2::Constant(-1e300);
  for (const SceneSlice& sl : slices)
    for (const Polyline<3>& line : sl.curve.components)
      for (const Vec3& p : line.points) {
        const Vec2 q = screen_point(camera, p);
        box_lo = box_lo.cwiseMin(q);
        box_hi = box_hi.cwiseMax(q);
      }
  if (!(box_hi.x() > box_lo.x())) box_lo = Vec2(-camera.aspect, -1), box_hi = Vec2(camera.aspect, 1);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float avail = ImGui::GetContentRegionAvail().x;
  const float gap = 4 * ImGui::GetIO().FontGlobalScale;
  const int across = 3;
  const float w = (avail - gap * (across - 1)) / across, hgt = w * 0.75f;
  thumbnails_.clear();
  ViewSettings& v = scene.view;
  for (std::size_t i = 0; i < slices.size(); ++i) {
    if (i % across != 0) ImGui::SameLine(0, gap);
    ImGui::BeginGroup();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::InvisibleButton("frame", ImVec2(w, hgt))) {
      v.slice_level = movie_levels_[i];
      if (!v.slice) toggle_slice(model);
      v.slice_level = movie_levels_[i];
      sweep_ = false;
    }
    ImGui::PopID();
    thumbnails_.push_back({at.x, at.y, at.x + w, at.y + hgt});
    const bool current = v.slice && std::abs(v.slice_level - movie_levels_[i]) < 1e-9 * std::max(1.0, hi - lo);
    dl->AddRectFilled(at, ImVec2(at.x + w, at.y + hgt), IM_COL32(24, 26, 32, 255));
    dl->AddRect(at, ImVec2(at.x + w, at.y + hgt), current ? IM_COL32(255, 140, 0, 255) : IM_COL32(70, 74, 84, 255));
    const Vec2 mid = 0.5 * (box_lo + box_hi);
    const double scale = 0.9 * std::min(w / (box_hi.x() - box_lo.x()), hgt / std::max(box_hi.y() - box_lo.y(), 1e-12));
    for (const Polyline<3>& line : slices[i].curve.components) {
      std::vector<ImVec2> pts;
      for (const Vec3& p : line.points) {
        const Vec2 q = screen_point(camera, p) - mid;  // screen coordinates, y up
        pts.emplace_back(at.x + 0.5f * w + static_cast<float>(scale * q.x()),
                         at.y + 0.5f * hgt - static_cast<float>(scale * q.y()));
      }
      dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), IM_COL32(255, 140, 0, 255),
                      line.closed ? ImDrawFlags_Closed : ImDrawFlags_None, 1.5f);
    }
    const std::string label = i < movie_names_.size() ? movie_names_[i].label : "...";
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + w);
    ImGui::TextDisabled("%s", level_text(movie_levels_[i]).c_str());
    ImGui::TextWrapped("%s", label.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndGroup();
  }
}

void SlicePanel::dump(nlohmann::ordered_json& out) const {
  using Json = nlohmann::ordered_json;
  out["drawn"] = drawn_;
  out["on"] = on_;
  out["level"] = level_;
  out["name"] = shown_name();
  out["components"] = components_;
  out["open_components"] = open_;
  const auto latest = worker_.latest();
  const bool naming = submitted_ > 0 && (!latest || latest->request < submitted_);
  out["naming"] = naming;
  if (on_ && components_ > 0 && shown_ && shown_->info) {
    const KnotInfo& k = *shown_->info;
    out["label"] = short_knot_name(k.identification, k.candidates);
    out["proven"] = k.proven;
    out["linking"] = k.linking;
  }
  out["critical"] = {{"births", critical_.births},
                     {"saddles", critical_.saddles},
                     {"deaths", critical_.deaths},
                     {"euler_characteristic", critical_.euler_characteristic()}};
  Json buttons = Json::object();
  for (const auto& [label, r] : buttons_) buttons[label] = {r[0], r[1], r[2], r[3]};
  out["buttons"] = buttons;
  Json movie = Json::array();
  for (std::size_t i = 0; i < thumbnails_.size() && i < movie_levels_.size(); ++i) {
    Json f = {{"level", movie_levels_[i]},
              {"rect", {thumbnails_[i][0], thumbnails_[i][1], thumbnails_[i][2], thumbnails_[i][3]}}};
    if (i < movie_names_.size()) f["name"] = movie_names_[i].label;
    movie.push_back(f);
  }
  out["movie"] = movie;
}

}  // namespace s4d
