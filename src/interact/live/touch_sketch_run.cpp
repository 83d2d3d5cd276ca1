// The headless touch sketch: the loop's own tick (run_ticks), one hand sample per tick.
#include "interact/live/touch_sketch_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "haptics/haptic_loop.hpp"
#include "haptics/replay_device.hpp"
#include "knots/knot_diagram.hpp"

namespace s4d {

TouchSketchResult run_touch_sketch(std::unique_ptr<Device> device, const std::vector<HandSample>& hand,
                                   const TouchSketchOptions& options) {
  if (!device) throw Error("sketch: no device");
  if (!std::isfinite(options.plane_z)) throw Error("sketch: the plane's z is not finite");
  auto* replay = dynamic_cast<ReplayDevice*>(device.get());
  auto scene = std::make_unique<CurveSketchScene>(options.settings);
  CurveSketch& sketch = scene->curve_sketch();
  sketch.begin(options.plane_z);
  HapticLoopConfig cfg;
  cfg.realtime_priority = false;
  HapticLoop loop(std::move(device), std::move(scene), cfg);
  if (!options.record.empty()) {
    char setup[64];
    std::snprintf(setup, sizeof setup, "sketch plane_z=%.17g", options.plane_z);
    loop.record_to(options.record, setup);
  }
  TouchSketchResult r;
  const std::uint64_t input_ticks = replay ? replay->trajectory().ticks.size() : hand.size();
  const std::uint64_t total = input_ticks + options.settle_ticks;
  for (std::uint64_t t = 0; t < total; ++t) {
    if (!hand.empty()) {
      const HandSample& h = hand[std::min<std::size_t>(t, hand.size() - 1)];
      loop.set_pointer(h.target, t < hand.size() ? h.buttons : 0u);
    }
    loop.run_ticks(1);
    const HapticSnapshot& s = loop.snapshot();
    if (!s.device_connected) ++r.disconnected_ticks;
  }
  if (!options.record.empty()) loop.finish_recording();
  const HapticSnapshot& s = loop.snapshot();
  r.ticks = s.tick;
  r.max_force = s.max_force_output;
  r.safety_nonfinite = s.safety.nonfinite;
  if (replay) r.replay_mismatches = replay->mismatches();
  r.strokes = sketch.latest();
  std::vector<StrokeComponent> comps;
  for (StrokeComponent& c : stroke_components(r.strokes))
    if (c.points.size() >= 3) comps.push_back(std::move(c));
  r.link = link_from_strokes(comps, stroke_crossings(r.strokes), {});
  r.gauss = diagram_from_curve(r.link.curve, Frame<3>()).gauss_code();
  return r;
}

std::vector<HandSample> hand_from_stroke(const std::vector<Vec3>& samples, double dt, double rate, const Vec3& centre,
                                         const Vec2& fit) {
  if (samples.size() < 2) throw Error("a stroke needs at least 2 samples");
  if (!(dt > 0) || !(rate > 0) || !centre.allFinite() || !fit.allFinite() || !(fit.minCoeff() > 0))
    throw Error("stroke to hand: bad time step, rate or workspace");
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Vec3& q = samples[i];
    if (!q.allFinite()) throw Error("stroke sample " + std::to_string(i + 1) + " is not finite");
    if (q.z() != 0 && q.z() != 1 && q.z() != 2 && q.z() != -1)
      throw Error("stroke sample " + std::to_string(i + 1) + ": u must be 0 (draw), 1 (under), 2 (over) or -1 (pen up)");
    lo = lo.cwiseMin(q.head<2>());
    hi = hi.cwiseMax(q.head<2>());
  }
  const Vec2 half = 0.5 * (hi - lo);
  if (!(half.maxCoeff() > 0)) throw Error("the stroke has no extent");
  const double scale = std::min(fit.x() / std::max(half.x(), 1e-300), fit.y() / std::max(half.y(), 1e-300));
  const Vec2 mid = 0.5 * (lo + hi);
  auto at = [&](const Vec3& q) {
    const Vec2 p = centre.head<2>() + scale * (q.head<2>() - mid);
    return Vec3(p.x(), p.y(), centre.z());
  };
  auto buttons = [](double u) {
    if (u < 0) return 0u;
    return kSketchDraw | (u == 1 ? kSketchUnder : 0u) | (u == 2 ? kSketchOver : 0u);
  };
  std::vector<HandSample> out;
  const double step = 1.0 / rate;
  const double end = dt * static_cast<double>(samples.size() - 1);
  // Lead in: the hand rests at the first point, pen up, so the probe settles on the plane there.
  for (int k = 0; k < 800; ++k) out.push_back({at(samples[0]), 0u});
  for (double t = 0; t <= end; t += step) {
    const std::size_t i = std::min(static_cast<std::size_t>(t / dt), samples.size() - 2);
    const double f = std::clamp(t / dt - static_cast<double>(i), 0.0, 1.0);
    const Vec3 p = (1 - f) * at(samples[i]) + f * at(samples[i + 1]);
    out.push_back({p, buttons(samples[f < 0.5 ? i : i + 1].z())});
  }
  out.push_back({at(samples.back()), 0u});
  return out;
}

double sketch_plane_of_setup(const std::string& setup, double fallback) {
  std::istringstream in(setup);
  std::string word;
  in >> word;
  if (word != "sketch") return fallback;
  while (in >> word)
    if (word.rfind("plane_z=", 0) == 0) {
      try {
        const double z = std::stod(word.substr(8));
        return std::isfinite(z) ? z : fallback;
      } catch (const std::exception&) {
        return fallback;
      }
    }
  return fallback;
}

}  // namespace s4d
