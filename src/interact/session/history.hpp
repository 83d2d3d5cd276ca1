// History: undo and redo of every user action as whole document states (undo is the Session's
// concern, not each tool's): a tool records the state before its action under a label (one drag is one
// step, however many ticks it lasted); undo hands back the state to restore and keeps the
// current one for redo. Memory stays bounded: the last `max_steps` steps or `max_bytes` of
// states, whichever is reached first (the oldest go). The states are shared and never changed,
// so a saved session (and each autosave) takes the history without copying it, and a session
// reopened gets it back (load) under the same bounds.
#pragma once
#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/session_file.hpp"  // DocumentState

namespace s4d {

class History {
 public:
  static constexpr std::size_t kMaxSteps = 200;
  static constexpr std::size_t kMaxBytes = std::size_t{256} << 20;  // 256 MB
  // What a saved session keeps of it: the newest steps whose states hold at most this much (the
  // file is about twice as large: numbers as text). Every step of a knot or a spun trefoil fits;
  // a finely meshed surface keeps its last few dozen.
  static constexpr std::size_t kMaxSavedBytes = std::size_t{16} << 20;  // 16 MB

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
  // The states in the labels' order (done oldest first, then undone next to redo first): what a
  // session file keeps beside the labels (SessionFile::history_states).
  std::vector<std::shared_ptr<const DocumentState>> states() const;
  // The part of it a session file keeps: labels and states as above, the first `head` done, the
  // oldest done steps (then the furthest redo steps) left out beyond `max_bytes` of states.
  struct Saved {
    std::vector<std::string> labels;
    std::vector<std::shared_ptr<const DocumentState>> states;
    std::size_t head = 0;
  };
  Saved to_save(std::size_t max_bytes = kMaxSavedBytes) const;
  // Replaces the history with a saved one: labels and states as states() gives them, the first
  // `head` done. False (and the history left empty) when they do not match; trimmed to the bounds.
  bool load(const std::vector<std::string>& labels, const std::vector<std::shared_ptr<const DocumentState>>& states,
            std::size_t head);
  std::size_t bytes() const { return bytes_; }
  std::size_t dropped() const { return dropped_; }  // steps forgotten to stay within the bounds

 private:
  struct Step {
    std::string label;
    std::shared_ptr<const DocumentState> state;  // done_: the state before the step; undone_: after it
    std::size_t bytes = 0;
  };
  static Step make_step(std::string label, std::shared_ptr<const DocumentState> state);
  void trim();

  std::size_t max_steps_, max_bytes_;
  std::deque<Step> done_;
  std::vector<Step> undone_;  // back = the next to redo
  std::size_t bytes_ = 0, dropped_ = 0;
};

}  // namespace s4d
