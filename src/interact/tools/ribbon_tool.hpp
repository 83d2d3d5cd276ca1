// RibbonTool (paper Fig. 8, 14): Create > Sketch a ribbon. The left button draws the ribbon's
// centre line on the plane facing the eye (the wheel moves that plane in depth; a device draws in
// 3D directly while its button is held); where it passes another surface's shadow it goes above
// in w, or below where shift is held. On release the ribbon is built (interact/ribbon_sketch),
// checked to be embedded, added to the scene and the simulation restarts with it.
#pragma once
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
  // The ribbon made by the last stroke (its passages are drawn until the next one).
  const SketchedRibbon* last() const { return made_ ? &last_ : nullptr; }
  const std::vector<RibbonStrokeSample>& last_stroke() const { return last_stroke_; }
  // Builds the ribbon of a stroke and adds it to the session's scene (what release does; also
  // the headless path's). Returns false with the reason in the message when none can be made.
  bool finish(const std::vector<RibbonStrokeSample>& stroke, const Vec3& toward_eye, double view_size, Session& s);

 private:
  void add(const Vec3& p, double time, bool under);

  std::vector<RibbonStrokeSample> stroke_, last_stroke_;
  double depth_ = 0;          // scene units toward the eye from the view's centre
  bool device_drawing_ = false;
  double t0_ = 0;
  SketchedRibbon last_;
  bool made_ = false;
};

}  // namespace s4d
