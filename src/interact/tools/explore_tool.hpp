// ExploreTool (paper 5.3): press on a surface and move — a probe held to the surface's 3D shadow
// walks its own sheet through the shadow's self-intersections (it follows the 4D-continuous
// surface, not the visually nearer sheet); the hand feels the navigation spring (4.3.1) and hears
// a cue at every intersection curve passed, high above in w, low below. Release ends it.
// On a knot (4.3): press on a strand and move — the probe walks its strand of the image through
// every crossing, a cue over or under at each, and the Gauss code is built up as it goes.
#pragma once
#include <vector>

#include "haptics/haptic_scene.hpp"
#include "view/pick.hpp"
#include "interact/tools/tool.hpp"

namespace s4d {

class ExploreTool final : public Tool {
 public:
  const char* name() const override { return "Explore"; }
  std::string help() const override;
  DeviceButton device_button() const override { return DeviceButton::kExplore; }
  bool press(const ToolInput& in, Session& s) override;
  void drag(const ToolInput& in, Session& s) override;
  void release(const ToolInput& in, Session& s) override;
  void hover(const ToolInput& in, Session& s) override;
  void update(const ToolInput& in, Session& s) override;
  void overlay(Overlay& o, const Session& s) const override;

  // The passes heard so far in this exploration (for the panel and tests).
  const std::vector<SceneEvent>& passes() const { return passes_; }
  bool on_curve() const { return on_curve_; }
  // A knot's exploration: the Gauss code of the crossings passed so far ("1, -2, 3": + over).
  std::string gauss_so_far() const;
  // The window plays these as cues (taken once).
  std::vector<SceneEvent> take_new_passes() { return std::exchange(new_passes_, {}); }

 private:
  bool press_curve(const ToolInput& in, Session& s);
  void follow_device(const ToolInput& in, Session& s);
  bool begin(Session& s);
  void offer_image(const ToolInput& in, Session& s);

  bool exploring_ = false;
  bool by_device_ = false;  // the exploration was started by a device's button
  bool held_ = false;       // the left button is the tool's (pressed on something to explore)
  bool on_curve_ = false;
  double image_time_ = -1;  // the window's clock when the knot's image was last offered
  Camera image_camera_;
  Vec3 plane_point_ = Vec3::Zero();
  std::vector<SceneEvent> passes_, new_passes_;
};

}  // namespace s4d
