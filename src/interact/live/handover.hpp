// Handover<T>: the UI gives a heap object to a real-time thread and takes it back to free it,
// neither side ever waiting or the real-time side ever allocating or freeing: one slot for the
// latest offer (a newer one replaces it), one for the object the taker is done with.
#pragma once
#include <atomic>
#include <memory>

namespace s4d {

template <typename T>
class Handover {
 public:
  ~Handover() {
    delete offered_.exchange(nullptr);
    delete retired_.exchange(nullptr);
    delete backlog_;
  }
  // UI thread: the latest offer wins; what the taker gave back is freed here.
  void offer(std::unique_ptr<T> value) {
    delete retired_.exchange(nullptr, std::memory_order_acq_rel);
    delete offered_.exchange(value.release(), std::memory_order_acq_rel);
  }
  // Taker thread: the offer, if any. Give it back with retire() when done with it.
  T* take() {
    if (backlog_ && retire_into_slot(backlog_)) backlog_ = nullptr;
    if (backlog_) return nullptr;  // two given back and not collected: wait for the next offer()
    return offered_.exchange(nullptr, std::memory_order_acq_rel);
  }
  // An offer can come between a take() and its retire(), finding the slot empty and collecting
  // nothing; the taker then keeps what it gives back in its own backlog (it never frees), so the
  // newer offer is still taken at once rather than waiting for yet another offer().
  void retire(T* value) {
    if (!retire_into_slot(value)) backlog_ = value;
  }

 private:
  bool retire_into_slot(T* value) {
    T* empty = nullptr;
    return retired_.compare_exchange_strong(empty, value, std::memory_order_acq_rel);
  }

  std::atomic<T*> offered_{nullptr};
  std::atomic<T*> retired_{nullptr};
  T* backlog_ = nullptr;  // the taker's alone
};

}  // namespace s4d
