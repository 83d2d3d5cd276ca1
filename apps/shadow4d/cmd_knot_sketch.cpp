// `knot sketch`: a sketched stroke smoothed with Dynadraw as the sketch tool does, made into its
// knot (--knot), or drawn by touch through the haptic loop (--device), headless.
#include <iostream>
#include <memory>

#include "core/error.hpp"
#include "haptics/device_spec.hpp"
#include "haptics/replay_device.hpp"
#include "haptics/simulated_arm.hpp"
#include "interact/live/touch_sketch_run.hpp"
#include "io/object_file.hpp"
#include "knot_commands.hpp"
#include "knot_input.hpp"
#include "knots/dynadraw.hpp"
#include "knots/sketch.hpp"

namespace s4d::cli {

using nlohmann::json;

namespace {

// `knot sketch --device replay:T | sim [FILE]`: the touch sketch through the loop, headless.
void sketch_by_touch(const std::string& device_spec, const std::string& stroke, const std::string& out,
                     const std::string& record, double dt, bool as_json) {
  const DeviceSpec spec = parse_device_spec(device_spec);
  TouchSketchOptions o;
  o.record = record;
  std::unique_ptr<Device> device;
  std::vector<HandSample> hand;
  if (spec.kind == DeviceSpec::Kind::replay) {
    if (!stroke.empty()) throw Error("knot sketch --device replay:FILE takes no stroke file (the trajectory is the hand)");
    Trajectory t = read_trajectory(spec.file);
    o.plane_z = sketch_plane_of_setup(t.header.setup, t.header.caps.workspace_centre().z());
    const bool compare = t.header.scene == "curve-sketch";
    device = std::make_unique<ReplayDevice>(std::move(t), compare);
  } else if (spec.kind == DeviceSpec::Kind::sim) {
    if (stroke.empty()) throw Error("knot sketch --device sim needs a stroke FILE for the hand to follow");
    auto arm = std::make_unique<SimulatedArm>();
    const DeviceCapabilities& caps = arm->capabilities();
    const Vec3 half = 0.5 * (caps.workspace_max - caps.workspace_min);
    o.plane_z = caps.workspace_centre().z();
    const Curve<3> raw = load_knot_curve(stroke);
    hand = hand_from_stroke(raw.components[0].points, dt, 1000, caps.workspace_centre(),
                            0.8 * Vec2(half.x(), half.y()));
    device = std::move(arm);
  } else {
    throw Error("knot sketch --device takes replay:FILE or sim (the window sketches with the mouse and the others)");
  }
  const TouchSketchResult r = run_touch_sketch(std::move(device), hand, o);
  Curve<3> curve = r.link.curve;
  constexpr double kUnit = 0.05;  // m of the device per unit written
  for (Polyline<3>& p : curve.components)
    for (Vec3& q : p.points) q /= kUnit;
  if (!out.empty()) write_shape_file(curve, out);
  const KnotNaming id = name_knot(curve);
  if (as_json) {
    std::cout << json{{"components", curve.components.size()}, {"points", curve.point_count()},
                      {"crossings", r.link.crossings}, {"gauss", r.gauss}, {"name", id.name()},
                      {"proven", id.proven()}, {"ticks", r.ticks},
                      {"crossings_refused", r.strokes.status.crossings_refused},
                      {"blocked_ticks", r.strokes.status.blocked_ticks},
                      {"max_repulsion", r.strokes.status.max_repulsion}, {"max_force", r.max_force},
                      {"replay_mismatches", r.replay_mismatches}, {"disconnected_ticks", r.disconnected_ticks}}
                     .dump(2)
              << "\n";
    return;
  }
  std::cout << "sketched by touch (" << device_spec << ", " << r.ticks << " ticks): " << curve.components.size()
            << " component(s), " << r.link.crossings << " crossing(s)\n"
            << "Gauss code: " << (r.gauss.empty() ? "(no crossings)" : r.gauss) << "\n"
            << "name: " << id.headline() << "\n"
            << "strands refused without a choice: " << r.strokes.status.crossings_refused
            << ", largest repulsion " << r.strokes.status.max_repulsion << " N, largest force sent " << r.max_force
            << " N\n";
  if (r.disconnected_ticks) std::cout << "device gone for " << r.disconnected_ticks << " ticks (nothing lost)\n";
  if (!out.empty()) std::cout << "wrote " << out << "\n";
  if (!record.empty()) std::cout << "recorded " << record << " (replay: shadow4d knot sketch --device replay:" << record << ")\n";
}

// A sketched stroke (cursor samples, one per line, as the GUI's sketch tool or a tablet records
// them) smoothed the way the sketching tool does it, or with --knot made into its knot, so a
// sketch can be reproduced and inspected headless.
struct SketchArgs {
  std::string in, out, device, record;
  double dt = 1.0 / 120.0;
  DynadrawParams pen;
  bool json_out = false, knot = false;
};

void sketch_knot(const SketchArgs& a, const Curve<3>& raw) {
  SketchOptions o;
  o.pen = a.pen;
  const SketchedKnot k = knot_from_sketch(stroke_from_curve(raw, a.dt), o);
  write_shape_file(k.curve, a.out);
  const KnotNaming id = name_knot(k.curve);
  if (a.json_out)
    std::cout << json{{"points", k.curve.point_count()}, {"crossings", k.crossings},
                      {"gauss", diagram_from_curve(k.curve, Frame<3>()).gauss_code()},
                      {"name", id.name()}, {"proven", id.proven()}}.dump(2) << "\n";
  else
    std::cout << "sketched a knot of " << k.curve.point_count() << " points, " << k.crossings
              << " crossing(s): " << id.headline() << "; wrote " << a.out << "\n";
}

void sketch(const SketchArgs& a) {
  if (!a.device.empty()) {
    sketch_by_touch(a.device, a.in, a.out, a.record, a.dt, a.json_out);
    return;
  }
  if (a.in.empty() || a.out.empty()) throw Error("knot sketch needs a stroke FILE and --out (or --device)");
  const Curve<3> raw = load_knot_curve(a.in);
  if (a.knot) return sketch_knot(a, raw);
  Curve<3> smooth;
  for (const auto& comp : raw.components) {
    Polyline<3> p;
    p.closed = comp.closed;
    p.points = dynadraw_stroke<3>(comp.points, a.dt, a.pen, /*settle_steps=*/0);
    smooth.components.push_back(std::move(p));
  }
  write_shape_file(smooth, a.out);
  if (a.json_out)
    std::cout << json{{"points", smooth.point_count()}, {"length_before", raw.length()},
                      {"length_after", smooth.length()}}.dump(2) << "\n";
  else
    std::cout << "smoothed " << smooth.point_count() << " samples: length " << raw.length() << " -> "
              << smooth.length() << "; wrote " << a.out << "\n";
}

}  // namespace

void add_knot_sketch(CLI::App& knot) {
  auto a = std::make_shared<SketchArgs>();
  auto* s = knot.add_subcommand("sketch", "smooth a raw sketched stroke with Dynadraw (Haeberli)");
  s->add_option("file", a->in, "stroke: a curve file of cursor samples (with --device sim: the hand's path)");
  s->add_option("--out", a->out, "where to write the smoothed curve (the knot, with --knot or --device)");
  s->add_option("--device", a->device,
                "sketch by touch through the haptic loop: replay:TRAJECTORY (a recorded device), or sim "
                "(the simulated arm's hand follows FILE: x y u, u = 0 draw, 1 cross under, 2 cross over, "
                "-1 pen up); the knot is written in units of 5 cm of the device");
  s->add_option("--record", a->record, "with --device: record the device trajectory (for replay:FILE)");
  s->add_option("--dt", a->dt, "seconds between samples")->capture_default_str()->check(CLI::Range(1e-5, 1.0));
  s->add_option("--mass", a->pen.mass, "pen mass, kg")->capture_default_str()->check(CLI::Range(1e-6, 1e6));
  s->add_option("--stiffness", a->pen.stiffness, "spring to the cursor, N/m")
      ->capture_default_str()
      ->check(CLI::Range(1e-6, 1e9));
  s->add_option("--damping", a->pen.damping, "drag, N s/m")->capture_default_str()->check(CLI::Range(0.0, 1e9));
  s->add_flag("--json", a->json_out, "machine-readable output");
  s->add_flag("--knot", a->knot,
              "make the closed knot the GUI's sketch tool makes: samples are x y u, u = 1 where "
              "the stroke passes under (the modifier held), 0 where it passes over");
  s->callback([a] { sketch(*a); });
}

}  // namespace s4d::cli
