// Handover<T>: the UI gives a heap object to a real-time thread and takes it back to free it,
// neither side ever waiting or the real-time side ever allocating or freeing: one slot for the
// latest offer (a newer one replaces it), and slots for the objects the taker is done with, which
// the next offer frees.
#pragma once
#include <array>
#include <atomic>
#include <memory>

namespace s4d {

template <typename T>
class Handover {
 public:
  ~Handover() {
    delete offered_.exchange(nullptr);
    for (auto& r : retired_) delete r.exchange(nullptr);
    delete backlog_;
  }
  // UI thread: the latest offer wins; what the taker gave back is freed here.
  void offer(std::unique_ptr<T> value) {
    for (auto& r : retired_) delete r.exchange(nullptr, std::memory_order_acq_rel);
    delete offered_.exchange(value.release(), std::memory_order_acq_rel);
  }
  // Taker thread: the offer, if any. Give it back with retire() when done with it.
  T* take() {
    if (backlog_ && give_back(backlog_)) backlog_ = nullptr;
    if (backlog_) return nullptr;  // never reached (see retired_): wait for the next offer()
    return offered_.exchange(nullptr, std::memory_order_acq_rel);
  }
  void retire(T* value) {
    if (!give_back(value)) backlog_ = value;
  }

 private:
  bool give_back(T* value) {
    for (auto& r : retired_) {
      T* empty = nullptr;
      if (r.compare_exchange_strong(empty, value, std::memory_order_acq_rel)) return true;
    }
    return false;
  }

  std::atomic<T*> offered_{nullptr};
  // Between two offers' collections the taker gives back at most three objects: one it held from
  // before the first, the offer that collection found not yet taken, and the one published after
  // it (checked over every interleaving of offers against the taker's steps). One slot was not
  // enough: an offer that collected while the taker still held its object left the slot to be
  // filled after it, and the next offer then waited for yet another offer to be taken.
  std::array<std::atomic<T*>, 3> retired_{};
  T* backlog_ = nullptr;  // the taker's alone, should the bound ever be wrong: take() then waits
};

}  // namespace s4d
