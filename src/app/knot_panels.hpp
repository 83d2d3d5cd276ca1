// The knot studio's panels (issue 26 points 6-8): the live information of the selected curve
// (knot_info on its own thread, the latest result shown without dropping frames), Create > Knot
// from the table, and the user study's two exercises — "are these the same knot?" (a pair from the
// table side by side, the user's answer judged by the invariants) and "unknot it by one crossing
// change" (a knot of unknotting number one, its crossings numbered in the view, a right click
// judged), and the diagram toolbar (mirror, reverse or delete a component: one undoable step
// each). Every slow call runs off the UI thread.
#pragma once
#include <array>
#include <future>
#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "app/layout.hpp"
#include "knots/knot_exercises.hpp"
#include "knots/knot_info.hpp"
#include "knots/knot_table.hpp"

namespace s4d {

struct GuiModel;

class KnotPanels {
 public:
  // seed 0: the exercises are picked at random; another: the same exercises every run (a class).
  explicit KnotPanels(unsigned exercise_seed = 0);
  // Draws the Knot panel when the scene has curves, and the dialogs that are open.
  void draw(GuiModel& model, const Frame<3>& view);
  // The unknotting exercise's crossing numbers at their crossings in the view (under the panels).
  void overlay(GuiModel& model, const Camera& camera, const Rect& view);
  void open_table() { table_open_ = true; }
  // The window's right click on crossing `over_point` (shadow space) of `object` before it is
  // changed: in the unknotting exercise, the verdict on that crossing. True when it was one.
  bool exercise_crossing(GuiModel& model, int object, const Vec3& over_point);
  // Work under way off the UI thread (naming, making a knot, checking an answer): a scripted
  // input's `wait` holds until there is none.
  bool busy() const;
  // For dump and tests: the name the panel shows for the selected curve ("" until named).
  std::string shown_name() const;
  const std::string& exercise_message() const { return exercise_message_; }
  // The panels' state for the window's dump: buttons (window pixels), the exercises.
  void dump(nlohmann::ordered_json& out) const;

 private:
  void info_panel(GuiModel& model, const Frame<3>& view);
  void toolbar(GuiModel& model);  // mirror, reverse or delete a component of the selected curve
  void table_dialog(GuiModel& model);
  void same_dialog(GuiModel& model);
  void unknot_dialog(GuiModel& model, const Frame<3>& view);
  void start_unknot(GuiModel& model);
  void leave_button(GuiModel& model);
  void new_pair();  // a new same-knot pair from the table, made off the UI thread  // a new unknotting exercise, or back to the one under way
  bool button(const char* label);  // ImGui::Button, its rectangle kept for dump()
  void add_pair(GuiModel& model, SameKnotExercise pair);
  void add_exercise_knot(GuiModel& model, Curve<3> curve);
  void focus(GuiModel& model, const Frame<3>& view);  // frames the view on the objects of focus_ (a frame after they came)

  std::mt19937 rng_;
  bool table_was_open_ = false;  // the table's name field takes the keys when it opens
  std::map<std::string, std::array<float, 4>> buttons_;  // drawn this frame
  bool name_hidden_ = false;  // the Knot panel hides the name (touch and sound only, an exercise)
  KnotInfoWorker worker_;
  int selected_ = -1;              // scene object shown
  int component_ = 1;              // the toolbar's component (from 1, as the panel counts them)
  std::size_t submitted_hash_ = 0;
  std::uint64_t submitted_ = 0;    // the worker's request for it
  std::shared_ptr<const KnotInfoWorker::Result> shown_;
  // Create > Knot from the table.
  bool table_open_ = false;
  char filter_[64] = "";
  std::vector<TableName> names_;
  bool mirror_ = false;
  std::string making_;             // the name being made
  std::future<Curve<3>> made_;
  std::string table_error_;
  // Are these the same knot?
  bool same_open_ = false;
  int other_ = -1;
  std::future<SameKnotExercise> pair_;      // a pair from the table being made
  std::optional<SameKnotPair> pair_names_;  // the table's pair in the scene (told once answered)
  bool pair_answered_ = false;
  std::future<SameKnotAnswer> same_;
  std::optional<bool> user_says_same_;      // the answer being checked (none: just check)
  std::optional<SameKnotAnswer> same_answer_;
  std::optional<SameKnotJudgement> judgement_;
  std::string same_error_;
  // Unknot it by one crossing change.
  bool unknot_open_ = false;
  std::future<std::pair<std::string, Curve<3>>> unknot_make_;
  std::string unknot_name_;                 // the exercise knot's table name (told once answered)
  std::future<UnknottingReport> unknot_;
  std::size_t unknot_key_ = 0;              // (curve, view) hash of the report or the one coming
  std::optional<UnknottingReport> unknot_report_;
  std::optional<std::size_t> changed_at_;   // history length after the user's change (undo resumes)
  std::string exercise_message_;
  struct ShownLabel {
    int label;
    float x, y;  // window pixels
  };
  std::vector<ShownLabel> labels_;
  std::vector<std::string> focus_;  // objects the view is to frame next
};

}  // namespace s4d
