// The two stacks of History and their bound.
#include "interact/session/history.hpp"

namespace s4d {

std::size_t DocumentState::bytes() const {
  std::size_t b = sizeof(DocumentState) + pinned.size() * sizeof(int) + scene.scenario.size();
  for (const SceneObject& o : scene.objects) {
    b += sizeof(SceneObject) + o.name.size();
    std::visit([&](const auto& s) {
      using T = std::decay_t<decltype(s)>;
      if constexpr (std::is_same_v<T, Surface<T::kDim>>) {
        b += s.vertices.size() * sizeof(s.vertices[0]) + s.triangles.size() * sizeof(Triangle);
      } else {
        for (const auto& c : s.components) b += c.points.size() * sizeof(c.points[0]) + sizeof(c);
      }
    }, o.shape);
  }
  return b;
}

void History::record(std::string label, DocumentState before) {
  for (const Step& s : undone_) bytes_ -= s.bytes;
  undone_.clear();
  Step s{std::move(label), std::move(before), 0};
  s.bytes = s.state.bytes();
  bytes_ += s.bytes;
  done_.push_back(std::move(s));
  trim();
}

std::optional<DocumentState> History::undo(DocumentState current) {
  if (done_.empty()) return std::nullopt;
  Step back = std::move(done_.back());
  done_.pop_back();
  Step forward{back.label, std::move(current), 0};
  forward.bytes = forward.state.bytes();
  bytes_ += forward.bytes - back.bytes;
  undone_.push_back(std::move(forward));
  trim();
  return std::move(back.state);
}

std::optional<DocumentState> History::redo(DocumentState current) {
  if (undone_.empty()) return std::nullopt;
  Step forward = std::move(undone_.back());
  undone_.pop_back();
  Step back{forward.label, std::move(current), 0};
  back.bytes = back.state.bytes();
  bytes_ += back.bytes - forward.bytes;
  done_.push_back(std::move(back));
  trim();
  return std::move(forward.state);
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

}  // namespace s4d
