// The sketch in the tick: [SECTION] commands, [SECTION] strokes (segments, resampling, closing,
// Backspace), [SECTION] the head (blocked before strands without a choice), [SECTION] forces
// (Eq. 1-3 and the wall), [SECTION] publishing, [SECTION] scene.
#include "interact/live/curve_sketch_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace s4d {

SketchPublished::SketchPublished() {
  points.reserve(kMaxPoints);
  choices.reserve(kMaxPoints);
  component_begin.reserve(kMaxComponents + 1);
  closed.reserve(kMaxComponents);
  crossings.reserve(kMaxCrossings);
}

std::vector<StrokeComponent> stroke_components(const SketchPublished& p) {
  std::vector<StrokeComponent> out;
  for (int c = 0; c < p.component_count; ++c) {
    StrokeComponent s;
    const int b = p.component_begin[static_cast<std::size_t>(c)], e = p.component_begin[static_cast<std::size_t>(c) + 1];
    s.points.assign(p.points.begin() + b, p.points.begin() + e);
    s.choices.assign(p.choices.begin() + b, p.choices.begin() + e);
    s.closed = p.closed[static_cast<std::size_t>(c)] != 0;
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<StrokeCrossing> stroke_crossings(const SketchPublished& p) {
  return {p.crossings.begin(), p.crossings.begin() + p.crossing_count};
}

CurveSketch::CurveSketch(const SketchSettings& settings) : s_(settings), pen_(settings.pen) {
  points_.reserve(SketchPublished::kMaxPoints);
  choices_.reserve(SketchPublished::kMaxPoints);
  comp_begin_.assign(SketchPublished::kMaxComponents + 1, 0);
  comp_closed_.assign(SketchPublished::kMaxComponents, 0);
  segments_.reserve(4096);
  crossings_.reserve(SketchPublished::kMaxCrossings);
  crossing_point_.reserve(SketchPublished::kMaxCrossings);
}

// [SECTION] commands
// Each publishes at once, so that the UI sees the strokes' new state without waiting for a tick.
void CurveSketch::begin(double plane_z) {
  if (std::isfinite(plane_z)) {
    if (!active_ || plane_z_ != plane_z) forget_strokes();
    plane_z_ = plane_z;
    active_ = true;
  }
  publish(true);
}

void CurveSketch::end() {
  forget_strokes();
  active_ = false;
  publish(true);
}

void CurveSketch::clear() {
  forget_strokes();
  publish(true);
}

// [SECTION] strokes
void CurveSketch::forget_strokes() {
  points_.clear();
  choices_.clear();
  segments_.clear();
  crossings_.clear();
  crossing_point_.clear();
  comps_ = 0;
  drawing_ = false;
  wait_release_ = (buttons_ & kSketchDraw) != 0;  // a stroke in progress does not go on
  blocked_ = false;
  ++revision_;
}

void CurveSketch::store(const Vec2& at, CrossChoice choice) {
  if (static_cast<int>(points_.size()) >= SketchPublished::kMaxPoints) {
    ++status_.full;
    return;
  }
  const int c = comps_ - 1;
  const int first = comp_begin_[static_cast<std::size_t>(c)];
  if (static_cast<int>(points_.size()) > first) drawn_ += (at - points_.back()).norm();
  points_.push_back(at);
  choices_.push_back(choice);
  comp_begin_[static_cast<std::size_t>(comps_)] = static_cast<int>(points_.size());
  ++revision_;
  // Back near the start after having left it: the component closes.
  const Vec2 start = points_[static_cast<std::size_t>(first)];
  const double from_start = (at - start).norm();
  if (from_start > 3 * s_.close_radius) left_start_ = true;
  if (drawing_ && left_start_ && from_start < s_.close_radius && drawn_ > 8 * s_.close_radius) {
    comp_closed_[static_cast<std::size_t>(c)] = 1;
    if (!segments_.empty()) segments_.back().closed_component = true;
    drawing_ = false;
    wait_release_ = true;
  }
}

void CurveSketch::begin_segment(const Vec2& at) {
  const bool can_join = comps_ > 0 && !comp_closed_[static_cast<std::size_t>(comps_ - 1)] && !points_.empty() &&
                        (points_.back() - at).norm() < s_.join_radius;
  if (!can_join) {
    if (comps_ >= SketchPublished::kMaxComponents || segments_.size() >= segments_.capacity()) {
      ++status_.full;
      wait_release_ = true;
      return;
    }
    comp_begin_[static_cast<std::size_t>(comps_)] = static_cast<int>(points_.size());
    comp_closed_[static_cast<std::size_t>(comps_)] = 0;
    ++comps_;
    comp_begin_[static_cast<std::size_t>(comps_)] = static_cast<int>(points_.size());
    drawn_ = 0;
    left_start_ = false;
  } else if (segments_.size() >= segments_.capacity()) {
    ++status_.full;
    wait_release_ = true;
    return;
  }
  segments_.push_back({comps_ - 1, static_cast<int>(points_.size()), !can_join, false});
  drawing_ = true;
  blocked_ = false;
  head_ = at;
  pen_ = Dynadraw<2>(s_.pen);
  pen_.reset(at);
  store(at, CrossChoice::kNone);
}

// The pen trails the head: on release it is let settle onto the head (at most 0.3 s of pen time
// in this tick), so the stroke ends where the hand let go.
void CurveSketch::end_segment() {
  if (!drawing_) return;
  for (int k = 0; k < 300 && drawing_ && (pen_.position() - head_).norm() > 0.25 * s_.spacing; ++k) {
    pen_.step(head_, 1e-3);
    resample_to_pen(CrossChoice::kNone);
  }
  if (drawing_ && !points_.empty() && (head_ - points_.back()).norm() > 0.5 * s_.spacing) store(head_, CrossChoice::kNone);
  drawing_ = false;
  blocked_ = false;
}

// A point every `spacing` along the pen's path, up to where the pen is.
void CurveSketch::resample_to_pen(CrossChoice choice) {
  for (int k = 0; k < 64 && drawing_ && !points_.empty(); ++k) {
    const Vec2 to = pen_.position() - points_.back();
    const double l = to.norm();
    if (!(l >= s_.spacing)) break;
    store(points_.back() + (s_.spacing / l) * to, choice);
  }
}

// The last segment goes: the one being drawn (drawing then waits for the button's release), or
// the last one drawn, reopening its component if it had closed it.
void CurveSketch::backspace() {
  remove_last_segment();
  publish(true);
}

void CurveSketch::remove_last_segment() {
  if (segments_.empty()) return;
  const Segment seg = segments_.back();
  segments_.pop_back();
  points_.resize(static_cast<std::size_t>(seg.begin));
  choices_.resize(static_cast<std::size_t>(seg.begin));
  while (!crossing_point_.empty() && crossing_point_.back() >= seg.begin) {
    crossing_point_.pop_back();
    crossings_.pop_back();
  }
  if (seg.opened_component) --comps_;
  else comp_closed_[static_cast<std::size_t>(seg.component)] = 0;
  if (comps_ > 0) comp_begin_[static_cast<std::size_t>(comps_)] = static_cast<int>(points_.size());
  if (drawing_) wait_release_ = true;
  drawing_ = false;
  blocked_ = false;
  if (comps_ > 0) {  // what is left of the component's length, for closing it later
    const int b = comp_begin_[static_cast<std::size_t>(comps_ - 1)];
    drawn_ = 0;
    for (int i = b + 1; i < static_cast<int>(points_.size()); ++i)
      drawn_ += (points_[static_cast<std::size_t>(i)] - points_[static_cast<std::size_t>(i) - 1]).norm();
    left_start_ = true;
  }
  ++revision_;
}

// Every strand the head must not cross, as segments (a, b): the strokes, less the part of the
// one being drawn that trails its head (and its start, which the head comes back to close it),
// and the scene's other curves.
template <typename F>
void CurveSketch::for_each_obstacle(F&& f) const {
  const int tail = static_cast<int>(std::ceil(s_.own_tail / s_.spacing));
  const int lead = static_cast<int>(std::ceil(2 * s_.close_radius / s_.spacing));
  for (int c = 0; c < comps_; ++c) {
    const int b = comp_begin_[static_cast<std::size_t>(c)], e = comp_begin_[static_cast<std::size_t>(c) + 1];
    const bool current = drawing_ && c == comps_ - 1;
    const int last = current ? e - 1 - tail : e - 1;  // segments i -> i+1 for i < last
    const int from = current && left_start_ ? b + lead : b;
    for (int i = from; i < last; ++i) f(points_[static_cast<std::size_t>(i)], points_[static_cast<std::size_t>(i) + 1]);
    if (!current && e - b >= 3) f(points_[static_cast<std::size_t>(e) - 1], points_[static_cast<std::size_t>(b)]);
  }
  if (!obstacles_) return;
  for (const FixedStrand& st : obstacles_->strands) {
    const std::size_t m = st.points.size();
    if (m < 2) continue;
    for (std::size_t k = 0; k + 1 < m; ++k) f(st.points[k], st.points[k + 1]);
    if (st.closed) f(st.points[m - 1], st.points[0]);
  }
}

namespace {

// Parameter s in (0, 1] along p0->p1 where it crosses segment q0q1 (closed at q's ends), or -1.
double crossing_along(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const Vec2 r = p1 - p0, d = q1 - q0, w = q0 - p0;
  const double den = r.x() * d.y() - r.y() * d.x();
  if (den == 0) return -1;
  const double s = (w.x() * d.y() - w.y() * d.x()) / den;
  const double t = (w.x() * r.y() - w.y() * r.x()) / den;
  return s > 0 && s <= 1 && t >= 0 && t <= 1 ? s : -1;
}

Vec2 closest_on_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

}  // namespace

// [SECTION] the head
// The head follows the probe; a move that would cross a strand goes through only with a choice
// (recorded where it crossed). Without one the head stops `margin` before the strand and slides
// along it towards the probe, so the stroke hugs the strand instead of sticking to it.
Vec2 CurveSketch::move_head(const Vec2& from, const Vec2& to, CrossChoice choice) {
  const Vec2 d = to - from;
  const double len = d.norm();
  if (!(len > 0)) return to;
  // The move is tested `margin` further than it goes, so the head never comes nearer a strand.
  const double reach = len + s_.margin;
  const Vec2 ahead = from + (reach / len) * d;
  double first = 2;
  Vec2 qa = Vec2::Zero(), qb = Vec2::Zero();
  for_each_obstacle([&](const Vec2& a, const Vec2& b) {
    const double s = crossing_along(from, ahead, a, b);
    if (s >= 0 && s < first) {
      first = s;
      qa = a;
      qb = b;
    }
  });
  const double at = first * reach;  // m along the move to the strand
  if (first > 1 || (choice != CrossChoice::kNone && at > len * (1 + 1e-9) + 1e-12)) {  // not reached yet
    blocked_ = false;
    return to;
  }
  if (choice != CrossChoice::kNone) {
    if (static_cast<int>(crossings_.size()) < SketchPublished::kMaxCrossings) {
      crossings_.push_back({from + (at / len) * d, choice});
      crossing_point_.push_back(static_cast<int>(points_.size()));
      ++revision_;
    }
    blocked_ = false;
    return to;
  }
  if (!blocked_) ++status_.crossings_refused;
  blocked_ = true;
  const Vec2 stop = from + std::max(0.0, at - s_.margin) / len * d;
  const Vec2 u = (qb - qa).normalized();
  if (!u.allFinite()) return stop;
  Vec2 slide = stop + (to - stop).dot(u) * u;
  const Vec2 e = slide - stop;
  const double elen = e.norm();
  if (!(elen > 0)) return stop;
  const double ereach = elen + s_.margin;
  const Vec2 eahead = stop + (ereach / elen) * e;
  double again = 2;
  for_each_obstacle([&](const Vec2& a, const Vec2& b) {
    const double s = crossing_along(stop, eahead, a, b);
    if (s >= 0 && s < again) again = s;
  });
  if (again <= 1) slide = stop + std::max(0.0, std::min(again * ereach - s_.margin, elen)) / elen * e;
  return slide;
}

// [SECTION] forces
ToolOutput CurveSketch::step(const DeviceState& device, double dt) {
  if (SketchStrands* o = obstacles_in_.take()) {
    if (obstacles_) obstacles_in_.retire(obstacles_);
    obstacles_ = o;
  }
  ToolOutput out;
  const Vec3 c = device.position;
  const Vec3 v = device.velocity.allFinite() ? device.velocity : Vec3::Zero();
  const Vec3 on_plane(c.x(), c.y(), plane_z_);
  out.anchor = on_plane;
  out.engaged = true;
  out.force = sticky_force<3>(c, on_plane, s_.sticky_h, s_.sticky_beta) +
              damping_force<3>(radial_velocity<3>(v, Vec3::UnitZ()), s_.sticky_kd);
  const Vec2 p = c.head<2>();
  if (!p.allFinite()) {
    out.force.setZero();
    return out;
  }

  const std::uint32_t b = device.buttons;
  const bool draw = b & kSketchDraw;
  const CrossChoice choice = (b & kSketchUnder) ? CrossChoice::kUnder : (b & kSketchOver) ? CrossChoice::kOver : CrossChoice::kNone;
  if ((b & kSketchFinish) && !(buttons_ & kSketchFinish)) ++status_.finish_requests;
  if (!draw) wait_release_ = false;
  if (draw && !drawing_ && !wait_release_ && !(buttons_ & kSketchDraw)) begin_segment(p);
  if (!draw && drawing_) end_segment();
  buttons_ = b;

  if (drawing_) {
    head_ = move_head(head_, p, choice);
    if (blocked_) ++status_.blocked_ticks;
    pen_.step(head_, dt);
    resample_to_pen(choice);  // resampled as it is drawn
  }

  // Eq. 3 from the nearest strand, and the wall back to a held head.
  status_.near = false;
  status_.repulsion = status_.wall = 0;
  if (drawing_) {
    double best = std::numeric_limits<double>::infinity();
    Vec2 q = p;
    for_each_obstacle([&](const Vec2& a, const Vec2& bb) {
      const Vec2 x = closest_on_segment(p, a, bb);
      const double d2 = (x - p).squaredNorm();
      if (d2 < best) {
        best = d2;
        q = x;
      }
    });
    const double s = std::sqrt(best);
    if (s < s_.repulsion.range) {
      status_.near = true;
      status_.nearest = q;
      status_.distance = s;
      const Vec2 to = s > 0 ? Vec2((q - p) / s) : Vec2::Zero();
      const Vec2 fr = repulsion_force<2>(s, to, Vec2(v.head<2>()), s_.repulsion);
      out.force.head<2>() += fr;
      status_.repulsion = fr.norm();
    }
    Vec2 fw = s_.wall_k * (head_ - p);
    const double w = fw.norm();
    if (w > s_.wall_max) fw *= s_.wall_max / w;
    if (std::isfinite(w)) {
      out.force.head<2>() += fw;
      status_.wall = fw.norm();
    }
    out.anchor = Vec3(head_.x(), head_.y(), plane_z_);
    status_.max_repulsion = std::max(status_.max_repulsion, status_.repulsion);
    if (status_.near && status_.repulsion + status_.wall > 0.05)
      status_.max_lag_near = std::max(status_.max_lag_near, (device.target - device.position).head<2>().norm());
  }
  if (!out.force.allFinite()) out.force.setZero();  // (the safety layer would reject it too)
  status_.probe = c;
  status_.target = device.target;
  status_.head = head_;
  status_.pen = pen_.position();
  publish(++ticks_ % 4 == 0);
  return out;
}

// [SECTION] publishing
// The strokes are copied into a slot only when that slot holds an older revision, within the
// capacity every slot reserved (no allocation).
void CurveSketch::publish(bool always) {
  if (!always && revision_ == published_revision_) return;
  SketchPublished& dst = published_.back();
  if (dst.revision != revision_ || dst.point_count != static_cast<int>(points_.size())) {
    dst.points.assign(points_.begin(), points_.end());
    dst.choices.assign(choices_.begin(), choices_.end());
    dst.component_begin.assign(comp_begin_.begin(), comp_begin_.begin() + comps_ + 1);
    dst.closed.assign(comp_closed_.begin(), comp_closed_.begin() + comps_);
    dst.crossings.assign(crossings_.begin(), crossings_.end());
    dst.revision = revision_;
  }
  dst.status = status_;
  dst.active = active_;
  dst.drawing = drawing_;
  dst.blocked = blocked_;
  dst.plane_z = plane_z_;
  dst.point_count = static_cast<int>(points_.size());
  dst.component_count = comps_;
  dst.crossing_count = static_cast<int>(crossings_.size());
  published_.publish();
  published_revision_ = revision_;
}

// [SECTION] scene
CurveSketchScene::CurveSketchScene(const SketchSettings& settings) : sketch_(settings) {
  const SketchSettings& s = sketch_.settings();
  params_[kH] = {"H", s.sticky_h, 0, 5000, "N/m^(1+beta)"};
  params_[kBeta] = {"beta", s.sticky_beta, 0, 1, ""};
  params_[kKd] = {"Kd", s.sticky_kd, 0, 10, "N s/m"};
  params_[kRepulsionH] = {"repulsion H", s.repulsion.h, 0, 1e-4, "N m^(1+beta_r)"};
  params_[kRepulsionBeta] = {"repulsion beta", s.repulsion.beta, 0, 2, ""};
  params_[kRange] = {"repulsion range", s.repulsion.range, 1e-3, 0.05, "m"};
  params_[kWallK] = {"wall K", s.wall_k, 0, 1000, "N/m"};
  sketch_.begin(0);
}

void CurveSketchScene::command(const SceneCommand& c) {
  const live::Request* r = live::request(c);
  if (!r) return;
  if (const auto* b = std::get_if<live::SketchBegin>(r)) sketch_.begin(b->plane_z);
  else if (std::holds_alternative<live::SketchEnd>(*r)) sketch_.end();
  else if (std::holds_alternative<live::SketchBackspace>(*r)) sketch_.backspace();
  else if (std::holds_alternative<live::SketchClear>(*r)) sketch_.clear();
}

ToolOutput CurveSketchScene::step(const DeviceState& device, double dt) {
  SketchSettings& s = sketch_.settings();
  s.sticky_h = params_[kH].value;
  s.sticky_beta = params_[kBeta].value;
  s.sticky_kd = params_[kKd].value;
  s.repulsion.h = params_[kRepulsionH].value;
  s.repulsion.beta = params_[kRepulsionBeta].value;
  s.repulsion.range = params_[kRange].value;
  s.wall_k = params_[kWallK].value;
  if (!sketch_.active()) return {};
  return sketch_.step(device, dt);
}

}  // namespace s4d
