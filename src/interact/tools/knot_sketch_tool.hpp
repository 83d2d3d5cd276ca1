// The window's knot sketching (Create > Sketch a knot; the paper's section 4.2): the left button
// draws in the plane through the view's centre that faces the eye, shift held where the stroke
// should pass under what is already drawn; on release the stroke becomes a knot of R^3
// (knot_from_sketch), exactly where it was drawn. `shadow4d knot sketch FILE --knot` makes the
// same knot from a recorded stroke.
#pragma once
#include <vector>

#include "core/camera.hpp"
#include "interact/tools/tool.hpp"
#include "interact/live/curve_sketch_scene.hpp"
#include "knots/sketch.hpp"

namespace s4d {

// The sketch plane of a view: through camera.target, spanned by the camera's right and up axes.
struct SketchPlane {
  Vec3 centre = Vec3::Zero(), right = Vec3::UnitX(), up = Vec3::UnitY(), toward_eye = Vec3::UnitZ();
  explicit SketchPlane(const Camera& camera);
  SketchPlane() = default;
  // Where the line of sight through `cursor` (window pixels, y down, in a window of `window`
  // pixels) meets the plane, in (right, up) coordinates; false when it does not (parallel, or
  // behind the eye).
  bool cursor_to_plane(const Camera& camera, const Vec2& cursor, const Vec2& window, Vec2& at) const;
  // A point given as (right, up, toward the eye) coordinates, in shadow space.
  Vec3 to_shadow(const Vec3& local) const { return centre + local.x() * right + local.y() * up + local.z() * toward_eye; }
};

// The stroke itself, in window pixels mapped onto the sketch plane of the stroke's camera.
class SketchTool {
 public:
  bool drawing() const { return !stroke_.empty(); }
  // Starts a stroke under the cursor, in the plane of `camera`'s view.
  void begin(const Camera& camera, const Vec2& cursor, const Vec2& window, double time, bool under);
  // The next cursor sample (the camera of the stroke's start is kept: the view may refit as the
  // scene grows, the plane does not move).
  void add(const Vec2& cursor, const Vec2& window, double time, bool under);
  // The cursor samples so far, in window pixels, with their modifier, for drawing the stroke.
  const std::vector<std::pair<Vec2, bool>>& screen() const { return screen_; }
  // Ends the stroke: its knot as a curve of R^3, where it was drawn. Throws s4d::Error for a bad
  // stroke.
  Curve<3> finish();
  void cancel();
  // The last stroke finished (even one that made no knot), for File > Save last sketch stroke.
  const std::vector<SketchSample>& last_stroke() const { return last_; }

 private:
  std::vector<SketchSample> last_;
  Camera camera_;
  SketchPlane plane_;
  std::vector<SketchSample> stroke_;
  std::vector<std::pair<Vec2, bool>> screen_;
};

// The knot sketch by the cursor alone, without the haptic loop: press, drag and release draw
// one stroke; shift held where it passes under; the knot joins the scene. (The soak and tablet
// strokes use it; the window sketches through the loop with KnotSketchTool.)
class CursorKnotSketchTool final : public Tool {
 public:
  const char* name() const override { return "Sketch a knot (cursor)"; }
  std::string help() const override;
  bool press(const ToolInput& in, Session& s) override;
  void drag(const ToolInput& in, Session& s) override;
  void release(const ToolInput& in, Session& s) override;
  bool key(ToolKey k, const ToolInput& in, Session& s) override;
  void overlay(Overlay& o, const Session& s) const override;
  // The last stroke finished, as the curve File > Save last sketch stroke writes (x y u).
  Curve<3> last_stroke_curve() const { return stroke_as_curve(stroke_.last_stroke()); }
  bool has_last_stroke() const { return !stroke_.last_stroke().empty(); }
  const SketchTool& stroke() const { return stroke_; }

 private:
  SketchTool stroke_;
};

// The knot sketch by touch (Create > Sketch a knot, K; paper 4.1-4.2, Fig. 4), through the haptic
// loop's sketch (interact/live/curve_sketch_scene.hpp): the mouse's proxy, or a device, draws in the
// plane through the view's centre facing the eye, held there by the sticky stylus; near a strand
// it is repelled (the proxy lags, the strand glows) and it crosses only with shift (under) or
// ctrl (over) held — a device's second / third button. Closing near the start closes a component,
// a new press starts another, Backspace takes back the last segment, Enter (or a device's fourth
// button) finishes: the knot or link joins the scene as sketch-N, named in the Knot panel.
class KnotSketchTool final : public Tool {
 public:
  const char* name() const override { return "Sketch a knot"; }
  std::string help() const override;
  bool press(const ToolInput& in, Session& s) override;
  void drag(const ToolInput& in, Session& s) override;
  void release(const ToolInput& in, Session& s) override;
  void hover(const ToolInput& in, Session& s) override;
  bool key(ToolKey k, const ToolInput& in, Session& s) override;
  void update(const ToolInput& in, Session& s) override;
  void overlay(Overlay& o, const Session& s) const override;
  // The window chose another tool: the loop stops sketching (strokes not finished are dropped).
  void leave(Session& s);
  // Strokes are drawn and not finished: the view's device mapping must hold still.
  bool busy() const { return last_.point_count > 0; }
  // Makes the knot or link of the strokes so far and adds it to the scene; false (with the
  // reason in the message) when there is nothing to make.
  bool finish(Session& s);

  // The last sketch's first component, as File > Save last sketch stroke writes it (x y u, u = 1
  // where it was drawn passing under).
  Curve<3> last_stroke_curve() const { return last_stroke_; }
  bool has_last_stroke() const { return !last_stroke_.components.empty(); }
  // What the loop published last (strokes, probe, repulsion), as the window read it.
  const SketchPublished& published() const { return last_; }
  const std::string& last_gauss() const { return last_gauss_; }
  const std::string& last_name() const { return last_name_; }

 private:
  void hand(const ToolInput& in, Session& s, bool down);
  void offer_obstacles(Session& s);

  SketchPublished last_;
  std::vector<FixedStrand> fixed_;  // the scene's other curves in the plane, as offered
  std::uint64_t finish_seen_ = 0;
  bool begun_ = false;
  Curve<3> last_stroke_;
  std::string last_gauss_, last_name_;
};

}  // namespace s4d
