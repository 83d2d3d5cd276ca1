#include "interact/tools/knot_sketch_tool.hpp"

#include <cmath>

#include "core/error.hpp"
#include "interact/session/session.hpp"
#include "knots/knot_diagram.hpp"
#include "knots/knot_naming.hpp"

namespace s4d {

SketchPlane::SketchPlane(const Camera& camera) {
  const Eigen::Quaterniond q = camera.orientation.normalized();
  centre = camera.target;
  right = q * Vec3::UnitX();
  up = q * Vec3::UnitY();
  toward_eye = q * Vec3::UnitZ();
}

bool SketchPlane::cursor_to_plane(const Camera& camera, const Vec2& cursor, const Vec2& window,
                                  Vec2& at) const {
  if (!(window.x() > 0 && window.y() > 0) || !cursor.allFinite()) return false;
  // The line of sight in eye coordinates (the eye looks down -z), then in the world.
  const double t = std::tan(camera.fov_y / 2);
  const Vec3 d_eye(camera.aspect * t * (2 * cursor.x() / window.x() - 1), t * (1 - 2 * cursor.y() / window.y()), -1);
  const Vec3 dir = camera.orientation.normalized() * d_eye;
  const Vec3 eye = camera.eye();
  const double denom = dir.dot(toward_eye);
  if (!(std::abs(denom) > 1e-12)) return false;
  const double s = (centre - eye).dot(toward_eye) / denom;
  if (!(s > 0) || !std::isfinite(s)) return false;
  const Vec3 p = eye + s * dir - centre;
  at = Vec2(p.dot(right), p.dot(up));
  return true;
}

void SketchTool::begin(const Camera& camera, const Vec2& cursor, const Vec2& window, double time, bool under) {
  cancel();
  camera_ = camera;
  plane_ = SketchPlane(camera);
  add(cursor, window, time, under);
}

void SketchTool::add(const Vec2& cursor, const Vec2& window, double time, bool under) {
  Vec2 at;
  if (!plane_.cursor_to_plane(camera_, cursor, window, at)) return;
  if (!stroke_.empty() && (at == stroke_.back().at || time < stroke_.back().time)) return;
  const double t0 = stroke_.empty() ? time : stroke_.front().time;
  stroke_.push_back({at, time - t0, under});
  screen_.emplace_back(cursor, under);
}

Curve<3> SketchTool::finish() {
  last_ = std::move(stroke_);
  cancel();
  // Objects of R^3 are drawn as they are, so the knot's points are where they were drawn.
  SketchedKnot k = knot_from_sketch(last_);
  for (Vec3& p : k.curve.components[0].points) p = plane_.to_shadow(p);
  return k.curve;
}

void SketchTool::cancel() {
  stroke_.clear();
  screen_.clear();
}

std::string CursorKnotSketchTool::help() const {
  return "sketch: drag to draw a closed curve; hold shift where it passes under; Esc stops";
}

bool CursorKnotSketchTool::press(const ToolInput& in, Session& s) {
  stroke_.begin(in.view.camera, in.view.cursor, in.view.window, in.time, in.shift);
  return true;
}

void CursorKnotSketchTool::drag(const ToolInput& in, Session& s) {
  if (stroke_.drawing()) stroke_.add(in.view.cursor, in.view.window, in.time, in.shift);
}

void CursorKnotSketchTool::release(const ToolInput& in, Session& s) {
  if (!stroke_.drawing()) return;
  if (stroke_.screen().size() < 3) {
    stroke_.cancel();
    message_ = "a click is not a stroke; " + help();
    return;
  }
  SceneObject obj;
  try {
    obj.shape = stroke_.finish();
  } catch (const std::exception& e) {
    message_ = std::string("no knot: ") + e.what();
    return;
  }
  int n = 1;
  for (const SceneObject& o : s.scene().objects) n += o.name.rfind("sketch-", 0) == 0;
  obj.name = "sketch-" + std::to_string(n);
  s.record("sketch a knot");
  s.scene().objects.push_back(std::move(obj));
  s.scene().view.intersections = true;  // its crossings and Gauss code
  message_ = "sketched " + s.scene().objects.back().name + "; " + help();
}

bool CursorKnotSketchTool::key(ToolKey k, const ToolInput&, Session&) {
  if (k != ToolKey::kEscape || !stroke_.drawing()) return false;
  stroke_.cancel();
  message_ = "stroke dropped";
  return true;
}

// The stroke so far: white where it passes over, blue where under.
void CursorKnotSketchTool::overlay(Overlay& o, const Session&) const {
  const auto& pts = stroke_.screen();
  for (std::size_t i = 1; i < pts.size(); ++i)
    o.screen_lines.push_back({pts[i - 1].first, pts[i].first,
                              pts[i].second ? overlay_colour(0.35, 0.6, 1) : overlay_colour(0.95, 0.95, 0.95), 3});
}

// [SECTION] sketching by touch
namespace {

constexpr std::uint32_t buttons_of(const ToolInput& in, bool down) {
  return (down ? kSketchDraw : 0u) | (in.shift ? kSketchUnder : 0u) | (in.ctrl ? kSketchOver : 0u);
}

// The plane facing the eye through the point the device's workspace centre shows.
Vec3 cursor_on_plane(const ToolInput& in, const Session& s) { return in.view.on_plane_through(s.mapping().centre); }

Vec3 from_device_plane(const Session& s, const Vec2& xy, double z) { return s.mapping().to_shadow(Vec3(xy.x(), xy.y(), z)); }

}  // namespace

std::string KnotSketchTool::help() const {
  if (last_.blocked) return "sketch: held before a strand; hold shift (under) or ctrl (over) to cross it";
  return "sketch by touch: drag to draw; shift crosses under, ctrl over (without, strands stop you); "
         "back near the start closes; press again for another component; Backspace undoes a segment; "
         "Enter finishes";
}

void KnotSketchTool::hand(const ToolInput& in, Session& s, bool down) {
  s.set_hand_buttons(cursor_on_plane(in, s), buttons_of(in, down));
}

bool KnotSketchTool::press(const ToolInput& in, Session& s) {
  if (!s.curve_sketch()) {
    message_ = "sketching needs the haptic loop, which did not start: " + s.physics_error();
    return false;
  }
  update(in, s);
  hand(in, s, true);
  return true;
}

void KnotSketchTool::drag(const ToolInput& in, Session& s) { hand(in, s, true); }
void KnotSketchTool::release(const ToolInput& in, Session& s) { hand(in, s, false); }
void KnotSketchTool::hover(const ToolInput& in, Session& s) { hand(in, s, false); }

bool KnotSketchTool::key(ToolKey k, const ToolInput&, Session& s) {
  switch (k) {
    case ToolKey::kBackspace:
    case ToolKey::kUndo:
      if (!busy()) return false;
      s.send(live::SketchBackspace{});
      message_ = "last segment removed";
      return true;
    case ToolKey::kRedo:
      if (!busy()) return false;  // the history's redo would drop the strokes: keep them
      message_ = "finish the sketch (Enter) or drop it (Esc) before redoing";
      return true;
    case ToolKey::kEnter:
      finish(s);
      return true;
    case ToolKey::kEscape:
      if (!busy()) return false;
      s.send(live::SketchClear{});
      message_ = "strokes dropped";
      return true;
    default: return false;
  }
}

void KnotSketchTool::leave(Session& s) {
  s.send(live::SketchEnd{});
  begun_ = false;
  last_ = SketchPublished();
}

// The scene's curves (not the strokes) as the loop sees them: in the device's plane coordinates.
void KnotSketchTool::offer_obstacles(Session& s) {
  CurveSketch* k = s.curve_sketch();
  if (!k) return;
  const DeviceMapping& m = s.mapping();
  const double z0 = m.workspace_centre.z();
  fixed_.clear();
  for (const SceneObject& o : s.scene().objects) {
    std::visit([&](const auto& sh) {
      using T = std::decay_t<decltype(sh)>;
      if constexpr (std::is_same_v<T, Curve<3>> || std::is_same_v<T, Curve<4>>) {
        for (const auto& comp : sh.components) {
          FixedStrand f;
          f.closed = comp.closed;
          for (const auto& p : comp.points) {
            Vec3 q;
            if constexpr (std::is_same_v<T, Curve<4>>) q = s.scene().frame.shadow(p);
            else q = p;
            const Vec3 d = m.to_device(q);
            if (!d.allFinite()) continue;
            f.points.push_back(d.head<2>());
            f.depth.push_back(d.z() - z0);
          }
          if (f.points.size() >= 2) fixed_.push_back(std::move(f));
        }
      }
    }, o.shape);
  }
  auto ob = std::make_unique<SketchStrands>();
  ob->strands = fixed_;
  k->offer_obstacles(std::move(ob));
}

void KnotSketchTool::update(const ToolInput&, Session& s) {
  CurveSketch* k = s.curve_sketch();
  if (!k) return;
  last_ = k->latest();
  if (!last_.active) {  // a new loop (a document opened, an undo, a sketched knot joining the World)
    s.send(live::SketchBegin{s.mapping().workspace_centre.z()});
    offer_obstacles(s);  // the new loop has none yet
    begun_ = true;
    finish_seen_ = last_.status.finish_requests;
    return;
  }
  if (!begun_) {
    offer_obstacles(s);
    begun_ = true;
  }
  if (last_.status.finish_requests > finish_seen_) {
    finish_seen_ = last_.status.finish_requests;
    finish(s);
  }
}

bool KnotSketchTool::finish(Session& s) {
  std::vector<StrokeComponent> comps;
  for (StrokeComponent& c : stroke_components(last_))
    if (c.points.size() >= 3) comps.push_back(std::move(c));
  if (comps.empty()) {
    message_ = "nothing to finish: drag to draw a stroke first";
    return false;
  }
  StrokeLink link;
  try {
    link = link_from_strokes(comps, stroke_crossings(last_), fixed_);
  } catch (const std::exception& e) {
    message_ = std::string("no knot: ") + e.what();
    return false;
  }
  last_gauss_ = diagram_from_curve(link.curve, Frame<3>()).gauss_code();
  Curve<3> shape = link.curve;
  for (Polyline<3>& p : shape.components)
    for (Vec3& q : p.points) q = from_device_plane(s, q.head<2>(), last_.plane_z + q.z());
  last_stroke_ = Curve<3>();
  Polyline<3> raw{{}, false};
  for (std::size_t i = 0; i < comps[0].points.size(); ++i)
    raw.points.emplace_back(comps[0].points[i].x(), comps[0].points[i].y(), comps[0].choices[i] == CrossChoice::kUnder ? 1.0 : 0.0);
  last_stroke_.components.push_back(std::move(raw));
  try {
    NamingOptions fast;  // on the UI thread: the fast naming, saying what it skipped (the Knot panel goes on)
    fast.fast = true;
    last_name_ = name_knot(shape, fast).headline();
  } catch (const std::exception& e) {
    last_name_ = std::string("(not named: ") + e.what() + ")";
  }
  SceneObject obj;
  obj.shape = std::move(shape);
  int n = 1;
  for (const SceneObject& o : s.scene().objects) n += o.name.rfind("sketch-", 0) == 0;
  obj.name = "sketch-" + std::to_string(n);
  s.record("sketch a knot");
  s.scene().objects.push_back(std::move(obj));
  s.scene().view.intersections = true;
  s.send(live::SketchClear{});
  offer_obstacles(s);
  last_ = SketchPublished();
  finished_ = true;
  message_ = "sketched " + s.scene().objects.back().name + ": " + last_name_ + ", " + std::to_string(link.crossings) +
             " crossing(s), Gauss code " + (last_gauss_.empty() ? "(none)" : last_gauss_);
  return true;
}

// The strokes as drawn (white; blue where drawn crossing under, orange over), the strand the
// probe is near glowing as strongly as it pushes, the proxy and the cursor it lags behind.
void KnotSketchTool::overlay(Overlay& o, const Session& s) const {
  if (!last_.active) return;
  const double z = last_.plane_z;
  auto colour = [](CrossChoice c) {
    return c == CrossChoice::kUnder ? overlay_colour(0.35, 0.6, 1) : c == CrossChoice::kOver ? overlay_colour(1, 0.6, 0.2)
                                                                                             : overlay_colour(0.95, 0.95, 0.95);
  };
  for (int c = 0; c < last_.component_count; ++c) {
    const int b = last_.component_begin[static_cast<std::size_t>(c)], e = last_.component_begin[static_cast<std::size_t>(c) + 1];
    for (int i = b + 1; i < e; ++i)
      o.lines.push_back({from_device_plane(s, last_.points[static_cast<std::size_t>(i) - 1], z),
                         from_device_plane(s, last_.points[static_cast<std::size_t>(i)], z),
                         colour(last_.choices[static_cast<std::size_t>(i)]), 3});
    if (last_.closed[static_cast<std::size_t>(c)] && e - b >= 3)
      o.lines.push_back({from_device_plane(s, last_.points[static_cast<std::size_t>(e) - 1], z),
                         from_device_plane(s, last_.points[static_cast<std::size_t>(b)], z), colour(CrossChoice::kNone), 3});
  }
  const SketchStatus& st = last_.status;
  if (st.near) {
    const double strength = std::clamp((st.repulsion + st.wall) / 1.0, 0.25, 1.0);
    const double radius = 0.012;  // m around the nearest point
    const std::uint32_t glow = overlay_colour(1, 0.85, 0.2, 0.35 + 0.55 * strength);
    auto near_segment = [&](const Vec2& a, const Vec2& b) {
      const Vec2 ab = b - a;
      const double l2 = ab.squaredNorm();
      const double t = l2 > 0 ? std::clamp((st.nearest - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
      if ((a + t * ab - st.nearest).norm() < radius)
        o.lines.push_back({from_device_plane(s, a, z), from_device_plane(s, b, z), glow, static_cast<float>(5 + 5 * strength)});
    };
    for (int i = 1; i < last_.point_count; ++i) near_segment(last_.points[static_cast<std::size_t>(i) - 1], last_.points[static_cast<std::size_t>(i)]);
    for (const FixedStrand& f : fixed_)
      for (std::size_t i = 1; i < f.points.size(); ++i) near_segment(f.points[i - 1], f.points[i]);
    o.dots.push_back({from_device_plane(s, st.nearest, z), glow, static_cast<float>(4 + 6 * strength), true});
  }
  const Vec3 probe = from_device_plane(s, st.probe.head<2>(), z);
  const Vec3 target = from_device_plane(s, st.target.head<2>(), z);
  o.lines.push_back({target, probe, last_.blocked ? overlay_colour(1, 0.3, 0.3) : overlay_colour(0.8, 0.8, 0.8, 0.7), 2});
  o.dots.push_back({target, overlay_colour(0.8, 0.8, 0.8, 0.8), 4, false});
  o.dots.push_back({probe, last_.blocked ? overlay_colour(1, 0.3, 0.3) : overlay_colour(1, 1, 1), 6, true});
}

}  // namespace s4d
