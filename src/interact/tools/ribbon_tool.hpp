// RibbonTool (paper Fig. 8, 14): Create > Sketch a ribbon. The left button draws the ribbon's
// centre line on the plane facing the eye (the wheel moves that plane in depth; a device draws in
// 3D directly while its button is held); where it passes another surface's shadow it goes above
// in w, or below where shift is held. On release the ribbon is built (interact/ribbon_sketch;
// smoothed where the stroke is too rough for its width), checked to be embedded, added to the
// scene and the simulation restarts with it. A stroke that makes no ribbon is kept, drawn, with
// the reason: Enter tries it again (after [ ] or the Ribbon panel change the width), Esc drops it.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "interact/tools/ribbon_sketch.hpp"
#include "interact/tools/tool.hpp"

namespace s4d {

class RibbonTool final : public Tool {
 public:
  RibbonSketchOptions options;  // width (0: from the view's size), closed, across, ...
  RibbonTool() { options.width = 0; }

  const char* name() const override { return "Sketch a ribbon"; }
  std::string help() const override;
  bool press(const ToolInput& in, Session& s) override;
  void drag(const ToolInput& in, Session& s) override;
  void release(const ToolInput& in, Session& s) override;
  bool wheel(double steps, const ToolInput& in, Session& s) override;
  bool key(ToolKey k, const ToolInput& in, Session& s) override;
  void update(const ToolInput& in, Session& s) override;
  void overlay(Overlay& o, const Session& s) const override;

  bool drawing() const { return !stroke_.empty(); }
  // The last stroke that made no ribbon, kept for another try (empty: none).
  const std::vector<RibbonStrokeSample>& kept_stroke() const { return kept_.stroke; }
  // Builds the kept stroke's ribbon again with the options as they are now (Enter).
  bool retry(Session& s);
  void drop_kept();  // Esc
  // The width the last refusal named as one at which the stroke's ribbon lies flat (0: none).
  double suggested_width() const { return suggested_width_; }
  // Why the kept stroke made no ribbon: where, and what to change ("" when none is kept).
  const std::string& refusal() const { return refusal_; }
  // The width the last stroke was built with (the options', or the one taken from the view).
  double last_width() const { return last_width_; }
  // The ribbon made by the last stroke (its passages are drawn until the next one).
  const SketchedRibbon* last() const { return made_ ? &last_ : nullptr; }
  const std::vector<RibbonStrokeSample>& last_stroke() const { return last_stroke_; }
  // Builds the ribbon of a stroke and adds it to the session's scene (what release does; also
  // the headless path's). Returns false with the reason in the message when none can be made.
  bool finish(const std::vector<RibbonStrokeSample>& stroke, const Vec3& toward_eye, double view_size, Session& s);

 private:
  struct Attempt {
    std::vector<RibbonStrokeSample> stroke;
    Vec3 toward_eye = Vec3::UnitZ();
    double view_size = 1;
    bool came_back = false;  // a loop: decided once, so that a narrower retry stays one
  };
  void add(const Vec3& p, double time, bool under);
  bool build(const Attempt& a, Session& s);
  void set_width(double w, Session& s);

  std::vector<RibbonStrokeSample> stroke_, last_stroke_;
  double depth_ = 0;          // scene units toward the eye from the view's centre
  bool device_drawing_ = false;
  double t0_ = 0;
  SketchedRibbon last_;
  bool made_ = false;
  Attempt kept_;
  std::optional<Vec3> fold_at_;  // where the kept stroke's ribbon folds
  double suggested_width_ = 0, last_width_ = 0;
  std::string refusal_;
};

}  // namespace s4d
