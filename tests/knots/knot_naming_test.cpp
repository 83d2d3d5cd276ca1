// The one naming decision: identify (name_knot), info (knot_info, the Knot panel's engine) and a
// table diagram agree on every Rolfsen knot and on redrawn curves; the covers decide what the
// polynomials leave (10_132, the mutants 11n_34 and 11n_42) and --fast says what it skipped.
#include "knots/knot_naming.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/plane.hpp"
#include "knots/knot_info.hpp"
#include "knots/knot_table.hpp"

namespace s4d {
namespace {

Frame<3> turned(std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  Frame<3> f;
  f.rotate(*parse_plane("xz", 3), angle(rng));
  f.rotate(*parse_plane("yz", 3), angle(rng));
  f.rotate(*parse_plane("xy", 3), angle(rng));
  return f;
}

// The curve moved to another position: turned about a random axis, moved and scaled.
Curve<3> redrawn(Curve<3> c, std::mt19937& rng) {
  const Mat<3> r = turned(rng).matrix();
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  const Vec3 shift(u(rng), u(rng), u(rng));
  for (auto& p : c.components)
    for (Vec3& q : p.points) q = 0.5 * (r * q) + shift;
  return c;
}

TEST(KnotNaming, IdentifyInfoAndTheTableDiagramAgreeOnEveryRolfsenKnot) {
  if (!regina_available()) GTEST_SKIP() << "some Rolfsen knots are proven by covers (9_12 against 4_1 # 5_2), which need Regina";
  std::mt19937 rng(37);
  DiagramEmbedding raw;
  raw.relax_iterations = 0;  // the drawing itself: fast, and its diagram is the table's
  int knots = 0;
  for (const KnotTableEntry& e : KnotIndex::shipped().entries()) {
    if (e.rolfsen_name.empty()) continue;
    SCOPED_TRACE(e.rolfsen_name);
    const TableKnot t = table_knot(e.rolfsen_name);
    const Curve<3> curve = make_table_knot(e.rolfsen_name, raw);
    const KnotNaming identify = name_knot(redrawn(curve, rng));
    const KnotInfo info = knot_info(curve, turned(rng));
    const KnotNaming table = name_diagram(t.diagram);
    EXPECT_EQ(identify.name(), table.name());
    EXPECT_EQ(info.name, table.name());
    EXPECT_TRUE(identify.proven() && info.proven && table.proven()) << table.name();
    EXPECT_EQ(table.name().rfind(e.rolfsen_name, 0), 0u) << table.name();
    EXPECT_FALSE(info.decided_by.empty());
    ++knots;
  }
  EXPECT_EQ(knots, 249);  // Rolfsen's table, the Perko pair counted once
}

// Issue 37's contradiction: identify said "one of: 5_1 mirror, 10_132 mirror" where info named
// 10_132 by covers. Now both run the covers, and --fast says it skipped them.
TEST(KnotNaming, TenOneThirtyTwoIsDecidedByCoversAndFastSaysItSkippedThem) {
  if (!regina_available()) GTEST_SKIP() << "decided by covers of the knot group, which need Regina";
  const Curve<3> c = make_table_knot("10_132 mirror");
  const KnotNaming full = name_knot(c);
  EXPECT_EQ(full.name(), "10_132 mirror (DT 10n_13)");
  EXPECT_TRUE(full.proven());
  ASSERT_FALSE(full.decided_by.empty());
  EXPECT_EQ(full.decided_by[0].find("covers of the knot group of index 2 to 6 rule out 1"), 0u);
  EXPECT_EQ(knot_info(c).name, full.name());

  NamingOptions o;
  o.fast = true;
  const KnotNaming fast = name_knot(c, o);
  EXPECT_FALSE(fast.proven());
  EXPECT_EQ(fast.candidates(), (std::vector<std::string>{"5_1 mirror", "10_132 mirror"}));
  EXPECT_TRUE(fast.further_used.empty());
  ASSERT_FALSE(fast.skipped.empty());
  EXPECT_NE(fast.headline().find("[fast: covers of the knot group"), std::string::npos) << fast.headline();
}

// Issue 37, point 4: the Conway knot and the Kinoshita-Terasaka knot share every polynomial and
// every cover of index 2 to 5; covers of index 6 tell them apart, from any position.
TEST(KnotNaming, TheConwayAndKinoshitaTerasakaKnotsAreToldApartInAnyPosition) {
  if (!regina_available()) GTEST_SKIP() << "decided by covers of the knot group, which need Regina";
  std::mt19937 rng(11);
  for (const char* name : {"11n_34", "11n_42", "11n_34 mirror", "11n_42 mirror"}) {
    SCOPED_TRACE(name);
    const Curve<3> made = make_table_knot(name);
    for (int k = 0; k < 2; ++k) {
      const KnotNaming n = name_knot(redrawn(made, rng));
      EXPECT_EQ(n.name(), table_knot(name).name);
      EXPECT_TRUE(n.proven());
      bool by_covers = false;
      for (const auto& d : n.decided_by) by_covers = by_covers || d.find("index 2 to 6 rule out") != std::string::npos;
      EXPECT_TRUE(by_covers) << n.headline();
    }
  }
}

#if S4D_WITH_REGINA
// A stand-in for Regina (as a build without it would have): the naming asks it, and only it.
class CountingRefinements final : public KnotRefinements {
 public:
  mutable int covers = 0, searches = 0;
  std::string engine() const override { return "stand-in"; }
  KnotDiagram table_diagram(const KnotFactor& f) const override { return regina_refinements().table_diagram(f); }
  std::string cover_signature(const KnotDiagram& d, int n) const override {
    ++covers;
    return regina_refinements().cover_signature(d, n);
  }
  std::optional<std::size_t> reidemeister_search(const KnotDiagram&, const std::vector<KnotDiagram>&,
                                                 int) const override {
    ++searches;
    return std::nullopt;
  }
  bool complement_is_solid_torus(const KnotDiagram&) const override { return false; }
};

TEST(KnotNaming, TheRefinementsGoThroughTheirInterface) {
  CountingRefinements stand_in;
  NamingOptions o;
  o.refinements = &stand_in;
  const KnotNaming n = name_diagram(table_knot("11n_42").diagram, o);
  EXPECT_EQ(n.name(), "11n_42");
  EXPECT_GE(stand_in.covers, 1);
  EXPECT_EQ(stand_in.searches, 0) << "one candidate left after the covers: no search";
  EXPECT_NE(n.further_used[0].find("(stand-in)"), std::string::npos) << n.further_used[0];
}
#endif

}  // namespace
}  // namespace s4d
