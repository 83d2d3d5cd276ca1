// The centre line of a ribbon sketch (see ribbon_centre_line.hpp).
//
// Sections: [SECTION] rows and their directions, [SECTION] folds, [SECTION] smoothing.
//
// Why Laplacian smoothing of a finely resampled copy: a corner turning by phi, blurred over an arc
// length sigma, bends no tighter than a radius of about sigma sqrt(2 pi) / phi and moves by about
// 2 sigma sin(phi / 2) / sqrt(2 pi); a right angle under a ribbon w wide lies flat once sigma is
// about 0.3 w, having moved 0.18 w; a hairpin narrower than the ribbon never does (it shortens
// until the bound on what it leaves behind stops it). Smoothing the
// rows themselves and resampling them each round would blur the whole line a little each time;
// the fine copy is smoothed only near the folds and the rows are taken from it afresh.
#include "interact/tools/ribbon_centre_line.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <tuple>
#include <utility>

#include "core/error.hpp"
#include "proximity/self_intersections.hpp"
#include "shape/ribbons.hpp"

namespace s4d {

namespace {

constexpr int kMaxRounds = 40;
constexpr double kMargin = 1.25;     // smoothed until a ribbon this many times as wide lies flat
constexpr double kRate = 0.5;        // of each Laplacian pass
constexpr double kRoundBlur = 0.02;  // variance each round adds to the blur, in widths squared
constexpr int kMaxFinePoints = 200000;

// [SECTION] rows and their directions

double polyline_length(const std::vector<PenPoint<3>>& p, bool closed) {
  double length = 0;
  for (std::size_t i = 1; i < p.size(); ++i) length += (p[i].at - p[i - 1].at).norm();
  if (closed) length += (p.back().at - p.front().at).norm();
  return length;
}

CentreLine rows_along(const std::vector<PenPoint<3>>& path, bool closed, double spacing, int min_segments,
                      const Vec3& eye) {
  CentreLine c;
  c.closed = closed;
  c.rows = resample_pen_path<3>(path, spacing, closed, min_segments);
  // A closed line's closing stretch is the pen's last move: it keeps the stroke's last time.
  for (std::size_t i = 1; i < c.rows.size(); ++i) c.rows[i].time = std::max(c.rows[i].time, c.rows[i - 1].time);
  c.length = polyline_length(path, closed);
  const int segments = static_cast<int>(c.rows.size()) - (closed ? 0 : 1);
  c.spacing = c.length / segments;
  c.across = across_directions(c.rows, closed, eye);
  return c;
}

}  // namespace

std::vector<Vec3> across_directions(const std::vector<PenPoint<3>>& rows, bool closed, const Vec3& eye) {
  const int n = static_cast<int>(rows.size());
  std::vector<Vec3> out(n, Vec3::Zero());
  std::vector<char> good(n, 0);
  for (int i = 0; i < n; ++i) {
    const int ip = i > 0 ? i - 1 : closed ? n - 1 : i;
    const int in = i + 1 < n ? i + 1 : closed ? 0 : i;
    const Vec3 t = (rows[in].at - rows[ip].at).normalized();
    const Vec3 c = eye.cross(t);
    if (c.norm() > 1e-3) {
      out[i] = c.normalized();
      good[i] = 1;
    } else {
      out[i] = t;  // replaced below
    }
  }
  int first = -1;
  for (int i = 0; i < n && first < 0; ++i)
    if (good[i]) first = i;
  if (first < 0)
    throw Error("the stroke runs along the line of sight everywhere: the ribbon's width has no direction; "
                "draw across the view");
  for (int k = 1; k < n; ++k) {
    const int i = (first + k) % n, prev = (i + n - 1) % n;
    if (good[i] || (!closed && i < first)) continue;
    const Vec3 t = out[i];
    out[i] = (out[prev] - out[prev].dot(t) * t).normalized();
  }
  for (int i = first - 1; i >= 0 && !closed; --i)
    if (!good[i]) {
      const Vec3 t = out[i];
      out[i] = (out[i + 1] - out[i + 1].dot(t) * t).normalized();
    }
  return out;
}

// [SECTION] folds

std::vector<RibbonFold> ribbon_folds(const CentreLine& line, double width) {
  std::vector<Vec3> centre;
  for (const PenPoint<3>& p : line.rows) centre.push_back(p.at);
  const Surface<3> flat = ribbon_along(centre, line.closed, line.across, width, 2);
  const int n = static_cast<int>(centre.size());
  auto cell_row = [&](const Triangle& t) {
    int lo = n, hi = -1;
    for (int v : t) {
      lo = std::min(lo, v / 2);
      hi = std::max(hi, v / 2);
    }
    return line.closed && lo == 0 && hi == n - 1 ? n - 1 : lo;
  };
  // A fold pairs cells less than a width apart along the line: only those pairs are looked at
  // (the ribbon passing itself further along is not a fold), a few per cell, where a search of
  // the whole ribbon would cost a broad phase over every cell each time the line is smoothed.
  const int cells = n - (line.closed ? 0 : 1), nt = static_cast<int>(flat.triangles.size());
  std::vector<int> row_of(nt), first(cells + 1, 0), in_row(nt);  // the triangles of each cell row
  for (int t = 0; t < nt; ++t) ++first[(row_of[t] = cell_row(flat.triangles[t])) + 1];
  for (int r = 0; r < cells; ++r) first[r + 1] += first[r];
  std::vector<int> fill(first.begin(), first.end() - 1);
  for (int t = 0; t < nt; ++t) in_row[fill[row_of[t]]++] = t;
  std::vector<std::array<int, 2>> candidates;
  for (int a = 0; a < cells; ++a)
    for (int i = first[a]; i < first[a + 1]; ++i)
      for (int d = 0; d < cells && d * line.spacing < width && (line.closed || a + d < cells); ++d) {
        const int b = (a + d) % cells;
        for (int j = d == 0 ? i + 1 : first[b]; j < first[b + 1]; ++j)
          candidates.push_back({in_row[i], in_row[j]});
      }
  std::set<std::pair<int, int>> found;
  for (const ProximityPair<3>& p : self_intersections_among<3>(flat, candidates).pairs) {
    int a = cell_row(flat.triangles[p.a]), b = cell_row(flat.triangles[p.b]);
    if (a > b) std::swap(a, b);
    const int d = line.closed ? std::min(b - a, n - (b - a)) : b - a;
    if (d * line.spacing < width) found.insert({a, b});
  }
  std::vector<RibbonFold> out;
  for (const auto& [a, b] : found) out.push_back({a, b});
  return out;
}

namespace {

// The stretch of a fold along the line, in arc length from row 0: [from, to], `to` past the
// length when it goes round a closed line's join.
std::pair<double, double> fold_stretch(const CentreLine& line, const RibbonFold& f) {
  const int n = static_cast<int>(line.rows.size());
  if (line.closed && 2 * (f.b - f.a) > n) return {f.b * line.spacing, (f.a + 1 + n) * line.spacing};
  return {f.a * line.spacing, (f.b + 1) * line.spacing};
}

// Distance along the line from arc length s to a stretch (round the loop when closed).
double to_stretch(double s, std::pair<double, double> stretch, double length, bool closed) {
  double best = std::max({0.0, stretch.first - s, s - stretch.second});
  if (closed)
    for (double t : {s - length, s + length}) best = std::min(best, std::max({0.0, stretch.first - t, t - stretch.second}));
  return best;
}

// Places where the ribbon folds: runs of rows within half a width of a fold.
int count_turns(const CentreLine& line, const std::vector<RibbonFold>& folds, double width) {
  const int n = static_cast<int>(line.rows.size());
  std::vector<char> near(n, 0);
  for (const RibbonFold& f : folds) {
    const auto stretch = fold_stretch(line, f);
    for (int r = 0; r < n; ++r)
      if (to_stretch(r * line.spacing, stretch, line.length, line.closed) <= 0.5 * width) near[r] = 1;
  }
  int runs = 0;
  for (int r = 0; r < n; ++r)
    if (near[r] && !near[r > 0 ? r - 1 : line.closed ? n - 1 : r]) ++runs;
  if (runs == 0 && !folds.empty()) runs = 1;  // every row of a closed line near a fold
  if (!line.closed && n > 0 && near[0]) ++runs;
  return runs;
}

// [SECTION] smoothing

struct Smoother {
  std::vector<PenPoint<3>> drawn, line;  // evenly resampled copies: as drawn, as smoothed so far
  std::vector<double> weight;            // how much each point is smoothed (0: left as drawn)
  std::vector<int> moving;               // the points smoothed, in order (a few near the folds)
  bool closed = false;
  double step = 0;                       // between the drawn copy's points

  int count() const { return static_cast<int>(line.size()); }
  bool movable(int i) const { return closed || (i > 0 && i + 1 < count()); }

  // Weights 1 within 1.5 widths of each fold along the line, falling to 0 a width further on.
  void mark(const CentreLine& rows, const std::vector<RibbonFold>& folds, double width) {
    std::vector<double> at(line.size(), 0.0);  // arc length along the smoothed copy
    for (int i = 1; i < count(); ++i) at[i] = at[i - 1] + (line[i].at - line[i - 1].at).norm();
    const double length = polyline_length(line, closed);
    for (const RibbonFold& f : folds) {
      const auto stretch = fold_stretch(rows, f);
      // Only points within 2.5 widths of the stretch gain weight: those (closed: round the loop
      // either way) lie among the points 3 widths or less from it, found by bisection.
      for (int turn = closed ? -1 : 0; turn <= (closed ? 1 : 0); ++turn) {
        const double shift = turn * length;
        const auto lo = std::lower_bound(at.begin(), at.end(), stretch.first + shift - 3 * width);
        const auto hi = std::upper_bound(lo, at.end(), stretch.second + shift + 3 * width);
        for (auto it = lo; it != hi; ++it) {
          const int i = static_cast<int>(it - at.begin());
          const double d = to_stretch(at[i], stretch, length, closed);
          weight[i] = std::max(weight[i], std::clamp(2.5 - d / width, 0.0, 1.0));
        }
      }
    }
    moving.clear();
    for (int i = 0; i < count(); ++i)
      if (weight[i] > 0 && movable(i)) moving.push_back(i);
  }

  std::vector<PenPoint<3>> smoothed(int passes) const {
    std::vector<PenPoint<3>> cur = line;
    std::vector<Vec3> next(moving.size());  // each pass reads the last one's points only
    const int n = count();
    for (int k = 0; k < passes; ++k) {
      for (std::size_t m = 0; m < moving.size(); ++m) {
        const int i = moving[m];
        const Vec3& a = cur[(i + n - 1) % n].at;
        const Vec3& b = cur[(i + 1) % n].at;
        next[m] = cur[i].at + kRate * weight[i] * (0.5 * (a + b) - cur[i].at);
      }
      for (std::size_t m = 0; m < moving.size(); ++m) cur[moving[m]].at = next[m];
    }
    return cur;
  }

  // How far `candidate` lies from the drawn line, both ways: the farthest a moved point lies from
  // its own stretch of the drawn line (first), and the farthest a drawn point lies from the
  // candidate's stretch there (second: a line that slides back along itself, shortening a
  // hairpin, leaves the hairpin's end far from it).
  std::pair<double, double> farthest(const std::vector<PenPoint<3>>& candidate, double max_move) const {
    const int n = count(), reach = static_cast<int>(std::ceil(4 * max_move / step)) + 2;
    const int segments = closed ? n : n - 1;
    auto to_stretch_of = [&](const std::vector<PenPoint<3>>& line, int i, const Vec3& p) {
      double best = (p - line[i].at).norm();
      for (int k = i - reach; k <= i + reach; ++k) {
        if (!closed && (k < 0 || k >= segments)) continue;
        const int s = ((k % n) + n) % n;
        const Vec3& a = line[s].at;
        const Vec3 d = line[(s + 1) % n].at - a;
        const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
        best = std::min(best, (a + t * d - p).norm());
      }
      return best;
    };
    std::pair<double, double> worst{0, 0};
    for (int i = 0; i < n; ++i) {
      if (weight[i] <= 0) continue;
      worst.first = std::max(worst.first, to_stretch_of(drawn, i, candidate[i].at));
      worst.second = std::max(worst.second, to_stretch_of(candidate, i, drawn[i].at));
    }
    return worst;
  }
};

}  // namespace

CentreLineResult ribbon_centre_line(const std::vector<PenPoint<3>>& path, bool closed, double spacing,
                                    int min_segments, double width, const Vec3& eye, double max_move,
                                    long long max_work) {
  CentreLineResult out;
  auto folds_of = [&](const CentreLine& line, double w) {
    out.work += static_cast<long long>(line.rows.size());
    return ribbon_folds(line, w);
  };
  // Whether the budget has room for an attempt: its two fold tests of about as many rows.
  auto affordable = [&] {
    out.cut_short = out.cut_short || out.work + 2 * static_cast<long long>(out.line.rows.size()) > max_work;
    return !out.cut_short;
  };
  out.line = rows_along(path, closed, spacing, min_segments, eye);
  out.folds = folds_of(out.line, width);
  out.smoothing.limit = std::max(max_move, 0.0);
  for (const RibbonFold& f : out.folds)
    out.places.push_back({out.line.rows[f.a].at, f.a * out.line.spacing / out.line.length});
  if (out.folds.empty() || !(max_move > 0)) return out;
  out.smoothing.turns = count_turns(out.line, out.folds, width);
  const CentreLine as_drawn = out.line;
  const std::vector<RibbonFold> drawn_folds = out.folds;

  Smoother sm;
  sm.closed = closed;
  sm.step = std::clamp(spacing / 2, width / 40, width / 8);
  sm.step = std::max(sm.step, out.line.length / kMaxFinePoints);
  sm.drawn = resample_pen_path<3>(path, sm.step, closed, std::max(min_segments, closed ? 8 : 2));
  sm.line = sm.drawn;
  sm.weight.assign(sm.drawn.size(), 0.0);
  // Each round smooths twice as long as the last (a blur growing by about sqrt 2), or half as
  // long, down to the first round's, where that would move the line too far; the round that takes
  // the last fold out is made as short as does that.
  struct Attempt {
    std::vector<PenPoint<3>> line;
    CentreLine rows;
    std::vector<RibbonFold> folds, aim;  // at the width, and those with the margin's too
    double moved = 0, cut = 0;
    bool too_far = false;
  };
  auto attempt = [&](int passes) {
    Attempt a;
    a.line = sm.smoothed(passes);
    std::tie(a.moved, a.cut) = sm.farthest(a.line, max_move);
    a.too_far = a.moved > max_move || a.cut > 2 * max_move;
    if (a.too_far) return a;
    a.rows = rows_along(a.line, closed, spacing, min_segments, eye);
    a.folds = folds_of(a.rows, width);
    a.aim = folds_of(a.rows, kMargin * width);
    a.aim.insert(a.aim.end(), a.folds.begin(), a.folds.end());
    return a;
  };
  const int first = static_cast<int>(std::ceil(kRoundBlur * width * width / (kRate * sm.step * sm.step)));
  std::vector<RibbonFold> aim = folds_of(out.line, kMargin * width);
  aim.insert(aim.end(), out.folds.begin(), out.folds.end());
  for (int round = 1, passes = first;
       round <= kMaxRounds && passes >= first && !aim.empty() && affordable();) {
    sm.mark(out.line, aim, width);
    Attempt a = attempt(passes);
    if (a.too_far) {
      passes /= 2;
      continue;
    }
    for (int fewer = passes / 2; a.aim.empty() && fewer >= first && affordable(); fewer /= 2) {
      Attempt b = attempt(fewer);
      if (b.too_far || !b.aim.empty()) break;
      a = std::move(b);
    }
    sm.line = std::move(a.line);
    out.line = std::move(a.rows);
    out.folds = std::move(a.folds);
    aim = std::move(a.aim);
    out.smoothing.rounds = round++;
    out.smoothing.moved = a.moved;
    out.smoothing.cut = a.cut;
    passes *= 2;
  }
  // Where the folds left are on the line the user sees: the nearest fold of the line as drawn.
  out.places.clear();
  for (const RibbonFold& f : out.folds) {
    const Vec3 at = out.line.rows[f.a].at;
    FoldPlace best{as_drawn.rows[drawn_folds[0].a].at, 0};
    double best_d = std::numeric_limits<double>::infinity();
    for (const RibbonFold& g : drawn_folds)
      for (int r : {g.a, g.b})
        if ((as_drawn.rows[r].at - at).norm() < best_d) {
          best_d = (as_drawn.rows[r].at - at).norm();
          best = {as_drawn.rows[r].at, r * as_drawn.spacing / as_drawn.length};
        }
    out.places.push_back(best);
  }
  return out;
}

}  // namespace s4d
