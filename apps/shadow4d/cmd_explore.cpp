// `shadow4d explore INPUT (--through "x,y,z;..." | --device replay:FILE)`: the paper's multimodal
// exploration headless. A scripted hand (or a recorded trajectory) drags the probe over the surface's
// 3D shadow through the real haptic loop; the command prints each intersection curve the probe passed
// (above / below in w), whether it stayed on its sheet, and writes the events (CSV) and cues (WAV).
// For a knot (a scene of curves) the probe walks the curve's image in the view, through every
// crossing along its own strand (4.3.1), and the Gauss code is built up from the crossings passed
// (4.3.2); with no hand given, the hand traces the knot once round.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <vector>

#include "audio/cue_synth.hpp"
#include "audio/wav_file.hpp"
#include "command.hpp"
#include "core/error.hpp"
#include "haptics/device_spec.hpp"
#include "haptics/haptic_loop.hpp"
#include "haptics/replay_device.hpp"
#include "haptics/simulated_arm.hpp"
#include "interact/live/curve_explorer_scene.hpp"
#include "interact/live/surface_explorer_path.hpp"
#include "interact/live/surface_explorer_scene.hpp"
#include "interact/live/surface_explorer_sound.hpp"
#include "io/scene.hpp"
#include "knot_input.hpp"
#include "knots/knot_diagram.hpp"

namespace s4d::cli {
namespace {

struct ExploreArgs {
  std::string input;
  std::string rotate;
  std::string through;
  std::string device;
  double seconds = 0;  // 0: the path at 5 cm/s of hand motion, or the whole recording
  std::string events;
  std::string wav;
  bool depth_tone = false;
};

constexpr double kHandSpeed = 0.05;  // m/s, the scripted hand's default pace

// Every surface of the scene as one mesh (surfaces of R^3 at w = 0): the probe walks each, and the
// crossings between them are intersection curves of the one shadow.
Surface<4> scene_surface(const Scene& scene, int& pieces) {
  Surface<4> all;
  pieces = 0;
  for (const SceneObject& o : scene.objects) {
    Surface<4> s;
    if (const auto* s4 = std::get_if<Surface<4>>(&o.shape)) s = *s4;
    else if (const auto* s3 = std::get_if<Surface<3>>(&o.shape)) s = lift_to_4d(*s3);
    else continue;
    const int base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), s.vertices.begin(), s.vertices.end());
    for (Triangle t : s.triangles) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    ++pieces;
  }
  return all;
}

void write_events_csv(const std::string& path, const std::vector<ExplorerEvent>& events) {
  std::ofstream f(path);
  if (!f) throw Error("cannot create " + path);
  f << "time_s,side,triangle,other_triangle,x,y,z,w_self,w_other\n";
  char line[256];
  for (const ExplorerEvent& e : events) {
    std::snprintf(line, sizeof line, "%.6f,%s,%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g\n", e.time, e.above ? "above" : "below",
                  e.triangle, e.other, e.point[0], e.point[1], e.point[2], e.w_self, e.w_other);
    f << line;
  }
  f.close();
  if (!f) throw Error("writing " + path + " failed");
}

// The device for a scripted hand along `path` (shadow space) taking `seconds`, or a recording.
struct Hand {
  std::unique_ptr<Device> device;
  std::optional<PolylinePath> path;
  double rate = 1000;
  std::uint64_t ticks = 0;
};

Hand open_hand(const ExploreArgs& a) {
  Hand h;
  if (!a.through.empty()) {
    h.path.emplace(parse_point_list(a.through, "--through"));
    h.device = std::make_unique<SimulatedArm>();
    return h;
  }
  if (a.device.empty()) {
    h.device = std::make_unique<SimulatedArm>();
    return h;
  }
  const DeviceSpec spec = parse_device_spec(a.device);
  if (spec.kind != DeviceSpec::Kind::replay)
    throw Error("explore: --device takes replay:FILE (a recorded or generated trajectory); live devices "
                "explore in the window");
  h.device = make_device(spec);
  const Trajectory& tr = static_cast<ReplayDevice&>(*h.device).trajectory();
  if (tr.ticks.empty()) throw Error(spec.file + " holds no ticks");
  h.rate = tr.header.rate;
  h.ticks = tr.ticks.size();
  if (a.seconds > 0) h.ticks = std::min<std::uint64_t>(h.ticks, std::uint64_t(std::llround(a.seconds * h.rate)));
  return h;
}

// Starts the scripted hand at the path's start; returns that start (shadow space).
Vec3 script_hand(Hand& h, const DeviceMapping& mapping, double seconds) {
  auto& arm = static_cast<SimulatedArm&>(*h.device);
  h.ticks = static_cast<std::uint64_t>(std::llround(seconds * h.rate));
  arm.set_position(mapping.to_device(h.path->points().front()));
  arm.set_hand_script([p = *h.path, mapping, seconds](double t) { return mapping.to_device(p.at_time(t, seconds)); });
  return h.path->points().front();
}

void run_curve(const ExploreArgs& a, const std::string& input) {
  const Curve<3> curve = load_knot_curve(input);
  const Frame<3> view = parse_view(a.rotate);
  Hand hand = open_hand(a);
  // The image's box in the view's axes, fitted into the device's workspace with the same axes, so
  // the hand's right/up move along the image's x/y.
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = -lo;
  for (const auto& comp : curve.components)
    for (const Vec3& p : comp.points) {
      lo = lo.cwiseMin(view.to_view(p));
      hi = hi.cwiseMax(view.to_view(p));
    }
  const DeviceCapabilities caps = hand.device->capabilities();
  const Vec3 half = 0.5 * (caps.workspace_max - caps.workspace_min);
  const DeviceMapping mapping = DeviceMapping::fit(view.matrix() * (0.5 * (lo + hi)), 0.5 * (hi - lo).maxCoeff(),
                                                   view.matrix(), caps.workspace_centre(), 0.9 * half);
  auto scene = std::make_unique<CurveExplorerScene>(curve, view, mapping);
  CurveExplorerScene& ex = *scene;
  Vec3 start;
  if (hand.path || a.device.empty()) {
    if (!hand.path) {  // trace the first component once round, starting at its first point
      std::vector<Vec3> pts = curve.components[0].points;
      if (curve.components[0].closed) pts.push_back(pts.front());
      hand.path.emplace(std::move(pts));
    }
    const double seconds =
        a.seconds > 0 ? a.seconds : std::max(1.0, hand.path->length() * mapping.metres_per_unit / kHandSpeed);
    start = script_hand(hand, mapping, seconds);
  } else {
    start = mapping.to_shadow(static_cast<ReplayDevice&>(*hand.device).trajectory().ticks.front().state().position);
  }
  if (!ex.place(start)) throw Error("explore: cannot put the probe on " + input + " (is the curve finite?)");
  const int crossings = ex.navigation().explorer().crossing_count();
  std::printf("explore: %s (%zu component(s)), %d crossing(s) in this view; probe starts on component %d\n",
              input.c_str(), curve.components.size(), crossings, ex.navigation().explorer().probe().component);
  std::string code;
  try {
    code = diagram_from_curve(curve, view).gauss_code();
  } catch (const std::exception&) {  // an open curve or a touching one: no diagram to compare with
  }
  HapticLoopConfig cfg;
  cfg.rate_hz = hand.rate;
  cfg.realtime_priority = false;
  HapticLoop loop(std::move(hand.device), std::move(scene), cfg);
  std::vector<CueEvent> cues;
  std::vector<DepthSample> depth;
  std::ofstream csv;
  if (!a.events.empty()) {
    csv.open(a.events);
    if (!csv) throw Error("cannot write " + a.events);
    csv << "time,crossing,strand,x,y\n";
  }
  const double dmin = lo.z(), drange = std::max(1e-12, hi.z() - lo.z());
  int over = 0, under = 0;
  for (std::uint64_t i = 0; i < hand.ticks; ++i) {
    loop.run_ticks(1);
    while (auto e = ex.pop_event()) {
      (e->over ? over : under)++;
      std::printf("  %8.4f s  crossing %d  %s\n", e->time, e->label, e->over ? "over" : "under");
      cues.push_back({e->time, e->over ? CueKind::crossing_over : CueKind::crossing_under, 1.0f});
      if (csv) csv << e->time << "," << e->label << "," << (e->over ? "over" : "under") << "," << e->point[0] << ","
                   << e->point[1] << "\n";
    }
    if (a.depth_tone && i % 10 == 0)
      depth.push_back({ex.stats().time, (ex.navigation().explorer().probe_depth() - dmin) / drange});
  }
  const CurveExploreStats& st = ex.stats();
  const HapticSnapshot& snap = loop.snapshot();
  std::printf("summary: %d crossing(s) passed: %d over, %d under; stayed on its strand: %s; probe within %.4g of "
              "the hand (largest distance in the image, scene units)\n",
              over + under, over, under, st.left_component ? "NO" : "yes", st.max_distance);
  std::printf("  Gauss code of the passes: %s\n", ex.navigation().explorer().gauss_text().c_str());
  if (!code.empty())
    std::printf("  the knot's Gauss code in this view: %s (%s)\n", code.c_str(),
                code == ex.navigation().explorer().gauss_text() ? "the passes spell it exactly"
                                                                : "the passes so far are not one whole round of it");
  std::printf("  force: max %.3f N; safety %s (clamped %llu, non-finite %llu)\n", snap.max_force_output,
              safety_phase_name(snap.safety_phase), static_cast<unsigned long long>(snap.safety.clamped),
              static_cast<unsigned long long>(snap.safety.nonfinite));
  if (!a.events.empty()) std::printf("  events -> %s\n", a.events.c_str());
  if (!a.wav.empty()) {
    SynthSettings synth;
    synth.depth_tone = a.depth_tone;
    write_wav(a.wav, render_cues(cues, depth, st.time, synth), kAudioSampleRate);
    std::printf("  cues -> %s (%.2f s, %zu cue(s)%s)\n", a.wav.c_str(), st.time, cues.size(),
                a.depth_tone ? ", with the depth tone" : "");
  }
}

void run(const ExploreArgs& a) {
  {
    const Scene probe_scene = load_scene_or_object(a.input);
    const bool any_surface = std::any_of(probe_scene.objects.begin(), probe_scene.objects.end(),
                                         [](const SceneObject& o) { return is_surface(o.shape); });
    if (!any_surface && !probe_scene.objects.empty()) {
      if (!(a.seconds >= 0) || a.seconds > 3600) throw Error("--seconds must be in (0, 3600]");
      if (!a.through.empty() && !a.device.empty()) throw Error("explore: give --through or --device, not both");
      return run_curve(a, a.input);
    }
  }
  if (a.through.empty() == a.device.empty())
    throw Error("explore: give either --through \"x,y,z;x,y,z;...\" (a scripted hand) or --device replay:FILE");
  if (!(a.seconds >= 0) || a.seconds > 3600) throw Error("--seconds must be in (0, 3600]");
  Scene scene = load_scene_or_object(a.input);
  apply_rotations(scene.frame, parse_rotation_list(a.rotate, 4));
  int pieces = 0;
  const Surface<4> surface = scene_surface(scene, pieces);
  if (surface.triangles.empty())
    throw Error(a.input + " has no surface to explore (explore walks surfaces; knots have the knot commands)");

  // The device: a simulated arm held by the scripted hand, or a recording played tick by tick.
  std::unique_ptr<Device> device;
  std::optional<PolylinePath> path;
  double rate = 1000;
  std::uint64_t ticks = 0;
  if (!a.through.empty()) {
    path.emplace(parse_point_list(a.through, "--through"));
    device = std::make_unique<SimulatedArm>();
  } else {
    const DeviceSpec spec = parse_device_spec(a.device);
    if (spec.kind != DeviceSpec::Kind::replay)
      throw Error("explore: --device takes replay:FILE (a recorded or generated trajectory); live devices "
                  "explore in the window");
    device = make_device(spec);
    const Trajectory& tr = static_cast<ReplayDevice&>(*device).trajectory();
    if (tr.ticks.empty()) throw Error(spec.file + " holds no ticks");
    rate = tr.header.rate;
    ticks = tr.ticks.size();
    if (a.seconds > 0) ticks = std::min<std::uint64_t>(ticks, std::uint64_t(std::llround(a.seconds * rate)));
  }
  Vec3 lo, hi;
  shadow_box(surface.vertices, scene.frame, lo, hi);
  const DeviceMapping mapping = fit_shadow_box(lo, hi, device->capabilities());
  auto explore = std::make_unique<SurfaceExplorerScene>(surface, scene.frame, mapping);
  SurfaceExplorerScene& ex = *explore;

  Vec3 start;
  if (path) {
    const double seconds =
        a.seconds > 0 ? a.seconds : std::max(1.0, path->length() * mapping.metres_per_unit / kHandSpeed);
    ticks = static_cast<std::uint64_t>(std::llround(seconds * rate));
    auto& arm = static_cast<SimulatedArm&>(*device);
    start = path->points().front();
    arm.set_position(mapping.to_device(start));
    arm.set_hand_script([p = *path, mapping, seconds](double t) { return mapping.to_device(p.at_time(t, seconds)); });
  } else {
    const Trajectory& tr = static_cast<ReplayDevice&>(*device).trajectory();
    start = mapping.to_shadow(tr.ticks.front().state().position);
  }
  if (!ex.place(start)) throw Error("explore: no usable triangle to put the probe on (is the surface finite?)");
  const int start_triangle = ex.explorer().probe().triangle;
  const CrossingTable& table = ex.explorer().crossings();

  std::printf("explore: %s (%d triangles, %d piece(s) of mesh), %d shadow intersection segment(s) in this view; "
              "shadow box (%.3g, %.3g, %.3g) to (%.3g, %.3g, %.3g)\n",
              a.input.c_str(), ex.explorer().triangle_count(), ex.explorer().component_count(), table.segments,
              lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z());
  if (table.coplanar_pairs > 0)
    std::printf("  note: the view is not generic (%d triangle pair(s) of the shadow overlap in area, where no "
                "crossing is found): turn it, e.g. --rotate xw=30,yw=20\n",
                table.coplanar_pairs);
  std::printf("  device %s at %.0f Hz for %.3f s; %.4g m of device motion per scene unit; probe starts on "
              "triangle %d at (%.4g, %.4g, %.4g)\n",
              std::string(device->name()).c_str(), rate, ticks / rate, mapping.metres_per_unit, start_triangle,
              start.x(), start.y(), start.z());

  HapticLoopConfig cfg;
  cfg.rate_hz = rate;
  cfg.realtime_priority = false;
  HapticLoop loop(std::move(device), std::move(explore), cfg);
  std::vector<ExplorerEvent> events;
  std::vector<double> tick_us;
  tick_us.reserve(ticks);
  for (std::uint64_t i = 0; i < ticks; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    loop.run_ticks(1);
    tick_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    while (auto e = ex.pop_event()) {
      events.push_back(*e);
      std::printf("  %8.4f s  %-5s  triangle %d %s %d (w %.4g %s %.4g) at (%.4g, %.4g, %.4g)\n", e->time,
                  e->above ? "above" : "below", e->triangle, e->above ? "over" : "under", e->other, e->w_self,
                  e->above ? ">" : "<", e->w_other, e->point[0], e->point[1], e->point[2]);
    }
  }
  const ExploreStats& st = ex.stats();
  const ExplorerCounters& c = ex.explorer().counters();
  const HapticSnapshot& snap = loop.snapshot();
  const auto above = std::count_if(events.begin(), events.end(), [](const ExplorerEvent& e) { return e.above; });
  const bool stayed = !st.left_component;
  std::printf("summary: %zu crossing(s): %ld above, %ld below; probe within %.4g of the device point (largest "
              "distance, scene units); stayed on its sheet: %s (%llu mesh edge(s) walked, placed %llu time(s)%s)\n",
              events.size(), long(above), long(events.size() - above), st.max_distance, stayed ? "yes" : "NO",
              static_cast<unsigned long long>(c.edges_walked), static_cast<unsigned long long>(c.placements),
              stayed ? ", never left its piece of mesh" : ", it left its piece of mesh");
  std::printf("  probe ends on triangle %d at (%.4g, %.4g, %.4g), w %.4g; boundary stops %llu, fold stops %llu, "
              "edge-on passes %llu, rejected device inputs %llu, events dropped %llu\n",
              ex.explorer().probe().triangle, st.probe.x(), st.probe.y(), st.probe.z(), st.probe_w,
              static_cast<unsigned long long>(c.boundary_stops), static_cast<unsigned long long>(c.ridge_stops),
              static_cast<unsigned long long>(c.degenerate_passes),
              static_cast<unsigned long long>(c.rejected_inputs), static_cast<unsigned long long>(c.events_dropped));
  std::printf("  force: max %.3f N; safety %s (clamped %llu, non-finite %llu)\n", snap.max_force_output,
              safety_phase_name(snap.safety_phase), static_cast<unsigned long long>(snap.safety.clamped),
              static_cast<unsigned long long>(snap.safety.nonfinite));
  if (!tick_us.empty()) {
    std::vector<double> sorted = tick_us;
    std::sort(sorted.begin(), sorted.end());
    double mean = 0;
    for (double t : tick_us) mean += t / tick_us.size();
    const std::size_t worst = std::max_element(tick_us.begin(), tick_us.end()) - tick_us.begin();
    std::printf("  tick (device model + explorer + safety): mean %.2f us, p50 %.2f us, p99 %.2f us, max %.1f us "
                "(tick %zu)\n",
                mean, sorted[sorted.size() / 2], sorted[std::min(sorted.size() - 1, sorted.size() * 99 / 100)],
                sorted.back(), worst);
  }
  if (!a.events.empty()) {
    write_events_csv(a.events, events);
    std::printf("  events -> %s\n", a.events.c_str());
  }
  if (!a.wav.empty()) {
    const std::vector<CueEvent> cues = explore_cues(events);
    const std::vector<float> pcm = render_cues(cues, {}, st.time, {});
    write_wav(a.wav, pcm, kAudioSampleRate);
    std::printf("  cues -> %s (%.2f s, %zu cue(s))\n", a.wav.c_str(), st.time, cues.size());
  }
}

const CommandRegistrar kExplore(
    "explore",
    "drag a probe over a surface's 3D shadow, or along a knot's image, through the haptic loop: it stays "
    "on its sheet (strand) across the shadow's intersection curves (crossings) and reports each pass "
    "(above/below in w, over/under) with sound cues; for a knot the Gauss code is built up as it goes",
    [](CLI::App& sub) {
      auto a = std::make_shared<ExploreArgs>();
      sub.add_option("input", a->input, "scene .json, mesh .4off/.off, or a generator call (spun-trefoil:n=48)")
          ->required();
      sub.add_option("--rotate", a->rotate,
                     "rotations of the 4D view, degrees, in order, e.g. xw=30,yw=20 (planes xy xz xw yz yw zw)");
      sub.add_option("--through", a->through,
                     "the scripted hand's path in shadow space (scene units), \"x,y,z;x,y,z;...\", walked at a "
                     "steady speed");
      sub.add_option("--device", a->device, "replay:FILE, a recorded or generated device trajectory");
      sub.add_option("--seconds", a->seconds,
                     "how long the hand takes along --through (default: 5 cm/s of device motion), or how much "
                     "of a recording to play (default: all)");
      sub.add_option("--events", a->events, "write the crossing events to this CSV file");
      sub.add_option("--wav", a->wav, "write the sound cues of the events to this WAV file (16-bit mono)");
      sub.add_flag("--depth-tone", a->depth_tone,
                   "knots: add to the WAV a continuous tone whose pitch follows the probe's depth");
      sub.callback([a] { run(*a); });
    });

}  // namespace
}  // namespace s4d::cli
