// The ribbon sketch (see ribbon_sketch.hpp).
//
// [SECTION] rows: the resampled stroke, one w per row
// [SECTION] passages: where the ribbon's shadow meets another sheet's, as constraints on w
// [SECTION] ribbon_from_sketch
// [SECTION] scenes
// [SECTION] stroke files
#include "interact/tools/ribbon_sketch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "interact/tools/ribbon_centre_line.hpp"
#include "io/text_scanner.hpp"
#include "knots/depth_edit.hpp"
#include "proximity/mesh_proximity.hpp"
#include "proximity/self_intersections.hpp"
#include "proximity/shadow_intersections.hpp"
#include "shape/ribbons.hpp"

namespace s4d {

namespace {

constexpr int kMaxRows = 20000;
constexpr long long kMaxVertices = 200000;  // ten times the largest scenario's cloth; seconds to build
constexpr int kMaxSmoothingIterations = 20000;
constexpr double kRate = 0.5;  // Laplacian rate of the w smoothing

std::string fmt(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", x);
  return b;
}
std::string fmt(const Vec3& p) {
  char b[96];
  std::snprintf(b, sizeof b, "(%.4g, %.4g, %.4g)", p.x(), p.y(), p.z());
  return b;
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// [SECTION] rows: the resampled stroke, one w per row

struct Rows {
  std::vector<PenPoint<3>> at;  // the centre line, evenly spaced by arc length
  bool closed = false;
  double spacing = 0;           // arc length between consecutive rows

  int count() const { return static_cast<int>(at.size()); }
  int next(int r) const { return closed ? (r + 1) % count() : std::min(r + 1, count() - 1); }
  // Row parameter u: row floor(u), a fraction u - floor(u) of the way to the next one.
  Vec3 point(double u) const {
    const int r = std::clamp(static_cast<int>(std::floor(u)), 0, count() - 1);
    const double f = u - r;
    return (1 - f) * at[r].at + f * at[next(r)].at;
  }
  double time(double u) const {
    const int r = std::clamp(static_cast<int>(std::floor(u)), 0, count() - 1);
    const double f = u - r;
    return (1 - f) * at[r].time + f * at[next(r)].time;
  }
  // Arc length between two rows, the short way round when closed.
  double separation(double a, double b) const {
    const double d = std::abs(a - b);
    return spacing * (closed ? std::min(d, count() - d) : d);
  }
  // Rows a and b are neighbours or the same (round the loop when closed).
  bool near(int a, int b) const {
    const int d = std::abs(a - b);
    return d <= 1 || (closed && d == count() - 1);
  }
};

// Where a point of the ribbon's shadow lies on its grid: cell row `row`, a fraction f of the way
// to the next row, across at v in [0, 1].
struct GridPoint {
  int row = 0;
  double f = 0;
  double v = 0;
  double u() const { return row + f; }
};

struct RibbonGrid {
  const Surface<3>* shadow;
  const Rows* rows;
  int cols;

  // The cell row of a triangle: its vertices lie on rows `row` and next(row).
  int cell_row(const Triangle& t) const {
    const int n = rows->count();
    int lo = n, hi = -1;
    for (int v : t) {
      lo = std::min(lo, v / cols);
      hi = std::max(hi, v / cols);
    }
    return rows->closed && lo == 0 && hi == n - 1 ? n - 1 : lo;
  }
  GridPoint locate(const Triangle& t, const Vec3& p) const {
    const Vec3& a = shadow->vertices[t[0]];
    const Vec3 e1 = shadow->vertices[t[1]] - a, e2 = shadow->vertices[t[2]] - a, d = p - a;
    const double d00 = e1.dot(e1), d01 = e1.dot(e2), d11 = e2.dot(e2);
    const double den = d00 * d11 - d01 * d01;
    double l1 = den > 0 ? (d11 * e1.dot(d) - d01 * e2.dot(d)) / den : 0;
    double l2 = den > 0 ? (d00 * e2.dot(d) - d01 * e1.dot(d)) / den : 0;
    l1 = std::clamp(l1, 0.0, 1.0);
    l2 = std::clamp(l2, 0.0, 1.0 - l1);
    const double lambda[3] = {1 - l1 - l2, l1, l2};
    GridPoint g;
    g.row = cell_row(t);
    for (int k = 0; k < 3; ++k) {
      g.f += lambda[k] * (t[k] / cols == g.row ? 0.0 : 1.0);
      g.v += lambda[k] * (t[k] % cols) / (cols - 1.0);
    }
    return g;
  }
};

// [SECTION] passages: where the ribbon's shadow meets another sheet's, as constraints on w

// A point of an overlap with another surface: the ribbon must pass above w_hi or below w_lo there
// (equal where the sheets cross; the other triangle's range where they overlap flat).
struct OverlapPoint {
  GridPoint at;
  double w_hi = 0, w_lo = 0;
};
struct Piece {
  std::vector<OverlapPoint> points;
  std::vector<std::pair<double, double>> centre_crossings;  // (u, other's w) where v = 1/2
};

// A pair of cell rows of the ribbon whose shadows overlap: `later` the higher index.
struct SelfPair {
  int earlier = 0, later = 0;
};

struct Passage {
  RibbonPassage out;
  std::vector<int> constraints;
  double other_u = -1;  // itself: the earlier strand's row parameter where the choice was read
};

struct Constraints {
  std::vector<DepthConstraint> list;
  std::vector<int> owner;  // the passage each belongs to
  void add(const DepthConstraint& c, int passage) {
    list.push_back(c);
    owner.push_back(passage);
  }
};

// The ribbon's w at (row, f) is sign × at least floor + gap (sign -1: at most -floor - gap).
DepthConstraint row_constraint(const Rows& rows, const GridPoint& g, double sign, double floor, double gap) {
  DepthConstraint c;
  c.terms[0] = {0, g.row, sign * (1 - g.f)};
  c.terms[1] = {0, rows.next(g.row), sign * g.f};
  c.count = 2;
  c.floor = floor;
  c.gap = gap;
  return c;
}

// Merges pieces of one surface that touch the same or neighbouring rows: the ribbon, one w a row,
// takes one side of that surface there, so one choice serves them.
std::vector<Piece> merge_pieces(std::vector<Piece> pieces, const Rows& rows) {
  const int n = static_cast<int>(pieces.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::map<int, std::vector<int>> by_row;  // the pieces on each row
  for (int i = 0; i < n; ++i)
    for (const OverlapPoint& p : pieces[i].points) {
      by_row[p.at.row].push_back(i);
      if (p.at.f > 0) by_row[rows.next(p.at.row)].push_back(i);
    }
  for (const auto& [row, ids] : by_row) {
    for (int id : ids) parent[find_root(parent, id)] = find_root(parent, ids[0]);
    const auto next = by_row.find(rows.next(row));
    if (next != by_row.end()) parent[find_root(parent, next->second[0])] = find_root(parent, ids[0]);
  }
  std::map<int, Piece> merged;
  for (int i = 0; i < n; ++i) {
    Piece& m = merged[find_root(parent, i)];
    m.points.insert(m.points.end(), pieces[i].points.begin(), pieces[i].points.end());
    m.centre_crossings.insert(m.centre_crossings.end(), pieces[i].centre_crossings.begin(),
                              pieces[i].centre_crossings.end());
  }
  std::vector<Piece> out;
  for (auto& [root, p] : merged) out.push_back(std::move(p));
  return out;
}

// The overlaps of the ribbon's shadow with the shadow of `other`: one piece per intersection curve
// (exact, the sheets crossing) and per flat overlap (coplanar triangles, the other's w range).
std::vector<Piece> overlaps_with(const Surface<4>& flat, const Surface<3>& shadow, const RibbonGrid& grid,
                                 const Surface<4>& other, const Frame<4>& frame, double scale) {
  std::vector<Piece> pieces;
  const ShadowIntersections si = shadow_intersections(flat, other, frame);
  for (const ShadowCurve& curve : si.curves) {
    Piece piece;
    for (int k : curve.segments) {
      const ShadowSegment& s = si.segments[k];
      const GridPoint g0 = grid.locate(flat.triangles[s.a], s.p0), g1 = grid.locate(flat.triangles[s.a], s.p1);
      piece.points.push_back({g0, s.depth_b0, s.depth_b0});
      piece.points.push_back({g1, s.depth_b1, s.depth_b1});
      if ((g0.v - 0.5) * (g1.v - 0.5) <= 0 && g0.v != g1.v) {
        const double t = (0.5 - g0.v) / (g1.v - g0.v);
        piece.centre_crossings.push_back({(1 - t) * g0.u() + t * g1.u(), (1 - t) * s.depth_b0 + t * s.depth_b1});
      }
    }
    pieces.push_back(std::move(piece));
  }
  if (si.coplanar_pairs > 0) {
    Surface<3> other_shadow;
    other_shadow.triangles = other.triangles;
    std::vector<double> w;
    for (const Vec4& p : other.vertices) {
      const Vec4 q = frame.to_view(p);
      other_shadow.vertices.push_back(frame.project(q));
      w.push_back(q[3]);
    }
    const IntersectionReport<3> r = surface_intersections<3>(shadow, other_shadow);
    for (const ProximityPair<3>& pair : r.pairs) {
      const Triangle& ta = shadow.triangles[pair.a];
      const Triangle& tb = other.triangles[pair.b];
      const Vec3 n = (shadow.vertices[ta[1]] - shadow.vertices[ta[0]])
                         .cross(shadow.vertices[ta[2]] - shadow.vertices[ta[0]]);
      bool flat_pair = n.norm() > 0;
      for (int v : tb)
        flat_pair = flat_pair && std::abs(n.dot(other_shadow.vertices[v] - shadow.vertices[ta[0]])) <=
                                     1e-9 * scale * n.norm();
      if (!flat_pair) continue;  // crossing sheets: the curves above have them exactly
      const double hi = std::max({w[tb[0]], w[tb[1]], w[tb[2]]});
      const double lo = std::min({w[tb[0]], w[tb[1]], w[tb[2]]});
      Piece piece;
      const GridPoint mid = grid.locate(ta, (shadow.vertices[ta[0]] + shadow.vertices[ta[1]] + shadow.vertices[ta[2]]) / 3);
      for (double f : {0.0, 1.0}) piece.points.push_back({GridPoint{mid.row, f, mid.v}, hi, lo});
      pieces.push_back(std::move(piece));
    }
  }
  return pieces;
}

std::string surface_name(std::span<const std::string> names, int k) {
  return k < static_cast<int>(names.size()) ? "'" + names[k] + "'" : "surface " + std::to_string(k + 1);
}

std::string passage_text(const RibbonPassage& p, std::span<const std::string> names) {
  return std::string(p.below ? "below " : "above ") + (p.surface < 0 ? "itself" : surface_name(names, p.surface)) +
         " at " + fmt(p.place);
}

}  // namespace

// [SECTION] ribbon_from_sketch

namespace {

void check_inputs(std::span<const RibbonStrokeSample> stroke, std::span<const Surface<4>> others,
                  const Vec3& toward_eye, const RibbonSketchOptions& options, std::span<const std::string> names) {
  check_stroke<3>(stroke, 2);
  if (!toward_eye.allFinite() || !(toward_eye.norm() > 0))
    throw Error("the direction towards the eye must be a finite, non-zero vector");
  if (options.across < 2 || options.across > 64)
    throw Error("a ribbon has 2 to 64 vertices across, not " + std::to_string(options.across));
  for (const auto* x : {&options.spacing, &options.clearance, &options.smoothing, &options.max_move})
    if (!(*x >= 0) || !std::isfinite(*x))
      throw Error("the ribbon's spacing, clearance, smoothing and largest move must be finite and not negative");
  for (std::size_t k = 0; k < others.size(); ++k)
    for (const Vec4& p : others[k].vertices)
      if (!p.allFinite()) throw Error(surface_name(names, static_cast<int>(k)) + " has a vertex that is not finite");
}

// The stroke laid out as a flat ribbon facing the eye: the pen's path, its centre line in rows
// (smoothed where the ribbon would fold), the ribbon's proportions, and its shadow. Not copied or
// moved once made: its grid points into it.
struct Layout {
  std::vector<PenPoint<3>> path;
  double size = 0, width = 0, path_length = 0, clearance = 0;
  double join = 1;  // closed: the fraction of the way round where the stroke's closing stretch starts
  Rows rows;
  std::vector<Vec3> centre;
  CentreLineSmoothing smoothing;
  std::vector<RibbonFold> folds;  // left after smoothing
  std::vector<FoldPlace> places;  // theirs on the stroke as drawn
  Surface<3> shadow;
  RibbonGrid grid{nullptr, nullptr, 0};
  double scale = 0;  // of the whole sketch, for tolerances
  int n() const { return rows.count(); }
};

double row_spacing(const RibbonSketchOptions& o, double width, double size) {
  return o.spacing > 0 ? o.spacing : std::min(width / 2, size / 60);
}

void lay_out(Layout& l, std::span<const RibbonStrokeSample> stroke, const Vec3& eye, const RibbonSketchOptions& options) {
  // The pen's path, its size and the ribbon's proportions.
  l.path = pen_path<3>(stroke, options.pen);
  Vec3 lo = l.path[0].at, hi = l.path[0].at;
  for (const PenPoint<3>& p : l.path) {
    lo = lo.cwiseMin(p.at);
    hi = hi.cwiseMax(p.at);
  }
  l.size = (hi - lo).norm();
  if (!(l.size > 0)) throw Error("the sketch has no extent: drag to draw");
  l.width = options.width;
  if (!(l.width > 0) || !std::isfinite(l.width))
    throw Error("the ribbon's width must be a positive number, not " + fmt(l.width));
  if (l.width > l.size)
    throw Error("a ribbon " + fmt(l.width) + " wide is wider than the whole stroke (" + fmt(l.size) +
                " across): draw a longer stroke or narrow the ribbon");
  if (l.width < 1e-4 * l.size)
    throw Error("a ribbon " + fmt(l.width) + " wide is too narrow for a stroke " + fmt(l.size) +
                " across (at least 1/10000 of it)");
  const double spacing = row_spacing(options, l.width, l.size);
  for (std::size_t i = 1; i < l.path.size(); ++i) l.path_length += (l.path[i].at - l.path[i - 1].at).norm();
  const double closing = options.closed ? (l.path.back().at - l.path.front().at).norm() : 0.0;
  l.path_length += closing;
  l.join = options.closed ? (l.path_length - closing) / l.path_length : 1.0;
  if (l.path_length / spacing > kMaxRows)
    throw Error("a spacing of " + fmt(spacing) + " along a stroke " + fmt(l.path_length) + " long gives more than " +
                std::to_string(kMaxRows) + " rows");
  const long long vertices = static_cast<long long>(std::ceil(l.path_length / spacing) + 1) * options.across;
  if (vertices > kMaxVertices)
    throw Error("a ribbon " + std::to_string(options.across) + " vertices across with rows " + fmt(spacing) +
                " apart along a stroke " + fmt(l.path_length) + " long has about " + std::to_string(vertices) +
                " vertices, more than " + std::to_string(kMaxVertices) + ": take fewer across or space the rows wider");
  l.clearance = options.clearance > 0 ? options.clearance : 0.05 * l.size;

  // The centre line, smoothed where the ribbon would fold.
  CentreLineResult line = ribbon_centre_line(l.path, options.closed, spacing, options.closed ? 8 : 2, l.width, eye,
                                             options.max_move * l.width);
  l.smoothing = line.smoothing;
  l.folds = std::move(line.folds);
  l.places = std::move(line.places);
  l.path_length = line.line.length;
  l.rows.closed = options.closed;
  l.rows.at = std::move(line.line.rows);
  l.rows.spacing = line.line.spacing;
  for (const PenPoint<3>& p : l.rows.at) l.centre.push_back(p.at);

  // The ribbon's shadow: face-on to the eye, width across the stroke.
  l.shadow = ribbon_along(l.centre, options.closed, line.line.across, l.width, options.across);
  l.grid = RibbonGrid{&l.shadow, &l.rows, options.across};
  l.scale = std::max(l.size, l.width);
}

// What the search for a narrower ribbon found.
struct WidestFlat {
  double width = 0;        // the widest that lies flat (0: none found)
  double narrowest = 0;    // the narrowest width found to fold (0: none tried)
  bool cut_short = false;  // the search stopped at its budget of work
  long long work = 0;      // rows its fold tests looked at
};

// The widest ribbon narrower than the layout's whose centre line lies flat without folding, to
// two significant digits (rounded down); 0 when none does down to a twentieth of the width (a
// narrower one would be another ribbon: the turn is what to change). The search looks at no more
// than kRibbonSuggestionWork rows in all (the window waits for it): a width it cannot settle
// within that ends it.
WidestFlat widest_flat(const Layout& l, const Vec3& eye, const RibbonSketchOptions& o) {
  WidestFlat out;
  // 1: lies flat; 0: folds; -1: not settled within the budget.
  auto flat = [&](double w) {
    const double spacing = row_spacing(o, w, l.size);
    if (l.path_length / spacing > kMaxRows) return 0;
    const long long left = kRibbonSuggestionWork - out.work;
    if (2 * static_cast<long long>(std::ceil(l.path_length / spacing) + 1) > left) return -1;
    const CentreLineResult r =
        ribbon_centre_line(l.path, o.closed, spacing, o.closed ? 8 : 2, w, eye, o.max_move * w, left);
    out.work += r.work;
    return r.folds.empty() ? 1 : r.cut_short ? -1 : 0;
  };
  double good = 0, bad = l.width;
  for (double w = 0.7 * l.width; w >= std::max(l.width / 20, 1e-4 * l.size) && good == 0; w *= 0.7) {
    const int f = flat(w);
    if (f < 0) {
      out.cut_short = true;
      return out;
    }
    (f > 0 ? good : bad) = w;
    if (f == 0) out.narrowest = w;
  }
  if (good == 0) return out;
  out.width = good;
  for (int k = 0; k < 3; ++k) {
    const double mid = 0.5 * (good + bad);
    const int f = flat(mid);
    if (f < 0) {
      out.cut_short = true;
      return out;
    }
    (f > 0 ? good : bad) = mid;
  }
  const double digit = std::pow(10.0, std::floor(std::log10(good)) - 1);
  const double rounded = std::floor(good / digit) * digit;
  const int f = rounded > 0 ? flat(rounded) : 0;
  out.cut_short = f < 0;
  out.width = f > 0 ? rounded : good;
  return out;
}

// Refuses a ribbon that folds at cell rows a < b, at `place` on the stroke as drawn (`along` the
// fraction of the way along it): says where, how far the stroke was allowed to be smoothed, and
// what to change: the turn, the stroke's end for a loop's join, or the width.
[[noreturn]] void refuse_fold(const Layout& l, int a, int b, const FoldPlace& place, const Vec3& eye,
                              const RibbonSketchOptions& o) {
  const int n = l.n();
  // A closed ribbon's join (the straight stretch from the stroke's end back to its start) turns at
  // both its ends.
  const double join = l.join * n, near = l.width / l.rows.spacing;
  const bool at_join = l.rows.closed && (2 * (b - a) > n || b >= join - near || a <= near || b >= n - near);
  std::string what = "the ribbon folds onto itself near " + fmt(place.at) + ", " +
                     std::to_string(static_cast<int>(std::lround(100 * place.along))) +
                     "% of the way along the stroke: the stroke turns there more sharply than half the ribbon's width (" +
                     fmt(l.width / 2) + ")";
  if (l.smoothing.limit > 0)
    what += ", even smoothed as far as it may move (" + fmt(l.smoothing.limit) + ", " + fmt(o.max_move) +
            " of the width)";
  what += at_join ? "; end the stroke nearer its start, heading the way it began" : "; draw that turn wider";
  const WidestFlat widest = widest_flat(l, eye, o);
  if (widest.width > 0)
    what += ", or make the ribbon at most " + fmt(widest.width) + " wide";
  else if (!widest.cut_short)
    what += " (no narrower ribbon lies flat there)";
  if (widest.cut_short && widest.width > 0)
    what += " (the search for the widest that lies flat there was cut short: a wider one may too)";
  else if (widest.cut_short)
    what +=
        " (the search for a narrower ribbon that lies flat there was cut short" +
        (widest.narrowest > 0 ? ": none down to " + fmt(widest.narrowest) + " wide does)" : std::string(")"));
  throw RibbonFoldError(what, place.at, widest.width, widest.cut_short, widest.work);
}

// Where the ribbon passes itself: overlapping cells far apart along the stroke. Cells near each
// other along it overlap only where it folds, which no choice of w can undo (the centre line was
// smoothed to take those out; any left are refused).
std::vector<SelfPair> self_overlaps(const Layout& l, const Vec3& eye, const RibbonSketchOptions& o) {
  if (!l.folds.empty()) refuse_fold(l, l.folds[0].a, l.folds[0].b, l.places[0], eye, o);
  std::vector<SelfPair> pairs;
  for (const ProximityPair<3>& p : self_intersections<3>(l.shadow).pairs) {
    int a = l.grid.cell_row(l.shadow.triangles[p.a]), b = l.grid.cell_row(l.shadow.triangles[p.b]);
    if (a > b) std::swap(a, b);
    if (l.rows.separation(a, b) < l.width) {
      const double u = l.rows.closed && 2 * (b - a) > l.n() ? b + 0.5 : a + 0.5;
      refuse_fold(l, a, b, FoldPlace{l.rows.point(u), u / (l.rows.closed ? l.n() : l.n() - 1)}, eye, o);
    }
    pairs.push_back({a, b});
  }
  return pairs;
}

// The passages past the other surfaces, each with the constraints on w its choice makes.
void passages_past_others(const Layout& l, std::span<const RibbonStrokeSample> stroke,
                          std::span<const Surface<4>> others, const Frame<4>& frame, std::vector<Passage>& passages,
                          Constraints& cons) {
  // The flat ribbon (w = 0 in the view), whose shadow meets the others' shadows.
  Surface<4> flat;
  flat.triangles = l.shadow.triangles;
  flat.grid = l.shadow.grid;
  for (const Vec3& s : l.shadow.vertices) flat.vertices.push_back(frame.to_world(Vec4(s.x(), s.y(), s.z(), 0.0)));
  const int n = l.n();
  for (std::size_t k = 0; k < others.size(); ++k) {
    if (others[k].triangles.empty()) continue;
    for (const Piece& piece : merge_pieces(overlaps_with(flat, l.shadow, l.grid, others[k], frame, l.scale), l.rows)) {
      if (piece.points.empty()) continue;
      // The choice is read where the centre line crosses the other sheet's shadow, or, where it
      // does not (sheets overlapping flat), in the middle of the rows the overlap covers.
      double u = piece.points[0].at.u(), other_w = piece.points[0].w_hi;
      if (!piece.centre_crossings.empty()) {
        u = piece.centre_crossings[0].first;
        other_w = piece.centre_crossings[0].second;
      } else {
        double u_lo = u, u_hi = u;
        for (const OverlapPoint& p : piece.points) {
          u_lo = std::min(u_lo, p.at.u());
          u_hi = std::max(u_hi, p.at.u());
        }
        if (u_hi - u_lo < 0.5 * n) u = 0.5 * (u_lo + u_hi);  // not round the join of a loop
        double best = std::numeric_limits<double>::infinity();
        for (const OverlapPoint& p : piece.points)
          if (std::abs(p.at.u() - u) < best) {
            best = std::abs(p.at.u() - u);
            other_w = 0.5 * (p.w_hi + p.w_lo);
          }
      }
      Passage ps;
      ps.out.surface = static_cast<int>(k);
      ps.out.place = l.rows.point(u);
      ps.out.row = static_cast<int>(std::floor(u)) % n;
      ps.out.at_length = u * l.rows.spacing;
      ps.out.below = held_under<3>(stroke, ps.out.place, l.rows.time(u));
      ps.out.other_w = other_w;
      const int id = static_cast<int>(passages.size());
      for (const OverlapPoint& p : piece.points) {
        ps.constraints.push_back(static_cast<int>(cons.list.size()));
        cons.add(ps.out.below ? row_constraint(l.rows, p.at, -1, -p.w_lo, l.clearance)
                              : row_constraint(l.rows, p.at, 1, p.w_hi, l.clearance),
                 id);
      }
      passages.push_back(std::move(ps));
    }
  }
}

// Self passages: clusters of overlapping cell pairs next to each other on both strands, the later
// strand choosing where the two centre lines come nearest.
void passages_past_itself(const Layout& l, std::span<const RibbonStrokeSample> stroke,
                          const std::vector<SelfPair>& self_pairs, std::vector<Passage>& passages, Constraints& cons) {
  const Rows& rows = l.rows;
  const int n = l.n(), m = static_cast<int>(self_pairs.size());
  std::vector<int> parent(m);
  std::iota(parent.begin(), parent.end(), 0);
  std::map<std::pair<int, int>, int> by_rows;
  for (int i = 0; i < m; ++i) by_rows.emplace(std::pair(self_pairs[i].earlier, self_pairs[i].later), i);
  for (int i = 0; i < m; ++i)
    for (int de = -1; de <= 1; ++de)
      for (int dl = -1; dl <= 1; ++dl) {
        const int e = (self_pairs[i].earlier + de + n) % n, lt = (self_pairs[i].later + dl + n) % n;
        if (!rows.near(e, self_pairs[i].earlier) || !rows.near(lt, self_pairs[i].later)) continue;
        const auto it = by_rows.find(std::pair(std::min(e, lt), std::max(e, lt)));
        if (it != by_rows.end()) parent[find_root(parent, i)] = find_root(parent, it->second);
      }
  std::map<int, std::vector<int>> clusters;
  for (int i = 0; i < m; ++i) clusters[find_root(parent, i)].push_back(i);
  for (const auto& [root, members] : clusters) {
    const SelfPair* at = &self_pairs[members[0]];
    double best = std::numeric_limits<double>::infinity();
    for (int i : members) {
      const SelfPair& p = self_pairs[i];
      const double d = (rows.point(p.earlier + 0.5) - rows.point(p.later + 0.5)).norm();
      if (d < best) {
        best = d;
        at = &p;
      }
    }
    Passage ps;
    ps.out.surface = -1;
    ps.out.row = at->later;
    ps.out.at_length = (at->later + 0.5) * rows.spacing;
    ps.out.place = rows.point(at->later + 0.5);
    ps.out.below = held_under<3>(stroke, ps.out.place, rows.time(at->later + 0.5));
    ps.other_u = at->earlier + 0.5;
    const int id = static_cast<int>(passages.size());
    std::set<std::pair<int, int>> done;
    for (int i : members) {
      const SelfPair& p = self_pairs[i];
      const int up = ps.out.below ? p.earlier : p.later, down = ps.out.below ? p.later : p.earlier;
      for (int x : {up, rows.next(up)})
        for (int y : {down, rows.next(down)}) {
          if (x == y || !done.insert({x, y}).second) continue;
          DepthConstraint c;
          c.terms[0] = {0, x, 1.0};
          c.terms[1] = {0, y, -1.0};
          c.count = 2;
          c.gap = l.clearance;
          ps.constraints.push_back(static_cast<int>(cons.list.size()));
          cons.add(c, id);
        }
    }
    passages.push_back(std::move(ps));
  }
}

// w, one value a row, smoothed keeping every choice; throws naming the passages whose choices
// cannot all hold.
std::vector<DepthChain> solve_w(const Layout& l, const RibbonSketchOptions& options, const std::vector<Passage>& passages,
                                const Constraints& cons, std::span<const std::string> names) {
  const int n = l.n();
  std::vector<DepthChain> chain{DepthChain{std::vector<double>(n, 0.0), options.closed}};
  const double spread = options.smoothing > 0 ? options.smoothing : 0.25 * l.size;
  const double steps = std::ceil(std::pow(spread / l.rows.spacing, 2) / kRate);
  // No more than about 1e8 operations, however long the ribbon.
  const double budget = std::max(50.0, 1e8 / (n + 8.0 * static_cast<double>(cons.list.size())));
  const int iterations = static_cast<int>(std::clamp(steps, 1.0, std::min(budget, double(kMaxSmoothingIterations))));
  // The order of every passage is checked below with its full gap, after a last projection.
  smooth_depth_values(chain, cons.list, iterations, kRate);
  project_depth(chain, cons.list, 20000, 1e-12 * l.scale);
  // Choices that cannot all hold leave a constraint short: say which passages meet there.
  int worst = -1;
  double worst_deficit = 1e-6 * l.clearance;
  for (std::size_t i = 0; i < cons.list.size(); ++i) {
    const DepthConstraint& c = cons.list[i];
    const double deficit = c.floor + c.gap - c.value(chain);
    if (deficit > worst_deficit) {
      worst_deficit = deficit;
      worst = static_cast<int>(i);
    }
  }
  if (worst < 0) return chain;
  const int p = cons.owner[worst];
  std::set<int> rows_there;
  for (int t = 0; t < cons.list[worst].count; ++t) rows_there.insert(cons.list[worst].terms[t].index);
  std::string with;
  for (std::size_t i = 0; i < cons.list.size(); ++i) {
    if (cons.owner[i] == p) continue;
    bool shares = false;
    for (int t = 0; t < cons.list[i].count; ++t) shares = shares || rows_there.count(cons.list[i].terms[t].index) > 0;
    if (shares) {
      with = " and " + passage_text(passages[cons.owner[i]].out, names);
      break;
    }
  }
  throw Error("the choices " + passage_text(passages[p].out, names) + with +
              " cannot both hold: where their overlaps meet, the ribbon (one w across each row) would have "
              "to be on both sides; choose the same side for both or draw them apart");
}

// The ribbon lifted to R^4 by w and checked to be embedded and apart from the others.
void lift_and_check(const Layout& l, const std::vector<double>& w, std::span<const Surface<4>> others,
                    const Frame<4>& frame, std::span<const std::string> names, SketchedRibbon& out) {
  const int cols = l.grid.cols;
  out.surface.triangles = l.shadow.triangles;
  out.surface.grid = l.shadow.grid;
  for (int i = 0; i < l.n(); ++i)
    for (int j = 0; j < cols; ++j) {
      const Vec3& s = l.shadow.vertices[i * cols + j];
      out.surface.vertices.push_back(frame.to_world(frame.lift(s, w[i])));
    }
  const IntersectionReport<4> self = self_intersections<4>(out.surface);
  if (!self.pairs.empty())
    throw Error("the ribbon would meet itself in R^4 near " + fmt(frame.shadow(self.points[0])) +
                " (in the shadow): draw it again there");
  out.gap_to_others = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < others.size(); ++k) {
    if (others[k].triangles.empty()) continue;
    const IntersectionReport<4> r = surface_intersections<4>(out.surface, others[k]);
    if (!r.pairs.empty())
      throw Error("the ribbon would meet " + surface_name(names, static_cast<int>(k)) + " in R^4 near " +
                  fmt(frame.shadow(r.points[0])) + " (in the shadow): its shadow overlaps there in a way no "
                  "passage caught; turn the view a little or draw it again");
    PairProximity<4, 3, 3> q(out.surface.triangles, others[k].triangles);
    out.gap_to_others = std::min(out.gap_to_others, q.smallest_distance(out.surface.vertices, others[k].vertices, 4 * l.clearance));
  }
}

// What the UI shows of each passage: the ribbon's w there, the other's, and the gap kept.
void describe_passages(const Layout& l, const std::vector<DepthChain>& chain, std::vector<Passage>& passages,
                       const Constraints& cons, SketchedRibbon& out) {
  const std::vector<double>& w = chain[0].z;
  const int n = l.n();
  auto w_at = [&](double u) {
    const int r = static_cast<int>(std::floor(u)) % n;
    return (1 - (u - std::floor(u))) * w[r] + (u - std::floor(u)) * w[l.rows.next(r)];
  };
  for (Passage& ps : passages) {
    ps.out.ribbon_w = w_at(ps.out.at_length / l.rows.spacing);
    if (ps.other_u >= 0) ps.out.other_w = w_at(ps.other_u);
    ps.out.gap = std::numeric_limits<double>::infinity();
    for (int c : ps.constraints) ps.out.gap = std::min(ps.out.gap, cons.list[c].value(chain) - cons.list[c].floor);
    out.passages.push_back(ps.out);
  }
  std::stable_sort(out.passages.begin(), out.passages.end(),
                   [](const RibbonPassage& a, const RibbonPassage& b) { return a.at_length < b.at_length; });
}

// What the smoothing did, for the status line: "" when the stroke was kept as drawn.
std::string smoothing_sentence(const CentreLineSmoothing& s, double width) {
  if (s.rounds == 0) return "";
  return "smoothed the stroke " + std::to_string(s.rounds) + (s.rounds == 1 ? " time" : " times") + " to take out " +
         (s.turns == 1 ? std::string("a turn") : std::to_string(s.turns) + " turns") +
         " too sharp for the ribbon's width (" + fmt(width) + "), moving its centre line by at most " + fmt(s.moved);
}

}  // namespace

SketchedRibbon ribbon_from_sketch(std::span<const RibbonStrokeSample> stroke,
                                  std::span<const Surface<4>> others, const Frame<4>& frame,
                                  const Vec3& toward_eye, const RibbonSketchOptions& options,
                                  std::span<const std::string> names) {
  check_inputs(stroke, others, toward_eye, options, names);
  Layout layout;
  const Vec3 eye = toward_eye.normalized();
  lay_out(layout, stroke, eye, options);
  const std::vector<SelfPair> self_pairs = self_overlaps(layout, eye, options);
  std::vector<Passage> passages;
  Constraints cons;
  passages_past_others(layout, stroke, others, frame, passages, cons);
  passages_past_itself(layout, stroke, self_pairs, passages, cons);
  const std::vector<DepthChain> chain = solve_w(layout, options, passages, cons, names);
  SketchedRibbon out;
  lift_and_check(layout, chain[0].z, others, frame, names, out);
  describe_passages(layout, chain, passages, cons, out);
  out.centre = std::move(layout.centre);
  out.w = chain[0].z;
  out.length = layout.path_length;
  out.clearance = layout.clearance;
  out.smoothing = layout.smoothing;
  out.changes = smoothing_sentence(layout.smoothing, layout.width);
  return out;
}

bool ribbon_stroke_comes_back(std::span<const RibbonStrokeSample> stroke, double width) {
  if (stroke.size() < 3 || !(width > 0)) return false;
  double length = 0;
  for (std::size_t i = 1; i < stroke.size(); ++i) length += (stroke[i].at - stroke[i - 1].at).norm();
  const double gap = (stroke.back().at - stroke.front().at).norm();
  return gap <= 1.5 * width && length > 6 * width;
}

// [SECTION] scenes

SketchObstacles sketch_obstacles(const Scene& scene) {
  SketchObstacles out;
  for (const SceneObject& obj : scene.objects) {
    if (const auto* s4 = std::get_if<Surface<4>>(&obj.shape)) {
      out.surfaces.push_back(*s4);
    } else if (const auto* s3 = std::get_if<Surface<3>>(&obj.shape)) {
      Surface<4> s;
      s.triangles = s3->triangles;
      s.grid = s3->grid;
      for (const Vec3& p : s3->vertices) s.vertices.push_back(scene.frame.to_world(Vec4(p.x(), p.y(), p.z(), 0.0)));
      out.surfaces.push_back(std::move(s));
    } else {
      ++out.curves;
      continue;
    }
    out.names.push_back(obj.name);
  }
  return out;
}

std::string add_sketched_ribbon(Scene& scene, const SketchedRibbon& ribbon, const std::string& name) {
  std::set<std::string> taken;
  for (const SceneObject& obj : scene.objects) taken.insert(obj.name);
  SceneObject o;
  o.name = name.empty() ? "ribbon" : name;
  for (int k = 2; taken.count(o.name); ++k) o.name = (name.empty() ? "ribbon" : name) + " " + std::to_string(k);
  o.shape = ribbon.surface;
  scene.objects.push_back(std::move(o));
  return scene.objects.back().name;
}

// [SECTION] stroke files

std::vector<RibbonStrokeSample> parse_ribbon_stroke(std::string_view text, const std::string& origin, double dt) {
  if (!(dt > 0) || !std::isfinite(dt)) throw Error("the time between stroke samples must be positive");
  std::vector<RibbonStrokeSample> out;
  TextScanner in(text, origin);
  while (!in.at_end()) {  // one sample a line
    const int line = in.line();
    double v[4];
    for (int k = 0; k < 4; ++k) {
      if (k > 0 && (in.at_end() || in.line() != line))
        in.fail_at(line, "a stroke sample is x y z u (4 numbers), this line has " + std::to_string(k));
      v[k] = in.next_double("x, y, z or u");
    }
    if (!in.at_end() && in.line() == line) in.fail_at(line, "too many numbers: a stroke sample is x y z u");
    if (v[3] != 0 && v[3] != 1)
      in.fail_at(line, "u is 1 where the modifier was held (below) and 0 elsewhere, not " + fmt(v[3]));
    out.push_back({Vec3(v[0], v[1], v[2]), dt * static_cast<double>(out.size()), v[3] == 1});
  }
  if (out.empty()) throw ParseError(origin, 0, "the stroke has no samples (lines of x y z u)");
  return out;
}

std::vector<RibbonStrokeSample> read_ribbon_stroke(const std::filesystem::path& path, double dt) {
  return parse_ribbon_stroke(read_text_file(path), path.string(), dt);
}

}  // namespace s4d
