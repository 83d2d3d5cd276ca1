// SpscQueue<T, N>: a bounded lock-free ring for one producer and one consumer thread (UI commands to
// the haptic loop, tick records to the recording writer). A full queue rejects, it never blocks.
#pragma once
#include <array>
#include <atomic>
#include <cstddef>
#include <optional>
#include <type_traits>

namespace s4d {

template <typename T, std::size_t N>
class SpscQueue {
  static_assert(N >= 2 && (N & (N - 1)) == 0, "capacity must be a power of two");
  static_assert(std::is_trivially_copyable_v<T>, "elements are copied across threads by value");

 public:
  // Producer: false when full (the caller decides: drop, count, retry later).
  bool try_push(const T& value) {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_cache_ == N) {
      tail_cache_ = tail_.load(std::memory_order_acquire);
      if (head - tail_cache_ == N) return false;
    }
    ring_[head & (N - 1)] = value;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }

  // Consumer: the oldest element, or nothing when empty.
  std::optional<T> try_pop() {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_cache_) {
      head_cache_ = head_.load(std::memory_order_acquire);
      if (tail == head_cache_) return std::nullopt;
    }
    T value = ring_[tail & (N - 1)];
    tail_.store(tail + 1, std::memory_order_release);
    return value;
  }

  static constexpr std::size_t capacity() { return N; }
  // Approximate (exact when called from either side with the other idle).
  std::size_t size() const {
    return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire);
  }

 private:
  std::array<T, N> ring_{};
  alignas(64) std::atomic<std::size_t> head_{0};  // next slot the producer writes
  std::size_t tail_cache_ = 0;                     // producer's view of tail_
  alignas(64) std::atomic<std::size_t> tail_{0};  // next slot the consumer reads
  std::size_t head_cache_ = 0;                     // consumer's view of head_
};

}  // namespace s4d
