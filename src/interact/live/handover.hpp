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
  }
  // UI thread: the latest offer wins; what the taker gave back is freed here.
  void offer(std::unique_ptr<T> value) {
    delete retired_.exchange(nullptr, std::memory_order_acq_rel);
    delete offered_.exchange(value.release(), std::memory_order_acq_rel);
  }
  // Taker thread: the offer, if any (only once the previous one was collected, so the taker
  // never holds two). Give it back with retire() when done with it.
  T* take() {
    if (retired_.load(std::memory_order_acquire) != nullptr) return nullptr;
    return offered_.exchange(nullptr, std::memory_order_acq_rel);
  }
  void retire(T* value) { retired_.store(value, std::memory_order_release); }

 private:
  std::atomic<T*> offered_{nullptr};
  std::atomic<T*> retired_{nullptr};
};

}  // namespace s4d
