// The six verdicts of the paper's scenarios (untied, knotted, slides-off, lifted, deforms,
// shadow-clean), each a measurement and a threshold from the scenario file.
#include "scenario/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"

namespace s4d {

namespace {

std::string fmt(double x, int prec = 3) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", prec, x);
  return b;
}

Vec3 head3(const std::vector<double>& v, const Vec3& fallback) {
  if (v.empty()) return fallback;
  Vec3 r = Vec3::Zero();
  for (std::size_t k = 0; k < 3 && k < v.size(); ++k) r[static_cast<int>(k)] = v[k];
  return r;
}

}  // namespace

VerdictJudge::VerdictJudge(const Scenario& sc, std::vector<int> first, std::vector<int> count,
                           std::vector<Vec4> initial, std::vector<std::uint8_t> tool)
    : verdict_(sc.verdict), initial_(std::move(initial)), tool_(std::move(tool)) {
  const int o = sc.object_index(verdict_.object);
  if (o < 0 || first[static_cast<std::size_t>(o)] < 0)
    throw Error("the verdict looks at '" + verdict_.object + "', which is no surface of the scene");
  object_ = sc.scene.objects[static_cast<std::size_t>(o)].shape;
  v0_ = first[static_cast<std::size_t>(o)];
  v1_ = v0_ + count[static_cast<std::size_t>(o)];
  reference_ = initial_;
  reference_time_ = number("reference_time", 0);
  const bool knot = verdict_.kind == "untied" || verdict_.kind == "knotted";
  const bool grid = std::visit([](const auto& s) {
    using T = std::decay_t<decltype(s)>;
    if constexpr (std::is_same_v<T, Surface<T::kDim>>) return s.grid.has_value();
    return false;
  }, object_);
  if (knot && !grid) throw Error(verdict_.object + ": a knot verdict needs a grid ribbon");
  if (verdict_.kind == "shadow-clean") initial_shadow_ = check_shadow(object_surface(initial_), verdict_.view);
}

double VerdictJudge::number(const std::string& key, double fallback) const {
  const auto it = verdict_.numbers.find(key);
  return it == verdict_.numbers.end() ? fallback : it->second;
}

Surface<4> VerdictJudge::object_surface(std::span<const Vec4> x) const {
  Surface<4> s;
  std::visit([&](const auto& o) {
    using T = std::decay_t<decltype(o)>;
    if constexpr (std::is_same_v<T, Surface<T::kDim>>) {
      s.triangles = o.triangles;
      s.grid = o.grid;
    }
  }, object_);
  s.vertices.assign(x.begin() + v0_, x.begin() + v1_);
  return s;
}

void VerdictJudge::observe(double t0, double t1, std::span<const Vec4> x) {
  if (reference_time_ > 0 && t0 < reference_time_ && t1 >= reference_time_) reference_.assign(x.begin(), x.end());
}

double VerdictProgress::fraction() const {
  const double span = goal - start;
  if (!std::isfinite(span) || !std::isfinite(now)) return 0;
  if (std::abs(span) < 1e-12) return (rising ? now >= goal : now <= goal) ? 1 : 0;
  return std::clamp((now - start) / span, 0.0, 1.0);
}

VerdictResult VerdictJudge::judge(std::span<const Vec4> x) const {
  VerdictResult r;
  auto& verdict = r.numbers;
  verdict["kind"] = verdict_.kind;
  bool ok = true;
  std::string detail;
  const std::string& kind = verdict_.kind;
  if (kind == "untied" || kind == "knotted") {
    const Surface<4> now = object_surface(x), start = object_surface(initial_);
    const Grid& g = *now.grid;
    auto centre4 = [&](const std::vector<Vec4>& p) {
      std::vector<Vec4> c;
      for (int i = 0; i < g.rows; ++i) {
        Vec4 s = Vec4::Zero();
        for (int j = 0; j < g.cols; ++j) s += p[static_cast<std::size_t>(g.index(i, j))];
        c.push_back(s / g.cols);
      }
      return c;
    };
    const std::vector<Vec4> c0 = centre4(start.vertices), c1 = centre4(now.vertices);
    double length = 0;
    for (std::size_t i = 1; i < c0.size(); ++i) length += (c0[i] - c0[i - 1]).norm();
    const double ends = (c1.back() - c1.front()).norm() / length;
    const Vec3 via = head3(verdict_.close_via, Vec3(0, 0, -1));
    const Vec3 along = (c1.back() - c1.front()).head<3>();
    const KnotCheck k0 = check_knot(ribbon_centre_line(start.vertices, g), via, along);
    const KnotCheck k1 = check_knot(ribbon_centre_line(now.vertices, g), via, along);
    verdict["end_distance_over_length"] = ends;
    verdict["initial"] = {{"min_crossings", k0.min_crossings}, {"determinant", k0.determinant}};
    verdict["final"] = {{"min_crossings", k1.min_crossings}, {"max_crossings", k1.max_crossings},
                        {"open_crossings", k1.open_crossings}, {"determinant", k1.determinant},
                        {"simplified_crossings", k1.simplified_crossings}, {"knot_error", k1.error}};
    if (kind == "untied") {
      const double need = number("end_fraction", 0.9);
      ok = ends >= need && k1.open_crossings <= number("max_open_crossings", 0) && k1.error.empty() &&
           k1.determinant == 1 && k1.simplified_crossings == 0;
      const double ends0 = (c0.back() - c0.front()).norm() / length;
      r.progress = VerdictProgress{"ends apart, of the length", ends0, ends, need, true};
      detail = "ends " + fmt(ends) + " of the length apart (need >= " + fmt(need) + "), shadow centre line " +
               std::to_string(k1.open_crossings) + " crossings in the worst transverse view, closed: " +
               (k1.simplified_crossings == 0 ? "unknot" : "det " + std::to_string(k1.determinant));
    } else {
      const int need = static_cast<int>(number("min_crossings", 3));
      r.progress = VerdictProgress{"crossings in every view", static_cast<double>(k0.min_crossings),
                                   static_cast<double>(k1.min_crossings), static_cast<double>(need), true};
      ok = k1.min_crossings >= need && k1.error.empty() && k0.error.empty() && k1.determinant == k0.determinant &&
           k1.fingerprint == k0.fingerprint && k0.determinant == 3;
      detail = "closed centre line has >= " + std::to_string(k1.min_crossings) + " crossings in every view (need " +
               std::to_string(need) + "), det " + std::to_string(k1.determinant) + " (start " +
               std::to_string(k0.determinant) + "), knot type " +
               (k1.fingerprint == k0.fingerprint ? "unchanged" : "CHANGED") + ", ends " + fmt(ends) + " of length";
    }
  } else if (kind == "slides-off") {
    const int axis = static_cast<int>(number("axis", 1));
    double top = -1e300, support = 1e300;
    for (int v = 0; v < static_cast<int>(x.size()); ++v) {
      if (v >= v0_ && v < v1_) top = std::max(top, x[v][axis]);
      else support = std::min(support, x[v][axis]);
    }
    verdict["object_top"] = top;
    verdict["support_bottom"] = support;
    ok = top < support - number("margin", 0);
    r.progress = VerdictProgress{"the cloth's top below the support by", std::nan(""), support - top, number("margin", 0), true};
    detail = verdict_.object + " top at " + fmt(top) + ", below the support's lowest point " + fmt(support) +
             (ok ? " (slid off)" : " (still held)");
  } else if (kind == "lifted") {
    const int axis = static_cast<int>(number("axis", 1));
    int nc = 0;
    const Surface<4> s = object_surface(x);
    const std::vector<int> comp = vertex_components(v1_ - v0_, s.triangles, &nc);
    std::vector<double> rise(static_cast<std::size_t>(nc), 0.0), cnt(static_cast<std::size_t>(nc), 0.0);
    for (int v = v0_; v < v1_; ++v) {
      rise[static_cast<std::size_t>(comp[v - v0_])] += x[v][axis] - reference_[v][axis];
      cnt[static_cast<std::size_t>(comp[v - v0_])] += 1;
    }
    double worst = 1e300;
    for (int c = 0; c < nc; ++c) worst = std::min(worst, rise[c] / cnt[c]);
    verdict["components"] = nc;
    verdict["min_rise"] = worst;
    verdict["rise_per_component"] = nlohmann::ordered_json::array();
    for (int c = 0; c < nc; ++c) verdict["rise_per_component"].push_back(rise[c] / cnt[c]);
    verdict["reference_time"] = reference_time_;
    const double need = number("min_rise", 0);
    ok = worst >= need;
    r.progress = VerdictProgress{"the lowest part's rise", 0, worst, need, true};
    detail = std::to_string(nc) + " components, the lowest rose " + fmt(worst) + " (need >= " + fmt(need) + ")" +
             (reference_time_ > 0 ? " since t = " + fmt(reference_time_) + " s" : "");
  } else if (kind == "shadow-clean") {
    // The shadow's self-intersection curves at the start (they must exist, or the scenario proves
    // nothing) and now (their total length must have gone to max_final_length, 0 = none).
    const ShadowCheck& s0 = initial_shadow_;
    const ShadowCheck s1 = check_shadow(object_surface(x), verdict_.view);
    verdict["view"] = verdict_.view;
    verdict["initial_length"] = s0.total_length;
    verdict["initial_curves"] = s0.curves;
    verdict["final_length"] = s1.total_length;
    verdict["final_curves"] = s1.curves;
    verdict["final_true_curves"] = s1.true_curves;
    verdict["final_coplanar_pairs"] = s1.coplanar_pairs;
    const double need0 = number("min_initial_length", 0), max1 = number("max_final_length", 0);
    r.progress = VerdictProgress{"shadow curves", s0.total_length, s1.total_length, max1, false};
    ok = s0.total_length >= need0 && s0.total_length > 0 && s1.total_length <= max1 && s1.true_curves == 0 &&
         s1.coplanar_pairs == 0;
    detail = "shadow self-intersection length " + fmt(s0.total_length) + " in " + std::to_string(s0.curves) +
             " curves at the start (need >= " + fmt(need0) + "), " + fmt(s1.total_length) + " in " +
             std::to_string(s1.curves) + " curves at the end (need <= " + fmt(max1) + ")" +
             (s1.coplanar_pairs > 0 ? ", " + std::to_string(s1.coplanar_pairs) + " coplanar pairs (view not generic)"
                                    : "");
  } else {  // deforms: how far the body moved, not the vertices the tool carried
    double moved = 0;
    for (int v = v0_; v < v1_; ++v)
      if (!tool_[static_cast<std::size_t>(v)]) moved = std::max(moved, (x[v] - initial_[v]).norm());
    verdict["max_displacement"] = moved;
    const double need = number("min_displacement", 0);
    ok = moved >= need;
    r.progress = VerdictProgress{"the body moved by", 0, moved, need, true};
    detail = "largest displacement of a vertex the tool does not hold " + fmt(moved) + " (need >= " + fmt(need) + ")";
  }
  r.pass = ok;
  r.detail = detail;
  return r;
}

}  // namespace s4d
