// TripleBuffer<T>: lock-free hand-over of the latest value from one writer thread to one reader
// thread (haptic loop -> renderer snapshots, GUI pointer -> loop). Neither side ever waits.
#pragma once
#include <array>
#include <atomic>
#include <cstdint>

namespace s4d {

// Three slots: the writer fills its private back slot and swaps it with the shared middle one; the
// reader swaps the middle slot with its private front slot when a fresh one is there. The reader's
// slot is therefore never written while it holds it: each published value is immutable to it.
template <typename T>
class TripleBuffer {
 public:
  TripleBuffer() = default;
  explicit TripleBuffer(const T& init) { slots_.fill(init); }

  // Writer side.
  T& back() { return slots_[back_]; }
  void publish() {
    const std::uint8_t old =
        middle_.exchange(static_cast<std::uint8_t>(back_ | kFresh), std::memory_order_acq_rel);
    back_ = old & kIndex;
  }
  // Convenience: copy-assign and publish (allocates only if T's assignment does).
  void write(const T& value) {
    back() = value;
    publish();
  }

  // Reader side: the latest published value (or the last one seen if nothing new). The reference stays
  // valid and unchanged until the next call to read() from the same reader.
  const T& read() {
    if (middle_.load(std::memory_order_relaxed) & kFresh) {
      const std::uint8_t old = middle_.exchange(front_, std::memory_order_acq_rel);
      front_ = old & kIndex;
    }
    return slots_[front_];
  }
  // True when the writer published since the last read().
  bool fresh() const { return middle_.load(std::memory_order_acquire) & kFresh; }

  // Direct access to every slot, only while no other thread uses the buffer (to size them once).
  std::array<T, 3>& slots_unsynchronised() { return slots_; }

 private:
  static constexpr std::uint8_t kIndex = 0x3;
  static constexpr std::uint8_t kFresh = 0x4;
  std::array<T, 3> slots_{};
  std::uint8_t back_ = 0;                   // writer's private slot
  alignas(64) std::atomic<std::uint8_t> middle_{1};  // shared slot index | fresh flag
  alignas(64) std::uint8_t front_ = 2;      // reader's private slot
};

}  // namespace s4d
