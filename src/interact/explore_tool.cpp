// The explore tool's events: the probe starts where the press hits the shadow, the hand moves on
// the plane facing the eye through that point, passes are collected from the session.
#include "interact/explore_tool.hpp"

#include <cstdio>

#include "interact/live_simulation.hpp"
#include "interact/session.hpp"

namespace s4d {

std::string ExploreTool::help() const {
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

bool ExploreTool::press(const ToolInput& in, Session& s) {
  const std::vector<SheetHit> hits = pick_sheets(s.scene(), in.view.eye, in.view.ray);
  if (hits.empty() || !s.simulating() || s.dimension() != 4) {
    if (!hits.empty() && s.dimension() != 4) message_ = "exploring needs a surface of R^4: its w is what the cues tell";
    return false;
  }
  plane_point_ = hits[0].point;
  s.set_hand(plane_point_, true);
  s.send(live_explore(true, plane_point_));
  s.take_events();  // what happened before is not this exploration's
  passes_.clear();
  new_passes_.clear();
  exploring_ = true;
  message_ = help();
  return true;
}

void ExploreTool::drag(const ToolInput& in, Session& s) {
  if (exploring_) s.set_hand(in.view.on_plane_through(plane_point_), true);
}

void ExploreTool::release(const ToolInput& in, Session& s) {
  if (!exploring_) return;
  update(in, s);
  exploring_ = false;
  s.send(live_explore(false));
  s.set_hand(in.view.on_plane_through(plane_point_), false);
  message_ = help();
}

void ExploreTool::update(const ToolInput&, Session& s) {
  if (!exploring_) return;
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
    const bool above = e.kind == kEventPassedAbove;
    o.dots.push_back({Vec3(e.point[0], e.point[1], e.point[2]),
                      above ? overlay_colour(0.95, 0.25, 0.2) : overlay_colour(0.25, 0.45, 1), 4, true});
  }
}

}  // namespace s4d
