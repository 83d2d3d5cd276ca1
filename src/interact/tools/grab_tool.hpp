// GrabTool (paper 5.1.4, Fig. 7; for knots Fig. 2): left-drag on a surface, or on a strand of a
// simulated curve, holds the vertex under the cursor on a rubber band that the haptic loop
// renders; Alt drags it along the shadow ray instead (w, or a knot's depth: its shadow stays); Tab
// picks the next sheet or strand under the cursor; P or a right click pins and unpins; the wheel
// moves the hand in depth while holding. On empty space the drag turns the view as usual.
// With carry on (C; [ and ] size it), the drag carries the patch around the vertex instead: it
// follows the hand and stays held where it is let go (the local deformations of Fig. 12).
#pragma once
#include <limits>
#include <optional>
#include <vector>

#include "view/pick.hpp"
#include "interact/live/live_requests.hpp"
#include "interact/tools/tool.hpp"

namespace s4d {

class GrabTool final : public Tool {
 public:
  const char* name() const override { return "Touch"; }
  std::string help() const override;
  DeviceButton device_button() const override { return DeviceButton::kGrab; }
  double device_carry_radius() const override { return carry_ ? carry_radius_ : 0; }
  bool press(const ToolInput& in, Session& s) override;
  void drag(const ToolInput& in, Session& s) override;
  void release(const ToolInput& in, Session& s) override;
  void hover(const ToolInput& in, Session& s) override;
  bool right_click(const ToolInput& in, Session& s) override;
  bool key(ToolKey k, const ToolInput& in, Session& s) override;
  bool wheel(double steps, const ToolInput& in, Session& s) override;
  void overlay(Overlay& o, const Session& s) const override;

  // The sheets under the cursor at the last hover, and the one a press would take.
  const std::vector<SheetHit>& hits() const { return hits_; }
  int sheet() const { return sheet_; }

  // Carrying a patch (true) or pulling one vertex on the band; the patch's radius along the
  // surface, in scene units (clamped to [kMinCarryRadius, kMaxCarryRadius]).
  bool carry() const { return carry_; }
  double carry_radius() const { return carry_radius_; }
  void set_carry(bool on) { carry_ = on; }
  void set_carry_radius(double r);
  // The next hover takes the sheet under the cursor nearest this depth in w, as Tab would (an
  // input script pointing at a vertex means that vertex's sheet).
  void prefer_depth(double w) { preferred_w_ = w; }
  // A handle under the cursor (a scenario's marker): taken by the next hover when no sheet is hit
  // there (a ribbon's thin end seen edge on), as a press on the marker takes what it marks.
  void offer_handle(const SheetHit& h) { handle_ = h; }
  static constexpr double kMinCarryRadius = 0.01, kMaxCarryRadius = 10;

 private:
  // The world vertex of hit h, or -1.
  static int world_vertex(const SheetHit& h, const Session& s);
  // The sheets, and the simulated curves' strands, under the cursor, nearest the eye first.
  static std::vector<SheetHit> pick(const ToolInput& in, const Session& s);
  static constexpr double kStrandPixels = 10;  // how near the cursor a strand is taken
  void toggle_pin_under_cursor(Session& s);

  std::vector<SheetHit> hits_;
  int sheet_ = 0;
  Vec2 tab_cursor_ = Vec2::Constant(-1e9);  // where Tab was last pressed
  bool holding_ = false;
  bool along_w_ = false;
  live::GrabMode grab_mode() const { return along_w_ ? live::GrabMode::kAlongRay : live::GrabMode::kShadow; }
  bool carry_ = false;
  double carry_radius_ = 0.5;
  Vec3 plane_point_ = Vec3::Zero();  // the drag plane passes through it, facing the eye
  Vec3 hand_ = Vec3::Zero();
  Vec3 right_ = Vec3::UnitX(), up_ = Vec3::UnitY();  // the view's axes at the last hover
  std::optional<SheetHit> handle_;
  double preferred_w_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace s4d
