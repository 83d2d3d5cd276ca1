// The two stacks of History and their bound.
#include "interact/session/history.hpp"

namespace s4d {

History::Step History::make_step(std::string label, std::shared_ptr<const DocumentState> state) {
  Step s{std::move(label), std::move(state), 0};
  s.bytes = s.state->bytes();
  return s;
}

void History::record(std::string label, DocumentState before) {
  for (const Step& s : undone_) bytes_ -= s.bytes;
  undone_.clear();
  Step s = make_step(std::move(label), std::make_shared<const DocumentState>(std::move(before)));
  bytes_ += s.bytes;
  done_.push_back(std::move(s));
  trim();
}

std::optional<DocumentState> History::undo(DocumentState current) {
  if (done_.empty()) return std::nullopt;
  Step back = std::move(done_.back());
  done_.pop_back();
  Step forward = make_step(back.label, std::make_shared<const DocumentState>(std::move(current)));
  bytes_ += forward.bytes - back.bytes;
  undone_.push_back(std::move(forward));
  trim();
  return *back.state;  // a copy: a saved session may share the state
}

std::optional<DocumentState> History::redo(DocumentState current) {
  if (undone_.empty()) return std::nullopt;
  Step forward = std::move(undone_.back());
  undone_.pop_back();
  Step back = make_step(forward.label, std::make_shared<const DocumentState>(std::move(current)));
  bytes_ += back.bytes - forward.bytes;
  done_.push_back(std::move(back));
  trim();
  return *forward.state;
}

void History::clear() {
  done_.clear();
  undone_.clear();
  bytes_ = 0;
}

// The oldest done steps go first; redo states only when nothing else is left to drop.
void History::trim() {
  while (!done_.empty() && (done_.size() + undone_.size() > max_steps_ || bytes_ > max_bytes_)) {
    bytes_ -= done_.front().bytes;
    done_.pop_front();
    ++dropped_;
  }
  while (!undone_.empty() && (undone_.size() > max_steps_ || bytes_ > max_bytes_)) {
    bytes_ -= undone_.front().bytes;
    undone_.erase(undone_.begin());
    ++dropped_;
  }
}

std::vector<std::string> History::done_labels() const {
  std::vector<std::string> l;
  for (const Step& s : done_) l.push_back(s.label);
  return l;
}

std::vector<std::string> History::undone_labels() const {
  std::vector<std::string> l;
  for (auto it = undone_.rbegin(); it != undone_.rend(); ++it) l.push_back(it->label);
  return l;
}

std::vector<std::shared_ptr<const DocumentState>> History::states() const {
  std::vector<std::shared_ptr<const DocumentState>> s;
  s.reserve(done_.size() + undone_.size());
  for (const Step& d : done_) s.push_back(d.state);
  for (auto it = undone_.rbegin(); it != undone_.rend(); ++it) s.push_back(it->state);
  return s;
}

History::Saved History::to_save(std::size_t max_bytes) const {
  // The steps nearest the present first: the last done, the next to redo, and outwards.
  std::size_t bytes = 0, done = 0, undone = 0;
  for (bool grew = true; grew;) {
    grew = false;
    if (done < done_.size() && bytes + done_[done_.size() - 1 - done].bytes <= max_bytes) {
      bytes += done_[done_.size() - 1 - done].bytes;
      ++done;
      grew = true;
    }
    if (undone < undone_.size() && bytes + undone_[undone_.size() - 1 - undone].bytes <= max_bytes) {
      bytes += undone_[undone_.size() - 1 - undone].bytes;
      ++undone;
      grew = true;
    }
  }
  Saved s;
  s.head = done;
  for (std::size_t i = done_.size() - done; i < done_.size(); ++i) {
    s.labels.push_back(done_[i].label);
    s.states.push_back(done_[i].state);
  }
  for (std::size_t i = 0; i < undone; ++i) {
    const Step& u = undone_[undone_.size() - 1 - i];
    s.labels.push_back(u.label);
    s.states.push_back(u.state);
  }
  return s;
}

bool History::load(const std::vector<std::string>& labels,
                   const std::vector<std::shared_ptr<const DocumentState>>& states, std::size_t head) {
  clear();
  if (labels.size() != states.size() || head > labels.size()) return false;
  for (const auto& s : states)
    if (!s) return false;
  for (std::size_t i = 0; i < head; ++i) {
    done_.push_back(make_step(labels[i], states[i]));
    bytes_ += done_.back().bytes;
  }
  // undone_'s back is the next to redo: the first undone label.
  for (std::size_t i = labels.size(); i-- > head;) {
    undone_.push_back(make_step(labels[i], states[i]));
    bytes_ += undone_.back().bytes;
  }
  trim();
  return true;
}

}  // namespace s4d
