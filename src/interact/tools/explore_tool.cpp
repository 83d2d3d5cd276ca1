// The explore tool's events: the probe starts where the press hits the shadow, the hand moves on
// the plane facing the eye through that point, passes are collected from the session.
#include "interact/tools/explore_tool.hpp"

#include <cstdio>

#include "interact/live/curve_explorer_scene.hpp"
#include "interact/live/live_simulation.hpp"
#include "interact/session/session.hpp"
#include "view/view_crossings.hpp"

namespace s4d {

namespace {

// The scene's curves where they are drawn, as one curve (objects and components in order).
Curve<3> drawn_curves(const Scene& scene) {
  Curve<3> all;
  for (const SceneObject& o : scene.objects)
    for (Polyline<3>& p : drawn_curve(o.shape, scene.frame)) all.components.push_back(std::move(p));
  return all;
}

// The drawn curve point nearest the cursor on the screen, within `pixels`; nullopt when none.
std::optional<Vec3> curve_point_under(const ToolView& view, const Curve<3>& curves, double pixels) {
  std::optional<Vec3> best;
  double best_d = pixels;
  for (const auto& comp : curves.components)
    for (const Vec3& p : comp.points) {
      const Vec2 ndc = view.camera.ndc(p);
      if (!ndc.allFinite()) continue;
      const Vec2 px((ndc.x() + 1) * 0.5 * view.window.x(), (1 - ndc.y()) * 0.5 * view.window.y());
      const double d = (px - view.cursor).norm();
      if (d < best_d) {
        best_d = d;
        best = p;
      }
    }
  return best;
}

// A haptic device, not the mouse, is the loop's hand.
bool device_in_use(const Session& s) {
  return s.snapshot() && std::string_view(s.snapshot()->device_name) != "mouse";
}

}  // namespace

std::string ExploreTool::gauss_so_far() const {
  std::string out;
  for (const SceneEvent& e : passes_) {
    if (e.kind != kEventCrossedOver && e.kind != kEventCrossedUnder) continue;
    out += (out.empty() ? "" : ", ") + std::to_string(e.kind == kEventCrossedOver ? e.label : -e.label);
  }
  return out;
}

std::string ExploreTool::help() const {
  if (on_curve_) {
    if (!exploring_) return "explore: press on a strand and move along it; a cue at each crossing (high over, low under)";
    char b[96];
    std::snprintf(b, sizeof b, "exploring the knot: %zu crossing(s) passed; Gauss code so far: ", passes_.size());
    return b + gauss_so_far();
  }
  if (!exploring_) return "explore: press on a surface and move; the probe keeps to its sheet, a cue at each curve passed (high above in w, low below)";
  char b[160];
  int above = 0;
  for (const SceneEvent& e : passes_) above += e.kind == kEventPassedAbove;
  std::snprintf(b, sizeof b, "exploring: %zu curve(s) passed, %d above and %zu below in w; release to stop",
                passes_.size(), above, passes_.size() - static_cast<std::size_t>(above));
  return b;
}

void ExploreTool::hover(const ToolInput& in, Session& s) {
  const std::vector<SheetHit> hits = pick_sheets(s.scene(), in.view.eye, in.view.ray);
  s.set_hand(hits.empty() ? in.view.on_plane_through(in.view.centre) : hits[0].point, false);
}

void ExploreTool::offer_image(const ToolInput& in, Session& s) {
  const Curve<3> curves = drawn_curves(s.scene());
  if (curves.components.empty()) return;
  try {
    s.offer_curve_image(build_curve_image(curves, camera_frame(in.view.right, in.view.up, in.view.toward_eye)));
  } catch (const std::exception&) {  // a component too short to walk: keep the last image
  }
  image_time_ = in.time;
  image_camera_ = in.view.camera;
}

bool ExploreTool::press_curve(const ToolInput& in, Session& s) {
  const Curve<3> curves = drawn_curves(s.scene());
  if (curves.components.empty()) return false;
  const std::optional<Vec3> at = curve_point_under(in.view, curves, 16);
  if (!at) return false;
  on_curve_ = true;
  if (!s.simulating() || s.dimension() != 3) {
    message_ = "exploring a knot needs its live loop (the knot is not simulated here)";
    return false;
  }
  plane_point_ = *at;
  offer_image(in, s);
  return begin(s);
}

// The probe goes out at plane_point_: the mouse's is placed by the tool; a device's by its button
// (DeviceButton::kExplore: the loop places it at the device's point, which the hand led there).
bool ExploreTool::begin(Session& s) {
  s.set_hand(plane_point_, true);
  held_ = true;
  if (device_in_use(s)) return true;  // follow_device takes the exploration up
  s.send(live::StartExploring{live::point(plane_point_)});
  s.take_events();  // what happened before is not this exploration's
  passes_.clear();
  new_passes_.clear();
  exploring_ = true;
  message_ = help();
  return true;
}

bool ExploreTool::press(const ToolInput& in, Session& s) {
  if (by_device_) return false;  // the device's probe is out: the mouse turns the view meanwhile
  on_curve_ = false;
  if (press_curve(in, s)) return true;
  if (on_curve_) return false;
  const std::vector<SheetHit> hits = pick_sheets(s.scene(), in.view.eye, in.view.ray);
  if (hits.empty() || !s.simulating() || s.dimension() != 4) {
    if (!hits.empty() && s.dimension() != 4) message_ = "exploring needs a surface of R^4: its w is what the cues tell";
    return false;
  }
  plane_point_ = hits[0].point;
  return begin(s);
}

void ExploreTool::drag(const ToolInput& in, Session& s) {
  if (held_) s.set_hand(in.view.on_plane_through(plane_point_), true);
}

void ExploreTool::release(const ToolInput& in, Session& s) {
  if (!held_) return;
  held_ = false;
  update(in, s);
  if (exploring_ && !by_device_) {  // a device's probe stops with its button, in the loop
    exploring_ = false;
    s.send(live::StopExploring{});
  }
  s.set_hand(in.view.on_plane_through(plane_point_), false);
  message_ = help();
}

// A device explores through its button (DeviceButton::kExplore): the loop places the probe at the
// device's point, and its passes are collected here as the mouse's are.
void ExploreTool::follow_device(const ToolInput& in, Session& s) {
  const HapticSnapshot* snap = s.snapshot();
  const bool device = device_in_use(s);
  const bool probing = snap && snap->status.exploring;
  if (by_device_ && !probing) {
    for (const SceneEvent& e : s.take_events()) {
      passes_.push_back(e);
      new_passes_.push_back(e);
    }
    exploring_ = by_device_ = false;
    message_ = help();
    return;
  }
  if (!device || exploring_) return;
  if (s.dimension() == 3 && (in.time - image_time_ > 0.25 || !(in.view.camera.view() - image_camera_.view()).isZero(1e-12)))
    offer_image(in, s);  // the knot's image, ready for the button
  if (!probing) {
    s.take_events();  // what happened before is not the next exploration's
    return;
  }
  exploring_ = by_device_ = true;
  on_curve_ = s.dimension() == 3;
  passes_.clear();
  new_passes_.clear();
  message_ = help();
}

void ExploreTool::update(const ToolInput& in, Session& s) {
  follow_device(in, s);
  if (!exploring_) return;
  // The knot moves (it is simulated) and the view turns: its image follows a few times a second.
  if (on_curve_ && (in.time - image_time_ > 0.25 || !(in.view.camera.view() - image_camera_.view()).isZero(1e-12)))
    offer_image(in, s);
  for (const SceneEvent& e : s.take_events()) {
    passes_.push_back(e);
    new_passes_.push_back(e);
    message_ = help();
  }
}

void ExploreTool::overlay(Overlay& o, const Session& s) const {
  const HapticSnapshot* snap = s.snapshot();
  if (!snap || !snap->status.exploring) return;
  const Vec3 hand = s.mapping().to_shadow(snap->device.position);
  o.lines.push_back({hand, snap->status.probe, overlay_colour(0.8, 0.8, 0.8, 0.7), 2});
  o.dots.push_back({snap->status.probe, overlay_colour(1, 1, 1), 5, true});
  // The last passes where they happened: red above, blue below.
  const std::size_t from = passes_.size() > 12 ? passes_.size() - 12 : 0;
  for (std::size_t i = from; i < passes_.size(); ++i) {
    const SceneEvent& e = passes_[i];
    const bool above = e.kind == kEventPassedAbove || e.kind == kEventCrossedOver;
    o.dots.push_back({Vec3(e.point[0], e.point[1], e.point[2]),
                      above ? overlay_colour(0.95, 0.25, 0.2) : overlay_colour(0.25, 0.45, 1), 4, true});
  }
}

}  // namespace s4d
