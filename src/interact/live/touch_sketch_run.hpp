// Sketching by touch without a window: the sketch scene run by the haptic loop on its own clock
// (run_ticks) with a device — a replayed trajectory, or the simulated arm whose hand follows a
// stroke file — then the strokes made into their knot or link. `shadow4d knot sketch --device`
// and the tests use it.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "haptics/device.hpp"
#include "interact/live/curve_sketch_scene.hpp"
#include "knots/sketch_link.hpp"

namespace s4d {

// Where a simulated hand aims each tick, and the buttons it holds (kSketch* bits).
struct HandSample {
  Vec3 target = Vec3::Zero();  // m, device coordinates
  std::uint32_t buttons = 0;
};

struct TouchSketchOptions {
  SketchSettings settings;
  double plane_z = 0;            // m, the sketch plane in device coordinates
  std::uint64_t settle_ticks = 300;  // run on after the device's input ends
  std::filesystem::path record;  // when set, the loop records the device trajectory here
};

struct TouchSketchResult {
  SketchPublished strokes;       // as the loop published them at the end
  StrokeLink link;               // their knot or link (plane coordinates, m; z towards the eye)
  std::string gauss;             // its Gauss code in the plane's view
  std::uint64_t ticks = 0;
  std::uint64_t replay_mismatches = 0;  // forces differing from the recording's (replays only)
  std::uint64_t disconnected_ticks = 0; // ticks the device was gone
  double max_force = 0;          // N, largest force sent to the device (after safety)
  std::uint64_t safety_nonfinite = 0;
};

// Runs `device` through the sketch scene: a replay plays to its end; with `hand` non-empty the
// loop's pointer follows it one sample a tick (the simulated arm's hand, the mouse's cursor).
// Throws s4d::Error when the strokes make no knot (with the reason).
TouchSketchResult run_touch_sketch(std::unique_ptr<Device> device, const std::vector<HandSample>& hand,
                                   const TouchSketchOptions& options);

// A stroke file (x y u per sample, `dt` seconds apart; u: 0 draw, 1 draw crossing under,
// 2 draw crossing over, -1 pen up) as a hand path of one sample a tick at `rate` Hz, scaled into
// `fit` (m, half extents around `centre`) of the device's plane z = centre.z. Throws s4d::Error
// for non-finite values, an unknown u, or no extent.
std::vector<HandSample> hand_from_stroke(const std::vector<Vec3>& samples, double dt, double rate, const Vec3& centre,
                                         const Vec2& fit);

// The plane of a recording made by run_touch_sketch ("sketch plane_z=..."), else `fallback`.
double sketch_plane_of_setup(const std::string& setup, double fallback);

}  // namespace s4d
