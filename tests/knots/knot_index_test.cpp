// The shipped knot index: complete, consistent with Regina on a sample, and strict about its format.
#include "knots/knot_index.hpp"

#include <gtest/gtest.h>

#if S4D_WITH_REGINA
#include <link/link.h>
#include <packet/packet.h>
#endif

#include <map>

#include "core/error.hpp"
#include "knots/knot_invariants.hpp"
#if S4D_WITH_REGINA
#include "knots/regina_link.hpp"
#endif

namespace s4d {
namespace {

TEST(KnotIndex, ShippedIndexCoversTheCensus) {
  const KnotIndex& idx = KnotIndex::shipped();
  // Prime knots with 3..14 crossings: 1, 1, 2, 3, 7, 21, 49, 165, 552, 2176, 9988, 46972.
  std::map<int, int> per;
  int rolfsen = 0;
  for (const auto& e : idx.entries()) {
    ++per[e.crossings];
    if (!e.rolfsen_name.empty()) ++rolfsen;
  }
  EXPECT_EQ(per[3], 1);
  EXPECT_EQ(per[8], 21);
  EXPECT_EQ(per[10], 165);
  EXPECT_EQ(per[12], 2176);
  EXPECT_EQ(per[14], 46972);
  EXPECT_EQ(rolfsen, 249);
  EXPECT_EQ(idx.max_crossings(), 14);
  ASSERT_NE(idx.find_name("8_19"), nullptr);
  EXPECT_EQ(idx.find_name("8_19")->dt_name, "8n_3");
  EXPECT_TRUE(idx.find_name("4_1")->amphichiral);
  EXPECT_FALSE(idx.find_name("3_1")->homfly_symmetric);
  EXPECT_TRUE(idx.find_name("9_42")->homfly_symmetric);   // chiral, but HOMFLY-PT cannot see it
  EXPECT_FALSE(idx.find_name("9_42")->amphichiral);
}

#if S4D_WITH_REGINA
TEST(KnotIndex, KeysAgreeWithReginaOnASampleOfTheCensus) {
  const KnotIndex& idx = KnotIndex::shipped();
  const auto root = regina::open("/usr/share/regina-normal/examples/knot-census.rga");
  if (!root) GTEST_SKIP() << "Regina's census is not installed";
  int checked = 0, i = 0;
  for (const auto& packet : *root) {
    const auto* held = dynamic_cast<const regina::PacketOf<regina::Link>*>(&packet);
    if (!held) continue;
    const auto& e = idx.entries().at(i++);
    if (i % 997 != 1) continue;  // a spread-out sample keeps the test fast
    const regina::Link& link = *held;
    ASSERT_EQ(packet.label().substr(0, packet.label().find(' ')), e.regina_name);
    Laurent2 h;
    const long b = 2 * static_cast<long>(link.size()) + 2;  // Morton: |alpha powers| <= 2n
    for (long x = -b; x <= b; ++x)
      for (long y = -b; y <= b; ++y)
        if (!link.homflyAZ()(x, y).isZero()) h.add(x, y, link.homflyAZ()(x, y).longValue());
    const auto k = homfly_fingerprint(h), km = homfly_fingerprint(h.mirror_alpha());
    EXPECT_TRUE(e.key == k || e.key == km) << e.regina_name;
    ++checked;
  }
  EXPECT_EQ(i, static_cast<int>(idx.entries().size()));
  EXPECT_GT(checked, 50);
}
#endif

TEST(KnotIndex, MalformedLinesNameFileAndLine) {
  try {
    KnotIndex::parse("# header\n1\t0\t3\t3at_1\t3a_1\t3_1\ta\nzz\t0\t3\tx\t-\t-\t-\n", "idx.tsv");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.file(), "idx.tsv");
  }
  EXPECT_THROW(KnotIndex::parse("1\t0\t3\ta\tb\n", "x"), ParseError);
  EXPECT_THROW(KnotIndex::parse("1\t0\t3\ta\tb\tc\tq\n", "x"), ParseError);
  EXPECT_THROW(KnotIndex::parse("# nothing\n", "x"), ParseError);
  EXPECT_THROW(KnotIndex::load("/nonexistent/knot_index.tsv"), Error);
  const KnotIndex one = KnotIndex::parse("ff\t0\t3\t3at_1\t3a_1\t3_1\tsAa\n", "x");
  EXPECT_EQ(one.entries()[0].key, 255u);
  EXPECT_TRUE(one.entries()[0].amphichiral);
  EXPECT_EQ(format_index_line(one.entries()[0]), "ff\t0\t3\t3at_1\t3a_1\t3_1\tsAa");
}

}  // namespace
}  // namespace s4d
