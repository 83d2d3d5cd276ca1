// The centre line of a ribbon sketch (ribbon_sketch.hpp): the pen's path resampled into evenly
// spaced rows, each with the direction the width lies in (across the line, facing the eye). A
// rough stroke (a corner sharper than half the ribbon's width, a jagged stretch) would fold the
// flat ribbon onto itself; there, and only there, the line is smoothed, round by round, until the
// ribbon lies flat with a margin, never moving further than a bound from the line drawn. A stroke
// whose ribbon does not fold is kept exactly as drawn.
#pragma once
#include <limits>
#include <vector>

#include "core/vec.hpp"
#include "knots/stroke.hpp"

namespace s4d {

struct CentreLine {
  std::vector<PenPoint<3>> rows;  // evenly spaced by arc length, each with the pen's time there
  std::vector<Vec3> across;       // per row, unit: the direction the width lies in
  bool closed = false;            // the last row joins the first
  double spacing = 0;             // arc length between consecutive rows
  double length = 0;              // of the line (closed: round the loop)
};

// A place where a flat ribbon along the line overlaps itself although the two overlapping cells
// are less than a width apart along it (cell r spans rows r and r + 1): a = the earlier cell,
// b = the later; round a closed line's join, b - a is more than half the rows.
struct RibbonFold {
  int a = 0, b = 0;
};

// What the smoothing did to the line drawn.
struct CentreLineSmoothing {
  int rounds = 0;     // 0: the line as drawn
  int turns = 0;      // places where the ribbon folded before any smoothing
  double moved = 0;   // the farthest a point of the line lies from the line drawn
  double cut = 0;     // the farthest a point drawn lies from the line (a hook cut off a corner)
  double limit = 0;   // how far it could move (max_move); it could cut twice as far
};

// Where a fold lies on the line as drawn (the user's stroke, before any smoothing).
struct FoldPlace {
  Vec3 at = Vec3::Zero();
  double along = 0;  // the fraction of the way along the line
};

struct CentreLineResult {
  CentreLine line;
  CentreLineSmoothing smoothing;
  std::vector<RibbonFold> folds;  // still there (empty: the ribbon lies flat without folding)
  std::vector<FoldPlace> places;  // one per fold still there: the drawn fold nearest it
  long long work = 0;             // rows the fold tests looked at: what the smoothing cost
  bool cut_short = false;         // the smoothing stopped at `max_work`: folds left may not be final
};

// The line of `path` (at least 2 points) in rows `spacing` apart (at least `min_segments`
// segments), a flat ribbon `width` wide along it facing `eye` (unit). Where that ribbon folds, the
// line is smoothed (Laplacian, the ends of an open line kept) until it lies flat even 1.25 times
// as wide, or until smoothing further would move the line more than `max_move` from the one
// drawn, or leave a point drawn more than 2 max_move from it (a hook at a corner may be cut off,
// a hairpin may not be shortened); 0: never smoothed. No smoothing round starts that would take
// the work past `max_work` (then cut_short): a caller trying many widths bounds its search so.
// Throws s4d::Error when the line runs along the line of sight.
CentreLineResult ribbon_centre_line(const std::vector<PenPoint<3>>& path, bool closed, double spacing,
                                    int min_segments, double width, const Vec3& eye, double max_move,
                                    long long max_work = std::numeric_limits<long long>::max());

// Unit directions across a flat ribbon along `rows`: in the plane facing `eye`, perpendicular to
// the line; where the line runs along the line of sight the last good direction carries on.
std::vector<Vec3> across_directions(const std::vector<PenPoint<3>>& rows, bool closed, const Vec3& eye);

// The folds of a flat ribbon `width` wide along `line` (its directions across). Only cells less
// than a width apart along the line are looked at: a few per cell, whatever the ribbon's shape.
std::vector<RibbonFold> ribbon_folds(const CentreLine& line, double width);

}  // namespace s4d
