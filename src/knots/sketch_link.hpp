// A link from strokes drawn through the haptic loop (paper 4.2, Fig. 4): each component is a
// stroke already smoothed and resampled as it was drawn, with the over/under choice the hand held;
// where a stroke crosses one drawn before it (or another curve of the scene), the later strand
// passes over or under as chosen there, and the depth is then smoothed without changing a choice.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "shape/curve.hpp"

namespace s4d {

// The choice a hand holds: pass under, pass over, or none (then the loop never let it cross).
enum class CrossChoice : std::int8_t { kUnder = -1, kNone = 0, kOver = 1 };

struct StrokeComponent {
  std::vector<Vec2> points;          // in the sketch plane, in drawing order
  std::vector<CrossChoice> choices;  // one per point: what was held when it was drawn
  bool closed = false;               // closed near its start; an open one is closed by its chord
};

// Where the probe crossed a strand, and the choice it crossed with (the pen that draws the
// stroke trails the probe, so the choice is looked up here first, by place).
struct StrokeCrossing {
  Vec2 at = Vec2::Zero();
  CrossChoice choice = CrossChoice::kOver;
};

// Another curve of the scene seen in the sketch plane: its points and their depth (towards the
// eye, the same units as the plane).
struct FixedStrand {
  std::vector<Vec2> points;
  std::vector<double> depth;
  bool closed = true;
};

struct StrokeLinkOptions {
  double clearance = 0.05;  // depth gap at every crossing, × the sketch's size
  double match = 0;         // how near a probe crossing must be to decide a diagram crossing;
                            // 0: 3 × the mean point spacing
};

struct StrokeLink {
  Curve<3> curve;           // one closed component per stroke: (x, y) in the plane, z towards the eye
  int crossings = 0;        // among its own components, in the plane's view
  int fixed_crossings = 0;  // with the fixed strands
};

// Throws s4d::Error for no component, a component of fewer than 3 points or non-finite values,
// or strokes whose smoothed paths run along each other (draw again).
StrokeLink link_from_strokes(std::span<const StrokeComponent> strokes, std::span<const StrokeCrossing> crossed,
                             std::span<const FixedStrand> fixed, const StrokeLinkOptions& options = {});

}  // namespace s4d
