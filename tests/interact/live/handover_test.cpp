// Handover: an offer made while the taker still holds the previous one is taken at once, and
// nothing is freed on the taker's side or leaked (ASan checks the frees).
#include "interact/live/handover.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace s4d {
namespace {

TEST(Handover, AnOfferMadeWhileTheTakerHoldsTheLastIsStillTaken) {
  Handover<int> h;
  h.offer(std::make_unique<int>(1));
  int* first = h.take();
  ASSERT_NE(first, nullptr);
  h.offer(std::make_unique<int>(2));  // the retired slot is empty: nothing to collect
  h.retire(first);
  int* second = h.take();
  ASSERT_NE(second, nullptr) << "the newer offer waits for no further offer";
  EXPECT_EQ(*second, 2);
  h.retire(second);
  EXPECT_EQ(h.take(), nullptr);
  h.offer(std::make_unique<int>(3));  // collects what was given back
  int* third = h.take();
  ASSERT_NE(third, nullptr);
  EXPECT_EQ(*third, 3);
  h.retire(third);
}

// Offers as fast as keys go against a taker on its own thread: the last offer is always taken.
TEST(Handover, TheLastOfManyQuickOffersIsTaken) {
  for (int round = 0; round < 1000; ++round) {
    Handover<int> h;
    std::atomic<int> last{0};
    std::atomic<bool> stop{false};
    std::thread taker([&] {
      while (!stop.load()) {
        if (int* v = h.take()) {
          last.store(*v);
          h.retire(v);
        }
      }
    });
    for (int i = 1; i <= 3; ++i) {
      h.offer(std::make_unique<int>(i));
      for (int spin = 0; spin < (round * 7 + i * 13) % 64; ++spin) std::atomic_signal_fence(std::memory_order_seq_cst);
    }
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (last.load() != 3 && std::chrono::steady_clock::now() < until) std::this_thread::yield();
    stop.store(true);
    taker.join();
    ASSERT_EQ(last.load(), 3) << "round " << round;
  }
}

}  // namespace
}  // namespace s4d
