// A scenario's steps drawn where they are to be done: a numbered marker on what to take (the live
// centre of its vertices), a target where it should go, an arrow between them; the next step not
// yet done is lit, and Show me runs a ghost of the motion along its arrow. Built from the
// scenario's hints (scenario.hpp) once the simulation has its first state.
#pragma once
#include <string>
#include <vector>

#include "app/layout.hpp"
#include "core/camera.hpp"
#include "core/vec.hpp"

namespace s4d {

struct GuiModel;

class HintMarkers {
 public:
  // Each frame: resolves the hints of a newly opened scenario, notes which are done, says in the
  // model what Show me would show, and starts a ghost when it was asked for.
  void update(GuiModel& model, double time);
  // Draws the markers, targets, arrows and the ghost into the view.
  void draw(const GuiModel& model, const Camera& camera, const Rect& view, double time) const;

  struct Step {
    std::vector<int> vertices;  // world vertices taken
    Vec4 target = Vec4::Zero();  // world (R^3 worlds: w = 0)
    Vec4 start = Vec4::Zero();   // their centre when the step's turn came (see anchored)
    std::string say;
    bool done = false;
    // A step's motion is from where its marker is when its turn comes, as a script's move is
    // from where its vertices are when it starts: until then start and target follow the marker
    // (an earlier step's patch may carry it). The turn comes when every earlier step is done and
    // the hand holds nothing, or when the hand takes one of the step's vertices.
    bool anchored = false;
  };
  const std::vector<Step>& steps() const { return steps_; }
  // The marker drawn under `cursor` (window pixels), or -1: a press there takes the marked sheet.
  int marker_under(const GuiModel& model, const Camera& camera, const Rect& view, const Vec2& cursor) const;
  // The view depth (w through the 4D frame) of a step's vertices now; NaN in R^3.
  double marked_w(const GuiModel& model, int step) const;
  int next() const;  // the first step not done, or -1
  // Where a world point is in the shadow (the view's 3D space).
  static Vec3 shadow_of(const GuiModel& model, const Vec4& world);
  Vec4 centre(const GuiModel& model, const Step& s) const;  // the live centre of its vertices

 private:
  std::string resolved_for_;  // the scenario file the steps are of
  std::vector<Step> steps_;
  int dim_ = 4;
  double ghost_start_ = -1;  // the time Show me began its ghost (s), -1: none
  int ghost_step_ = -1;
};

}  // namespace s4d
