// The walk along a strand of the image and the crossings passed on the way.
#include "interact/live/curve_explorer.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "proximity/shadow_crossings.hpp"

namespace s4d {

bool CurveImage::same_layout(const CurveImage& o) const {
  if (components.size() != o.components.size()) return false;
  for (std::size_t c = 0; c < components.size(); ++c)
    if (components[c].image.size() != o.components[c].image.size() || components[c].closed != o.components[c].closed)
      return false;
  return true;
}

std::unique_ptr<CurveImage> build_curve_image(const Curve<3>& curve, const Frame<3>& frame) {
  if (curve.components.empty()) throw Error("nothing to explore: the curve has no component");
  auto img = std::make_unique<CurveImage>();
  img->frame = frame;
  img->components.resize(curve.components.size());
  for (std::size_t c = 0; c < curve.components.size(); ++c) {
    const auto& comp = curve.components[c];
    if (comp.points.size() < 2) throw Error("a component of the curve has fewer than 2 points");
    CurveImage::Component& out = img->components[c];
    out.closed = comp.closed;
    for (const Vec3& p : comp.points) {
      const Vec3 q = frame.to_view(p);
      out.image.push_back(q.head<2>());
      out.depth.push_back(q.z());
    }
  }
  const ShadowCrossingResult<3> found = shadow_crossings<3>(curve, frame);
  for (std::size_t i = 0; i < found.crossings.size(); ++i) {
    const ShadowCrossing<3>& x = found.crossings[i];
    const int id = static_cast<int>(i);  // relabelled below
    img->components[static_cast<std::size_t>(x.a.component)].marks.push_back({x.a.segment, x.ta, id, x.a_over(), x.point});
    img->components[static_cast<std::size_t>(x.b.component)].marks.push_back({x.b.segment, x.tb, id, !x.a_over(), x.point});
  }
  // Number by first visit along the curve, as a Gauss code does.
  std::map<int, int> label;
  for (CurveImage::Component& comp : img->components) {
    std::sort(comp.marks.begin(), comp.marks.end(), [](const CurveImage::Mark& a, const CurveImage::Mark& b) {
      return a.segment != b.segment ? a.segment < b.segment : a.t < b.t;
    });
    for (CurveImage::Mark& m : comp.marks) {
      auto [it, fresh] = label.emplace(m.label, static_cast<int>(label.size()) + 1);
      m.label = it->second;
    }
  }
  img->crossings = static_cast<int>(found.crossings.size());
  return img;
}

CurveExplorer::CurveExplorer() { gauss_.reserve(kGaussCapacity); }

void CurveExplorer::swap_image(CurveImage& image) noexcept {
  const bool keep = probe_.valid() && image.same_layout(*image_);
  std::swap(*image_, image);
  if (!keep) probe_ = CurveProbe{};
}

Vec2 CurveExplorer::point(int comp, int seg, double t) const {
  const auto& p = image_->components[static_cast<std::size_t>(comp)].image;
  const std::size_t n = p.size();
  return (1 - t) * p[static_cast<std::size_t>(seg)] + t * p[(static_cast<std::size_t>(seg) + 1) % n];
}

bool CurveExplorer::place(const Vec2& at) noexcept {
  probe_ = CurveProbe{};
  gauss_.clear();
  armed_ = true;
  last_label_ = 0;
  if (image_->components.empty() || !at.allFinite()) return false;
  double best = HUGE_VAL;
  for (int c = 0; c < static_cast<int>(image_->components.size()); ++c)
    for (int s = 0; s < image_->components[static_cast<std::size_t>(c)].segments(); ++s) {
      const Vec2 a = point(c, s, 0), ab = point(c, s, 1) - a;
      const double len2 = ab.squaredNorm();
      const double t = len2 > 0 ? std::clamp((at - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
      const double d = (a + t * ab - at).squaredNorm();
      if (d < best) {
        best = d;
        probe_ = {c, s, t};
      }
    }
  return probe_.valid();
}

Vec2 CurveExplorer::probe_point() const {
  if (!probe_.valid()) return Vec2::Constant(NAN);
  return point(probe_.component, probe_.segment, probe_.t);
}

double CurveExplorer::probe_depth() const {
  if (!probe_.valid()) return NAN;
  const auto& d = image_->components[static_cast<std::size_t>(probe_.component)].depth;
  const std::size_t s = static_cast<std::size_t>(probe_.segment);
  return (1 - probe_.t) * d[s] + probe_.t * d[(s + 1) % d.size()];
}

// Crossings on (t0, t1] of one segment, in the order walked.
void CurveExplorer::passed(int comp, int seg, double t0, double t1, double time) noexcept {
  const auto& marks = image_->components[static_cast<std::size_t>(comp)].marks;
  const bool forward = t1 >= t0;
  const double lo = std::min(t0, t1), hi = std::max(t0, t1);
  const auto emit = [&](const CurveImage::Mark& m) {
    if (m.segment != seg || m.t <= lo || m.t > hi) return;
    if (!forward && m.t == hi) return;  // walking back, the start point was counted coming in
    if (m.label == last_label_ && !armed_) return;
    last_label_ = m.label;
    last_point_ = m.point;
    armed_ = false;
    CurveCrossingEvent e;
    e.time = time;
    e.label = m.label;
    e.over = m.over;
    e.point[0] = m.point.x();
    e.point[1] = m.point.y();
    events_.try_push(e);
    if (gauss_.size() < kGaussCapacity) gauss_.push_back(m.over ? m.label : -m.label);
  };
  if (forward)
    for (const auto& m : marks) emit(m);
  else
    for (auto it = marks.rbegin(); it != marks.rend(); ++it) emit(*it);
}

// Along the strand: project the target on the probe's segment; past an end, go on to the
// adjacent segment (the one the curve continues with), at most 256 segments a move.
Vec2 CurveExplorer::move_to(const Vec2& target, double time) noexcept {
  if (!probe_.valid() || !target.allFinite()) return probe_point();
  CurveProbe& p = probe_;
  const CurveImage::Component& comp = image_->components[static_cast<std::size_t>(p.component)];
  const int n = comp.segments();
  for (int step = 0; step < 256; ++step) {
    const Vec2 a = point(p.component, p.segment, 0), ab = point(p.component, p.segment, 1) - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? (target - a).dot(ab) / len2 : p.t;
    if (t > 1 && (comp.closed || p.segment + 1 < n)) {
      passed(p.component, p.segment, p.t, 1, time);
      p.segment = (p.segment + 1) % n;
      p.t = 0;
      continue;
    }
    if (t < 0 && (comp.closed || p.segment > 0)) {
      passed(p.component, p.segment, p.t, 0, time);
      p.segment = (p.segment - 1 + n) % n;
      p.t = 1;
      continue;
    }
    const double to = std::clamp(t, 0.0, 1.0);
    passed(p.component, p.segment, p.t, to, time);
    p.t = to;
    break;
  }
  const Vec2 at = probe_point();
  if (!armed_ && (at - last_point_).norm() > rearm_) armed_ = true;
  return at;
}

Vec2 CurveExplorer::update(const Vec2& c, const Vec2& v, double rate_hz, double time, const DampedSpring& spring) noexcept {
  if (!c.allFinite() || !v.allFinite() || !(rate_hz > 0) || !probe_.valid()) return Vec2::Zero();
  const Vec2 target = move_to(c + v / rate_hz, time);  // C_p on the probe's own strand
  const Vec2 d = target - c;
  const double len = d.norm();
  if (!(len > 0)) return Vec2::Zero();
  const Vec2 u = d / len;
  const Vec2 f = spring.k * d - spring.b * v.dot(u) * u;
  return f.allFinite() ? f : Vec2::Zero();
}

std::string CurveExplorer::gauss_text() const {
  std::string s;
  for (int g : gauss_) s += (s.empty() ? "" : ", ") + std::to_string(g);
  return s;
}

}  // namespace s4d
