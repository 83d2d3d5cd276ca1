#include "app/hint_markers.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "app/panels.hpp"
#include "app/screen.hpp"
#include "scenario/script_driver.hpp"

namespace s4d {

namespace {

constexpr double kGhostSeconds = 1.6;
constexpr double kDoneShare = 0.75;  // a step is done when its centre went this share of the way

}  // namespace

Vec3 HintMarkers::shadow_of(const GuiModel& model, const Vec4& world) {
  return model.session.dimension() == 4 ? Vec3(model.session.scene().frame.shadow(world))
                                        : Vec3(world.head<3>());
}

Vec4 HintMarkers::centre(const GuiModel& model, const Step& s) const {
  const HapticSnapshot* snap = model.session.snapshot();
  Vec4 c = Vec4::Zero();
  if (!snap || s.vertices.empty()) return c;
  const int d = snap->point_dimension;
  for (int v : s.vertices)
    for (int k = 0; k < std::min(d, 4); ++k) c[k] += snap->points[static_cast<std::size_t>(v * d + k)];
  return c / static_cast<double>(s.vertices.size());
}

int HintMarkers::marker_under(const GuiModel& model, const Camera& camera, const Rect& view, const Vec2& cursor) const {
  const double r = 11 * model.ui_scale;
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    ImVec2 at;
    if (to_screen(camera, shadow_of(model, centre(model, steps_[i])), view, at) &&
        (Vec2(at.x, at.y) - cursor).norm() <= r)
      return static_cast<int>(i);
  }
  return -1;
}

double HintMarkers::marked_w(const GuiModel& model, int step) const {
  if (step < 0 || step >= static_cast<int>(steps_.size()) || model.session.dimension() != 4)
    return std::numeric_limits<double>::quiet_NaN();
  return model.session.scene().frame.to_view(centre(model, steps_[static_cast<std::size_t>(step)]))(3);
}

int HintMarkers::next() const {
  for (std::size_t i = 0; i < steps_.size(); ++i)
    if (!steps_[i].done) return static_cast<int>(i);
  return -1;
}

void HintMarkers::update(GuiModel& model, double time) {
  const auto& sc = model.session.scenario();
  const HapticSnapshot* snap = model.session.snapshot();
  if (!sc) {
    steps_.clear();
    resolved_for_.clear();
    model.hint_next.clear();
    return;
  }
  if (resolved_for_ != sc->file.string() && snap && snap->point_dimension > 0) {
    resolved_for_ = sc->file.string();
    steps_.clear();
    dim_ = snap->point_dimension;
    std::vector<int> first, count;
    for (int o = 0; o < static_cast<int>(model.scene().objects.size()); ++o) {
      first.push_back(model.session.first_vertex(o));
      count.push_back(model.session.vertex_count(o));
    }
    const int nv = static_cast<int>(snap->points.size()) / dim_;
    try {
      for (const Hint& h : sc->hints) {
        Step s;
        s.say = h.say;
        if (dim_ == 4) {
          std::vector<Vec<4>> x(static_cast<std::size_t>(nv));
          for (int v = 0; v < nv; ++v) x[v] = Vec4(&snap->points[static_cast<std::size_t>(v * 4)]);
          s.vertices = selected_vertices<4>(*sc, first, count, std::span<const Vec<4>>(x), h.select);
        } else {
          std::vector<Vec<3>> x(static_cast<std::size_t>(nv));
          for (int v = 0; v < nv; ++v) x[v] = Vec3(&snap->points[static_cast<std::size_t>(v * 3)]);
          s.vertices = selected_vertices<3>(*sc, first, count, std::span<const Vec<3>>(x), h.select);
        }
        s.start = centre(model, s);
        Vec4 by = Vec4::Zero();
        for (std::size_t k = 0; k < h.by.size() && k < 4; ++k) by[static_cast<int>(k)] = h.by[k];
        s.target = s.start + by;
        steps_.push_back(std::move(s));
      }
      // The motion the steps ask for fits in the view: the view's ball grows to take the targets.
      for (const Step& st : steps_) {
        const double d = (st.target - model.fit.centre).norm();
        if (!(d > model.fit.radius)) continue;
        const double radius = 0.5 * (d + model.fit.radius);
        model.fit.centre += (radius - model.fit.radius) / d * (st.target - model.fit.centre);
        model.fit.radius = radius;
      }
    } catch (const std::exception& e) {
      steps_.clear();
      model.status = std::string("the scenario's hints cannot be shown: ") + e.what();
    }
  }
  const int held = snap ? snap->status.held_vertex : -1;
  bool earlier_done = true;
  for (Step& s : steps_) {
    if (!s.anchored && snap) {
      const Vec4 by = s.target - s.start;
      s.start = centre(model, s);
      s.target = s.start + by;
      const bool taken = held >= 0 && std::find(s.vertices.begin(), s.vertices.end(), held) != s.vertices.end();
      s.anchored = taken || (earlier_done && held < 0);
    }
    const double way = (s.target - s.start).norm();
    s.done = s.done || (s.anchored && way > 0 &&
                        (centre(model, s) - s.start).dot(s.target - s.start) >= kDoneShare * way * way);
    earlier_done = earlier_done && s.done;
  }
  const int n = next();
  model.hint_next.clear();
  const MonitorResult checks = model.session.checks();
  const bool passed = checks.verdict && checks.verdict->pass && checks.true_intersections == 0;
  if (n >= 0 && !passed) {
    const Step& s = steps_[static_cast<std::size_t>(n)];
    model.hint_next = "step " + std::to_string(n + 1) + " of " + std::to_string(steps_.size()) + ": take marker " +
                      std::to_string(n + 1) + " to its target" + (s.say.empty() ? "" : " (" + s.say + ")");
  }
  if (std::exchange(model.show_me, false) && n >= 0) {
    ghost_start_ = time;
    ghost_step_ = n;
    model.status = "Show me: " + model.hint_next + "; the ghost runs along the arrow";
  }
  if (ghost_start_ >= 0 && time - ghost_start_ > kGhostSeconds) ghost_start_ = -1;
}

void HintMarkers::draw(const GuiModel& model, const Camera& camera, const Rect& view, double time) const {
  if (steps_.empty() || model.touch_and_sound_only) return;
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  dl->PushClipRect(ImVec2(view.x, view.y), ImVec2(view.right(), view.bottom()), true);
  const float s = model.ui_scale, r = 11 * s;
  const int lit = next();
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    const Step& st = steps_[i];
    ImVec2 at, to;
    if (!to_screen(camera, shadow_of(model, centre(model, st)), view, at)) continue;
    const bool has_target = (st.target - st.start).norm() > 0;
    const bool on = static_cast<int>(i) == lit;
    const ImU32 colour = st.done ? IM_COL32(120, 200, 120, 200) : on ? IM_COL32(255, 215, 60, 255) : IM_COL32(200, 200, 200, 170);
    if (has_target && !st.done && to_screen(camera, shadow_of(model, st.target), view, to)) {
      dl->AddLine(at, to, colour, on ? 2.5f * s : 1.5f * s);
      dl->AddCircle(to, r, colour, 24, 2.0f * s);  // the target
      dl->AddLine(ImVec2(to.x - r * 0.6f, to.y), ImVec2(to.x + r * 0.6f, to.y), colour, 1.5f * s);
      dl->AddLine(ImVec2(to.x, to.y - r * 0.6f), ImVec2(to.x, to.y + r * 0.6f), colour, 1.5f * s);
    }
    dl->AddCircleFilled(at, r, IM_COL32(20, 20, 30, 220), 24);
    dl->AddCircle(at, r, colour, 24, 2.0f * s);
    const std::string label = std::to_string(i + 1);
    const ImVec2 size = ImGui::CalcTextSize(label.c_str());
    dl->AddText(ImVec2(at.x - size.x / 2, at.y - size.y / 2), colour, label.c_str());
  }
  if (ghost_start_ >= 0 && ghost_step_ >= 0 && ghost_step_ < static_cast<int>(steps_.size())) {
    const Step& st = steps_[static_cast<std::size_t>(ghost_step_)];
    const double t = std::clamp((time - ghost_start_) / kGhostSeconds, 0.0, 1.0);
    const Vec4 from = centre(model, st);
    ImVec2 g;
    if (to_screen(camera, shadow_of(model, from + t * (st.target - from)), view, g))
      dl->AddCircleFilled(g, r * 0.8f, IM_COL32(255, 215, 60, 140), 24);
  }
  dl->PopClipRect();
}

}  // namespace s4d
