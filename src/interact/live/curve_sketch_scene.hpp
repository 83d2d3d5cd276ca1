// Sketching a knot or link by touch through the haptic loop (paper 4.1, 4.2, Fig. 4). The probe
// (a device, or the mouse's virtual-coupling proxy) is held to the sketch plane by the sticky
// stylus (Eq. 1-2); drawing, it feels the repulsion of Eq. 3 from every strand already there
// (this stroke's earlier part, earlier components, other curves of the scene, all in the plane's
// projection) and cannot cross one unless it holds an over/under choice: without it the stroke's
// head stops before the strand and slides along it, and the hand feels a wall spring pulling it
// back to the head. The head's path is smoothed by Dynadraw and resampled as it is drawn, in the
// tick, into buffers sized once. Closing near the start closes a component; a new press starts
// another (a link); Backspace takes back the last segment.
//
// Everything is in device coordinates (m): the plane is z = plane_z, the stroke lives in (x, y).
// CurveSketch is the loop-side engine; CurveSketchScene runs it as the loop's whole scene (an
// empty scene, a scene of curves, the headless `shadow4d knot sketch --device`), and the live
// simulation runs it as a mode (SketchHost) while the window's sketch tool is active.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "haptics/force_models.hpp"
#include "haptics/haptic_scene.hpp"
#include "haptics/triple_buffer.hpp"
#include "interact/live/handover.hpp"
#include "interact/live/live_requests.hpp"
#include "knots/dynadraw.hpp"
#include "knots/sketch_link.hpp"

namespace s4d {

// Device buttons while sketching (the mouse sends the left button and the window's modifiers the
// same way): draw while bit 0 is held; cross under with bit 1 (shift, or a device's second
// button), over with bit 2 (ctrl, or a third button); a press of bit 3 finishes (Enter).
inline constexpr std::uint32_t kSketchDraw = 1u << 0;
inline constexpr std::uint32_t kSketchUnder = 1u << 1;
inline constexpr std::uint32_t kSketchOver = 1u << 2;
inline constexpr std::uint32_t kSketchFinish = 1u << 3;

// The scene's other curves, seen in the plane (device x, y; depth is device z - plane z).
struct SketchStrands {
  std::vector<FixedStrand> strands;
};

struct SketchSettings {
  double sticky_h = 500;    // N/m^(1+beta), Eq. 1
  double sticky_beta = 0;
  double sticky_kd = 1.0;   // N s/m, Eq. 2 on the velocity along the plane's normal
  RepulsionParams repulsion{2e-6, 1.0, 1e-3, 1.5, 0.012};  // Eq. 3: N m^2, beta, m, N, m
  double wall_k = 600;         // N/m, pulls the hand back to a head held before a strand
  double wall_max = 3;         // N
  double margin = 1.5e-3;      // m, how far before a strand the head stops
  double spacing = 1.5e-3;     // m between the stroke's resampled points
  double close_radius = 5e-3;  // m, coming back this near the start closes the component
  double join_radius = 6e-3;   // m, a press this near an open component's end continues it
  double own_tail = 12e-3;     // m of the stroke just drawn that does not repel its own head
  DynadrawParams pen;          // the paper's Dynadraw pen on the head
};

// The probe's part of what the loop publishes (refreshed every publish).
struct SketchStatus {
  Vec3 probe = Vec3::Zero();     // m, the device (or mouse proxy)
  Vec3 target = Vec3::Zero();    // m, where the hand aims (the mouse cursor)
  Vec2 head = Vec2::Zero();      // m, the stroke's head (the probe, unless held before a strand)
  Vec2 pen = Vec2::Zero();       // m, the Dynadraw pen
  bool near = false;             // a strand within the repulsion's range
  Vec2 nearest = Vec2::Zero();   // m, its nearest point
  double distance = 0;           // m, S of Eq. 3
  double repulsion = 0;          // N, |F_r| now
  double wall = 0;               // N, the wall spring now
  double max_repulsion = 0;      // N, largest so far
  double max_lag_near = 0;       // m, largest probe-to-target lag while a strand was near
  std::uint64_t finish_requests = 0;  // presses of kSketchFinish
  std::uint64_t blocked_ticks = 0;    // ticks the head was held before a strand
  std::uint64_t crossings_refused = 0;  // times a move was stopped for want of a choice
  std::uint64_t full = 0;             // points dropped because the buffers were full
};

// What the loop publishes for the window and the headless run (sized once, copied without
// allocating). Points are the resampled stroke, component by component.
struct SketchPublished {
  static constexpr int kMaxPoints = 20000;
  static constexpr int kMaxComponents = 32;
  static constexpr int kMaxCrossings = 512;
  std::uint64_t revision = 0;    // bumps whenever the strokes change
  bool active = false;
  bool drawing = false;
  bool blocked = false;          // the head is held before a strand now
  double plane_z = 0;            // m
  int point_count = 0;
  int component_count = 0;
  int crossing_count = 0;
  std::vector<Vec2> points;              // point_count
  std::vector<CrossChoice> choices;      // point_count
  std::vector<int> component_begin;      // component_count + 1 (the last is point_count)
  std::vector<std::uint8_t> closed;      // component_count
  std::vector<StrokeCrossing> crossings; // crossing_count: where the head crossed with a choice
  SketchStatus status;           // the probe, now
  SketchPublished();
};

// The published strokes as the link builder takes them.
std::vector<StrokeComponent> stroke_components(const SketchPublished& p);
std::vector<StrokeCrossing> stroke_crossings(const SketchPublished& p);

class CurveSketch {
 public:
  explicit CurveSketch(const SketchSettings& settings = {});
  ~CurveSketch() { delete obstacles_; }
  CurveSketch(const CurveSketch&) = delete;
  CurveSketch& operator=(const CurveSketch&) = delete;

  // Loop thread (live::SketchBegin ... SketchClear).
  bool active() const { return active_; }
  void begin(double plane_z);  // m, device; the strokes so far are kept on the same plane
  void end();                  // stops sketching and forgets the strokes
  void backspace();            // removes the last segment (the one being drawn, or the last one drawn)
  void clear();                // forgets the strokes, keeps sketching
  ToolOutput step(const DeviceState& device, double dt);
  SketchSettings& settings() { return s_; }

  // UI thread (one reader): the latest published state. Thread-safe against the loop.
  const SketchPublished& latest() { return published_.read(); }
  // UI thread: the scene's other curves (the latest offer wins; the tick installs it).
  void offer_obstacles(std::unique_ptr<SketchStrands> o) { obstacles_in_.offer(std::move(o)); }

 private:
  struct Segment {
    int component = 0;
    int begin = 0;  // first point of the segment
    bool opened_component = false;  // the segment started its component
    bool closed_component = false;  // the segment closed it
  };
  template <typename F>
  void for_each_obstacle(F&& f) const;
  void begin_segment(const Vec2& at);
  void end_segment();
  void resample_to_pen(CrossChoice choice);
  void store(const Vec2& at, CrossChoice choice);
  void forget_strokes();
  void remove_last_segment();
  Vec2 move_head(const Vec2& from, const Vec2& to, CrossChoice choice);
  void publish(bool always);

  SketchSettings s_;
  bool active_ = false;
  double plane_z_ = 0;
  // The strokes (capacity fixed at construction; the tick never allocates).
  std::vector<Vec2> points_;
  std::vector<CrossChoice> choices_;
  std::vector<int> comp_begin_;
  std::vector<std::uint8_t> comp_closed_;
  std::vector<Segment> segments_;
  std::vector<StrokeCrossing> crossings_;
  std::vector<int> crossing_point_;  // points stored when each crossing was made
  int comps_ = 0;
  bool drawing_ = false, wait_release_ = false, blocked_ = false;
  bool left_start_ = false;  // the component being drawn went away from its start
  std::uint32_t buttons_ = 0;
  Vec2 head_ = Vec2::Zero();
  Dynadraw<2> pen_;
  double drawn_ = 0;  // m of the current component drawn (stored)
  SketchStrands* obstacles_ = nullptr;
  Handover<SketchStrands> obstacles_in_;
  TripleBuffer<SketchPublished> published_;
  SketchStatus status_;  // the probe's part, updated every tick
  std::uint64_t revision_ = 0, published_revision_ = ~0ull;
  int ticks_ = 0;
};

// A scene that lets a live simulation carry the sketch as a mode.
class SketchHost {
 public:
  virtual ~SketchHost() = default;
  virtual CurveSketch& curve_sketch() = 0;
};

// The sketch as the loop's whole scene (no simulation).
class CurveSketchScene final : public HapticScene, public SketchHost {
 public:
  enum Param { kH, kBeta, kKd, kRepulsionH, kRepulsionBeta, kRange, kWallK, kParamCount };
  explicit CurveSketchScene(const SketchSettings& settings = {});
  std::string_view name() const override { return "curve-sketch"; }
  ToolOutput step(const DeviceState& device, double dt) override;
  void reset() override { sketch_.clear(); }
  std::span<SceneParam> params() override { return params_; }
  void command(const SceneCommand& c) override;
  CurveSketch& curve_sketch() override { return sketch_; }

 private:
  CurveSketch sketch_;
  std::array<SceneParam, kParamCount> params_;
};

}  // namespace s4d
