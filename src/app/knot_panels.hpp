// The knot studio's panels (issue 26 points 6-8): the live information of the selected curve
// (knot_info on its own thread, the latest result shown without dropping frames), Create > Knot
// from the table, and the user study's two exercises — "are these the same knot?" and "unknot it
// by one crossing change". Every slow call runs off the UI thread.
#pragma once
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "knots/knot_exercises.hpp"
#include "knots/knot_info.hpp"
#include "knots/knot_table.hpp"

namespace s4d {

struct GuiModel;

class KnotPanels {
 public:
  KnotPanels();
  // Draws the Knot panel when the scene has curves, and the dialogs that are open.
  void draw(GuiModel& model, const Frame<3>& view);
  void open_table() { table_open_ = true; }
  // The window's right click on crossing `over_point` (shadow space) of `object` before it is
  // changed: in the unknotting exercise, the verdict on that crossing. True when it was one.
  bool exercise_crossing(GuiModel& model, int object, const Vec3& over_point);
  // For dump and tests: the name the panel shows for the selected curve ("" until named).
  std::string shown_name() const;
  const std::string& exercise_message() const { return exercise_message_; }

 private:
  void info_panel(GuiModel& model, const Frame<3>& view);
  void table_dialog(GuiModel& model);
  void same_dialog(GuiModel& model);

  KnotInfoWorker worker_;
  int selected_ = -1;              // scene object shown
  std::size_t submitted_hash_ = 0;
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
  std::future<SameKnotAnswer> same_;
  std::optional<SameKnotAnswer> same_answer_;
  std::string same_error_;
  // Unknot it by one crossing change.
  bool unknot_on_ = false;
  std::future<UnknottingReport> unknot_;
  std::optional<UnknottingReport> unknot_report_;
  std::string exercise_message_;
};

}  // namespace s4d
