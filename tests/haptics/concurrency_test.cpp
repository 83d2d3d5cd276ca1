// TripleBuffer and SpscQueue under two real threads: values arrive whole, in order, none invented.
#include <gtest/gtest.h>

#include <array>
#include <thread>

#include "haptics/spsc_queue.hpp"
#include "haptics/triple_buffer.hpp"

namespace s4d {
namespace {

// A value whose fields must always agree: a torn read would show a mismatch.
struct Stamp {
  std::uint64_t seq = 0;
  std::array<std::uint64_t, 16> copies{};
};

TEST(TripleBuffer, ReaderSeesWholeIncreasingValues) {
  TripleBuffer<Stamp> buf;
  constexpr std::uint64_t kN = 200000;
  std::thread writer([&] {
    for (std::uint64_t i = 1; i <= kN; ++i) {
      Stamp& s = buf.back();
      s.seq = i;
      s.copies.fill(i);
      buf.publish();
    }
  });
  std::uint64_t last = 0, reads = 0;
  while (last < kN) {
    const Stamp& s = buf.read();
    for (std::uint64_t c : s.copies) ASSERT_EQ(c, s.seq) << "torn snapshot";
    ASSERT_GE(s.seq, last) << "went back in time";
    last = s.seq;
    ++reads;
  }
  writer.join();
  EXPECT_EQ(buf.read().seq, kN);
  EXPECT_GT(reads, 0u);
}

TEST(TripleBuffer, KeepsTheLastValueWhenNothingNew) {
  TripleBuffer<int> buf(0);
  buf.write(7);
  EXPECT_TRUE(buf.fresh());
  EXPECT_EQ(buf.read(), 7);
  EXPECT_FALSE(buf.fresh());
  EXPECT_EQ(buf.read(), 7);
  buf.write(8);
  buf.write(9);
  EXPECT_EQ(buf.read(), 9) << "only the latest matters";
}

TEST(SpscQueue, BoundedAndFifo) {
  SpscQueue<int, 4> q;
  EXPECT_FALSE(q.try_pop());
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(q.try_push(i));
  EXPECT_FALSE(q.try_push(99)) << "full: rejected, never blocks";
  for (int i = 0; i < 4; ++i) EXPECT_EQ(*q.try_pop(), i);
  EXPECT_FALSE(q.try_pop());
}

TEST(SpscQueue, TwoThreadsLoseNothing) {
  SpscQueue<std::uint64_t, 64> q;
  constexpr std::uint64_t kN = 300000;
  std::thread producer([&] {
    for (std::uint64_t i = 0; i < kN; ++i)
      while (!q.try_push(i)) std::this_thread::yield();
  });
  std::uint64_t expected = 0;
  while (expected < kN) {
    if (auto v = q.try_pop()) {
      ASSERT_EQ(*v, expected);
      ++expected;
    } else {
      std::this_thread::yield();
    }
  }
  producer.join();
  EXPECT_FALSE(q.try_pop());
}

}  // namespace
}  // namespace s4d
