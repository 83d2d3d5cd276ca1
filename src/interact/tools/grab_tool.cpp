// The grab tool's events: pick on hover, band on press, the hand on the drag plane.
#include "interact/tools/grab_tool.hpp"

#include <algorithm>
#include <cmath>

#include "interact/live/live_simulation.hpp"
#include "interact/session/session.hpp"

namespace s4d {

namespace {

// A knot's depth is the view's; a surface's shadow ray runs along w.
const char* along_what(const Session& s) { return s.dimension() == 3 ? "along the depth" : "along w"; }

}  // namespace

std::string GrabTool::help() const {
  const std::string rings = std::to_string(carry_rings_) + (carry_rings_ == 1 ? " ring" : " rings");
  std::string h = carry_ ? "touch: drag to carry the patch of " + rings +
                               " around the vertex (it stays held; [ ] size it, C: pull instead), Alt: along the shadow "
                               "ray, Tab: next sheet, P / right click: pin"
                         : "touch: drag a surface or a strand to pull it (Alt: along the shadow ray, C: carry a patch), "
                           "Tab: next sheet, P / right click: pin";
  if (hits_.size() > 1) h = sheet_text() + "; " + h;
  return h;
}

std::string GrabTool::sheet_text() const {
  const bool strand = !hits_.empty() && hits_[static_cast<std::size_t>(sheet_)].strand;
  return std::string(strand ? "strand " : "sheet ") + std::to_string(sheet_ + 1) + " of " +
         std::to_string(hits_.size()) + " under the cursor, Tab for the next";
}

int GrabTool::world_vertex(const SheetHit& h, const Session& s) {
  const int first = s.first_vertex(h.object);
  return first < 0 ? -1 : first + h.vertex;
}

std::vector<SheetHit> GrabTool::pick(const ToolInput& in, const Session& s) {
  std::vector<SheetHit> hits = pick_sheets(s.scene(), in.view.eye, in.view.ray);
  bool strands = false;
  for (const SheetHit& h : pick_strands(s.scene(), in.view.camera, in.view.cursor, in.view.window, kStrandPixels))
    if (s.first_vertex(h.object) >= 0) {  // a curve the World simulates
      hits.push_back(h);
      strands = true;
    }
  if (strands)
    std::stable_sort(hits.begin(), hits.end(), [](const SheetHit& a, const SheetHit& b) { return a.distance < b.distance; });
  return hits;
}

void GrabTool::choose(int sheet, const Vec2& cursor) {
  sheet_ = sheet;
  const SheetHit& h = hits_[static_cast<std::size_t>(sheet)];
  choice_ = Choice{cursor, h.object, h.strand ? h.distance : h.w, h.strand};
}

void GrabTool::take_chosen_sheet(const Vec2& cursor) {
  sheet_ = 0;  // the sheet nearest the eye, unless a choice made at this pixel says otherwise
  if (!choice_) return;
  if ((cursor - choice_->cursor).norm() > kChoicePixels) {
    choice_.reset();
    return;
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hits_.size(); ++i) {
    const SheetHit& h = hits_[i];
    if (choice_->object >= 0 && h.object != choice_->object) continue;
    const double d = std::abs((choice_->by_distance ? h.distance : h.w) - choice_->w);
    if (d < best) {  // strictly nearer: of two as near, the nearer the eye
      best = d;
      sheet_ = static_cast<int>(i);
    }
  }
}

void GrabTool::hover(const ToolInput& in, Session& s) {
  hits_ = pick(in, s);
  if (handle_) {  // a marker is drawn over every sheet: a press on it takes what it marks
    const SheetHit h = *handle_;
    std::erase_if(hits_, [&](const SheetHit& o) { return o.object == h.object && o.vertex == h.vertex; });
    hits_.insert(hits_.begin(), h);
    handle_.reset();
  }
  if (std::isfinite(preferred_w_)) {
    choice_ = Choice{in.view.cursor, -1, preferred_w_, false};
    preferred_w_ = std::numeric_limits<double>::quiet_NaN();
  }
  take_chosen_sheet(in.view.cursor);
  update_preview(s);
  // The mouse's hand rests where a press would take hold, so the band starts slack.
  hand_ = hits_.empty() ? in.view.on_plane_through(in.view.centre) : hits_[static_cast<std::size_t>(sheet_)].point;
  s.set_hand(hand_, false);
}

void GrabTool::update_preview(const Session& s) {
  preview_.vertices.clear();
  preview_.rings.clear();
  preview_.weights.clear();
  if (!carry_ || hits_.empty()) return;
  const SheetHit& h = hits_[static_cast<std::size_t>(sheet_)];
  const int first = s.first_vertex(h.object);
  if (first < 0 || h.object >= static_cast<int>(s.scene().objects.size())) return;
  const auto* surface = std::get_if<Surface<4>>(&s.scene().objects[static_cast<std::size_t>(h.object)].shape);
  const auto* surface3 = std::get_if<Surface<3>>(&s.scene().objects[static_cast<std::size_t>(h.object)].shape);
  if (!surface && !surface3) return;  // a curve's patch runs along its segments: the live one shows it
  const std::vector<Triangle>& tris = surface ? surface->triangles : surface3->triangles;
  const int nv = static_cast<int>(surface ? surface->vertices.size() : surface3->vertices.size());
  if (adjacency_object_ != h.object || adjacency_triangles_ != tris ||
      static_cast<int>(adjacency_offset_.size()) != nv + 1) {
    mesh_adjacency(tris, nv, adjacency_offset_, adjacency_);
    adjacency_object_ = h.object;
    adjacency_triangles_ = tris;
  }
  const int centre[] = {h.vertex};
  grow_patch(adjacency_offset_, adjacency_, centre, carry_rings_, preview_, preview_scratch_);
  for (int& v : preview_.vertices) v += first;
}

bool GrabTool::press(const ToolInput& in, Session& s) {
  hover(in, s);
  if (hits_.empty() || !s.simulating()) return false;
  const SheetHit& h = hits_[static_cast<std::size_t>(sheet_)];
  const int v = world_vertex(h, s);
  if (v < 0) return false;
  const std::string sheet = hits_.size() > 1 ? " (" + sheet_text() + ")" : "";
  choice_.reset();  // a Tab chooses for one press; the next takes the nearest sheet again
  along_w_ = in.alt;
  plane_point_ = h.point;
  hand_ = h.point;
  s.set_hand(hand_, true);
  const std::string how = carry_ ? "carry the patch around vertex " : "drag vertex ";
  s.record(how + std::to_string(v) + (along_w_ ? std::string(" ") + along_what(s) : ""));
  s.send(live::Grab{v, grab_mode(), live::point(hand_), carry_ ? carry_rings_ : 0});
  holding_ = true;
  const std::string patch = carry_ && !preview_.vertices.empty()
                                ? " (" + std::to_string(preview_.vertices.size()) + " vertices within " +
                                      std::to_string(carry_rings_) + (carry_rings_ == 1 ? " ring)" : " rings)")
                                : "";
  message_ = (carry_ ? "carrying the patch around vertex " : "holding vertex ") + std::to_string(v) + patch +
             (along_w_ ? std::string(" (") + along_what(s) + ")" : "") + sheet;
  return true;
}

void GrabTool::drag(const ToolInput& in, Session& s) {
  if (!holding_) return;
  if (in.alt != along_w_) {
    along_w_ = in.alt;
    s.send(live::SetGrabMode{grab_mode()});
  }
  hand_ = in.view.on_plane_through(plane_point_);
  s.set_hand(hand_, true);
}

void GrabTool::release(const ToolInput& in, Session& s) {
  if (!holding_) return;
  holding_ = false;
  s.send(live::Release{});
  s.set_hand(hand_, false);
  message_ = carry_ ? "let go: the patch stays held where it is (P unpins)" : "let go";
}

bool GrabTool::wheel(double steps, const ToolInput& in, Session& s) {
  if (!holding_ || !std::isfinite(steps)) return false;
  // Twenty pixels' worth of depth a notch: the hand moves toward (or away from) the eye.
  plane_point_ += steps * 20 * in.view.pixel_size * in.view.toward_eye;
  hand_ = in.view.on_plane_through(plane_point_);
  s.set_hand(hand_, true);
  return true;
}

void GrabTool::toggle_pin_under_cursor(Session& s) {
  if (hits_.empty()) return;
  const int v = world_vertex(hits_[static_cast<std::size_t>(sheet_)], s);
  if (v < 0) return;
  const bool was = s.pinned(v);
  s.record((was ? "unpin vertex " : "pin vertex ") + std::to_string(v));
  s.send(live::Pin{v, live::PinAction::kToggle});
  message_ = (was ? "unpinned vertex " : "pinned vertex ") + std::to_string(v);
}

bool GrabTool::right_click(const ToolInput& in, Session& s) {
  hover(in, s);
  if (hits_.empty() || !s.simulating()) return false;
  toggle_pin_under_cursor(s);
  return true;
}

void GrabTool::set_carry_rings(int rings) { carry_rings_ = std::clamp(rings, kMinCarryRings, kMaxCarryRings); }

bool GrabTool::key(ToolKey k, const ToolInput& in, Session& s) {
  const auto rings_text = [&] { return std::to_string(carry_rings_) + (carry_rings_ == 1 ? " ring" : " rings"); };
  if (k == ToolKey::kCarry && !holding_) {
    carry_ = !carry_;
    message_ = carry_ ? "carry: a drag carries the patch of " + rings_text() +
                            " of edges around the vertex, and it stays held ([ ] size it)"
                      : "pull: a drag pulls one vertex on the rubber band";
    return true;
  }
  if ((k == ToolKey::kSmaller || k == ToolKey::kLarger) && !holding_) {
    set_carry_rings(carry_rings_ + (k == ToolKey::kLarger ? 1 : -1));
    carry_ = true;
    hover(in, s);
    message_ = "carry " + rings_text() + " around the vertex" +
               (preview_.vertices.empty() ? "" : " (" + std::to_string(preview_.vertices.size()) + " vertices here)");
    return true;
  }
  if (k == ToolKey::kTab && !holding_) {
    hover(in, s);
    if (hits_.size() > 1) {
      choose((sheet_ + 1) % static_cast<int>(hits_.size()), in.view.cursor);
      update_preview(s);
      hand_ = hits_[static_cast<std::size_t>(sheet_)].point;
      s.set_hand(hand_, false);
      const SheetHit& h = hits_[static_cast<std::size_t>(sheet_)];
      message_ = sheet_text() + (h.strand ? " (" + std::to_string(h.distance).substr(0, 6) + " from the eye)"
                                          : " (w = " + std::to_string(h.w).substr(0, 6) + ")");
    } else {
      message_ = hits_.empty() ? "Tab: nothing under the cursor" : "Tab: one sheet under the cursor";
    }
    return true;
  }
  if (k == ToolKey::kPin && s.simulating()) {
    if (holding_ && s.snapshot()) {  // pin the held vertex where it is and let go
      const int v = s.snapshot()->status.held_vertex;
      release(in, s);
      if (v >= 0) {
        s.record("pin vertex " + std::to_string(v));
        s.send(live::Pin{v, live::PinAction::kPin});
      }
      message_ = "pinned vertex " + std::to_string(v);
    } else {
      hover(in, s);
      toggle_pin_under_cursor(s);
    }
    return true;
  }
  return false;
}

void GrabTool::overlay(Overlay& o, const Session& s) const {
  const HapticSnapshot* snap = s.snapshot();
  if (!holding_ && !hits_.empty()) {
    const SheetHit& h = hits_[static_cast<std::size_t>(sheet_)];
    o.dots.push_back({h.point, overlay_colour(1, 1, 1, 0.9), 6, false});
    // The patch a press would carry: its vertices, brighter where they go further with the hand.
    for (std::size_t i = 1; i < preview_.vertices.size(); ++i) {
      const Vec3 p = s.vertex_shadow(preview_.vertices[i]);
      if (p.allFinite()) o.dots.push_back({p, overlay_colour(1, 1, 1, 0.25 + 0.6 * preview_.weights[i]), 2.5f, true});
    }
    for (std::size_t i = 0; i < hits_.size(); ++i)
      if (static_cast<int>(i) != sheet_) o.dots.push_back({hits_[i].point, overlay_colour(1, 1, 1, 0.35), 3, false});
  }
  if (!snap) return;
  // Pins: a carried patch holds many, drawn finer so that the surface stays visible.
  std::size_t pins = 0;
  for (std::uint8_t f : snap->flags) pins += f & 1;
  const float pin_radius = pins > 24 ? 2.5f : 4;
  for (std::size_t v = 0; v < snap->flags.size(); ++v)
    if (snap->flags[v] & 1) {
      const Vec3 p = s.vertex_shadow(static_cast<int>(v));
      if (p.allFinite()) o.dots.push_back({p, overlay_colour(1, 0.55, 0.1), pin_radius, true});
    }
  if (snap->status.held_vertex >= 0) {
    // The band: green slack, yellow, red at the most it may pull.
    const double maxf = snap->param_count > kBandMaxForce ? snap->params[kBandMaxForce].value : 1;
    const double t = std::clamp(snap->status.band_force / std::max(maxf, 1e-9), 0.0, 1.0);
    const std::uint32_t c = overlay_colour(std::min(1.0, 2 * t), std::min(1.0, 2 * (1 - t)), 0.15);
    const Vec3 to = s.vertex_shadow(snap->status.held_vertex);
    o.lines.push_back({snap->status.band_from, to.allFinite() ? to : snap->status.band_to, c, 3});
    o.dots.push_back({snap->status.band_from, c, 5, true});
  }
  if (std::string_view(snap->device_name) != "mouse") {
    // A device's point: where its button would take hold.
    o.dots.push_back({s.mapping().to_shadow(snap->device.position), overlay_colour(0.3, 0.9, 1), 8, false});
  }
}

}  // namespace s4d
