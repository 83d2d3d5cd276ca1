// GrabTool (paper 5.1.4, Fig. 7; for knots Fig. 2): left-drag on a surface, or on a strand of a
// simulated curve, holds the vertex under the cursor on a rubber band that the haptic loop
// renders; Alt drags it along the shadow ray instead (w, or a knot's depth: its shadow stays); Tab
// picks the next sheet or strand under the cursor; P or a right click pins and unpins; the wheel
// moves the hand in depth while holding. On empty space the drag turns the view as usual.
// With carry on (C; [ and ] size it), the drag carries the patch around the vertex instead: the
// vertices within so many rings of mesh edges of it (physics/patch.hpp), never another sheet that
// the shadow folds onto it; it follows the hand and stays held where it is let go (the local
// deformations of Fig. 12). A press takes the sheet nearest the eye under the cursor, the same one
// every time at the same pixel, unless Tab chose a deeper one there for it.
#pragma once
#include <limits>
#include <optional>
#include <vector>

#include "physics/patch.hpp"
#include "view/pick.hpp"
#include "interact/live/live_requests.hpp"
#include "interact/tools/tool.hpp"

namespace s4d {

class GrabTool final : public Tool {
 public:
  const char* name() const override { return "Touch"; }
  std::string help() const override;
  DeviceButton device_button() const override { return DeviceButton::kGrab; }
  int device_carry_rings() const override { return carry_ ? carry_rings_ : 0; }
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

  // Carrying a patch (true) or pulling one vertex on the band; the patch's size in rings of mesh
  // edges around the vertex (clamped to [kMinCarryRings, kMaxCarryRings]).
  bool carry() const { return carry_; }
  int carry_rings() const { return carry_rings_; }
  void set_carry(bool on) { carry_ = on; }
  void set_carry_rings(int rings);
  // The patch a press would carry now (world vertices, their weights), empty when none.
  const Patch& patch_preview() const { return preview_; }
  // The next hover takes the sheet under the cursor nearest this depth in w, as Tab would (an
  // input script pointing at a vertex means that vertex's sheet).
  void prefer_depth(double w) { preferred_w_ = w; }
  // A handle under the cursor (a scenario's marker): the next hover puts it first, so that a
  // press on the marker takes the vertex it marks, not a sheet the shadow folds over it there
  // (nor nothing, at a ribbon's thin end seen edge on); Tab still reaches the sheets under it.
  void offer_handle(const SheetHit& h) { handle_ = h; }
  static constexpr int kMinCarryRings = 1, kMaxCarryRings = 40;

 private:
  // The world vertex of hit h, or -1.
  static int world_vertex(const SheetHit& h, const Session& s);
  // The sheets, and the simulated curves' strands, under the cursor, nearest the eye first.
  static std::vector<SheetHit> pick(const ToolInput& in, const Session& s);
  static constexpr double kStrandPixels = 10;  // how near the cursor a strand is taken
  static constexpr double kChoicePixels = 4;   // a Tab's choice holds while the cursor stays this near
  void toggle_pin_under_cursor(Session& s);
  // The sheet Tab (or a marker) chose at this pixel, found again in a new list of hits by what it
  // is (its object and depth), not by its place in the list.
  void take_chosen_sheet(const Vec2& cursor);
  void choose(int sheet, const Vec2& cursor);
  std::string sheet_text() const;  // "sheet 2 of 3 under the cursor, Tab for the next"
  void update_preview(const Session& s);

  std::vector<SheetHit> hits_;
  int sheet_ = 0;
  struct Choice {
    Vec2 cursor = Vec2::Constant(-1e9);  // where it was made
    int object = -1;                     // -1: any object
    double w = 0;                        // the sheet's depth (w, or its distance from the eye for a strand)
    bool by_distance = false;            // a strand: matched by its distance from the eye
  };
  std::optional<Choice> choice_;
  bool holding_ = false;
  bool along_w_ = false;
  live::GrabMode grab_mode() const { return along_w_ ? live::GrabMode::kAlongRay : live::GrabMode::kShadow; }
  bool carry_ = false;
  int carry_rings_ = 3;
  Patch preview_;
  PatchScratch preview_scratch_;
  int adjacency_object_ = -1;  // the object adjacency_ is of, and its mesh then
  std::vector<Triangle> adjacency_triangles_;
  std::vector<int> adjacency_offset_, adjacency_;
  Vec3 plane_point_ = Vec3::Zero();  // the drag plane passes through it, facing the eye
  Vec3 hand_ = Vec3::Zero();
  std::optional<SheetHit> handle_;
  double preferred_w_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace s4d
