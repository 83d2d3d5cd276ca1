// History: undo and redo of every user action as whole document states (undo is the Session's
// concern, not each tool's): a tool records the state before its action under a label (one drag is one
// step, however many ticks it lasted); undo hands back the state to restore and keeps the
// current one for redo. Memory stays bounded: the last `max_steps` steps or `max_bytes` of
// states, whichever is reached first (the oldest go).
#pragma once
#include <array>
#include <map>
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "io/scene.hpp"

namespace s4d {

// What an undo restores: the scene as it was (shapes, objects, physics, view settings), the
// pins, and the 4D rotation of the view.
struct DocumentState {
  Scene scene;
  std::vector<int> pinned;
  std::array<float, 6> angles{};
  Eigen::Quaterniond trackball = Eigen::Quaterniond::Identity();
  double zoom = 1;
  std::map<std::string, double> settings;  // the window's tool settings (app/tool_settings.hpp)
  std::size_t bytes() const;  // an estimate of the memory it holds
};

class History {
 public:
  static constexpr std::size_t kMaxSteps = 200;
  static constexpr std::size_t kMaxBytes = std::size_t{256} << 20;  // 256 MB

  explicit History(std::size_t max_steps = kMaxSteps, std::size_t max_bytes = kMaxBytes)
      : max_steps_(max_steps), max_bytes_(max_bytes) {}

  // A step was done; `before` is the document as it was. What was undone cannot be redone now.
  void record(std::string label, DocumentState before);
  bool can_undo() const { return !done_.empty(); }
  bool can_redo() const { return !undone_.empty(); }
  // The state to restore, given the current one (kept for redo / undo); nothing when there is
  // no step to undo / redo.
  std::optional<DocumentState> undo(DocumentState current);
  std::optional<DocumentState> redo(DocumentState current);
  void clear();

  // Labels of the steps done (oldest first), then of those undone (next to redo first).
  std::vector<std::string> done_labels() const;
  std::vector<std::string> undone_labels() const;
  std::size_t bytes() const { return bytes_; }
  std::size_t dropped() const { return dropped_; }  // steps forgotten to stay within the bounds

 private:
  struct Step {
    std::string label;
    DocumentState state;  // done_: the state before the step; undone_: the state after it
    std::size_t bytes = 0;
  };
  void trim();

  std::size_t max_steps_, max_bytes_;
  std::deque<Step> done_;
  std::vector<Step> undone_;  // back = the next to redo
  std::size_t bytes_ = 0, dropped_ = 0;
};

}  // namespace s4d
