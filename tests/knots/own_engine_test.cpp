// The own knot engine (no Regina) held equal to Regina: knot signatures read, HOMFLY-PT, Jones and
// Alexander on every knot and link of the tables to 12 crossings, the code texts, and the names.
// Without Regina (S4D_WITH_REGINA=OFF) the checks against the index's stored fingerprints (which
// Regina computed) and the brute-force references still run.
// Sections: [SECTION] moves, [SECTION] polynomials, [SECTION] codes, [SECTION] naming.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "knots/braid_closure.hpp"
#include "knots/diagram_codes.hpp"
#include "knots/diagram_moves.hpp"
#include "knots/knot_naming.hpp"
#include "knots/knot_table.hpp"
#include "knots/own_codes.hpp"
#include "knots/own_polynomials.hpp"
#if S4D_WITH_REGINA
#include "knots/regina_link.hpp"
#endif

namespace s4d {
namespace {

constexpr int kMaxCrossings = 12;

// The knots of the index to 12 crossings with their table diagrams: the Rolfsen table's braids
// where there is a Rolfsen name (the key's diagram), else the census diagram of the signature.
std::vector<std::pair<const KnotTableEntry*, KnotDiagram>> table_knots(int max_crossings = kMaxCrossings) {
  std::vector<std::pair<const KnotTableEntry*, KnotDiagram>> out;
  for (const KnotTableEntry& e : KnotIndex::shipped().entries())
    if (e.crossings <= max_crossings && !e.sig.empty())
      out.emplace_back(&e, e.rolfsen_name.empty() ? diagram_from_knot_sig(e.sig) : table_knot(e.rolfsen_name).diagram);
  return out;
}

// [SECTION] moves

TEST(OwnEngine, ReidemeisterMovesKeepTheKnotAndLoseCrossings) {
  // A trefoil with a kink (R1) and a removable bigon: the braid s1 s1 s1 s2 s2^-1 on 3 strands.
  const KnotDiagram d = braid_diagram(3, {1, 1, 1, 2, -2});
  const KnotDiagram s = simplify_diagram(d);
  EXPECT_EQ(d.crossing_count(), 5);
  EXPECT_EQ(s.crossing_count(), 3);
  EXPECT_TRUE(is_alternating(s));
  EXPECT_EQ(homfly_polynomial(s), homfly_polynomial(d));
  // Every R3 move keeps HOMFLY-PT (checked on the census diagrams' triangles).
  int moves = 0;
  for (const auto& [e, diagram] : table_knots(9)) {
    GaussDiagram g = GaussDiagram::of(diagram);
    const Laurent2 p = homfly_polynomial(g);
    for (const auto& tri : r3_moves(g)) {
      GaussDiagram h = g;
      apply_r3(h, tri);
      EXPECT_EQ(homfly_polynomial(h), p) << e->display_name();
      ++moves;
    }
  }
  EXPECT_GT(moves, 0);
}

TEST(OwnEngine, TheUnknotDrawnWithManyCrossingsSimplifiesToNone) {
  // s1 s2 s1^-1 s2 = s2^-1 s1 s2 s2, conjugate to s1 s2: the unknot with 4 crossings.
  const KnotDiagram unknot = braid_diagram(3, {1, 2, -1, 2});
  ASSERT_EQ(unknot.component_count(), 1);
  EXPECT_EQ(simplify_diagram(unknot).crossing_count(), 0);
  EXPECT_TRUE(is_unknot(unknot, false, KnotEngine::kOwn));
  EXPECT_FALSE(is_unknot(braid_diagram(2, {1, 1, 1}), false, KnotEngine::kOwn));
}

// [SECTION] polynomials

TEST(OwnEngine, HomflyMatchesTheIndexOnEveryKnotToTwelveCrossings) {
  // The index's keys are Regina's HOMFLY-PT fingerprints: this holds without Regina too.
  int knots = 0;
  for (const auto& [e, diagram] : table_knots()) {
    const KnotInvariants inv = compute_invariants(diagram, KnotEngine::kOwn);
    EXPECT_EQ(inv.fingerprint, e->key) << e->display_name();
    if (e->mirror_key) {
      EXPECT_EQ(inv.mirror_fingerprint, e->mirror_key) << e->display_name();
    }
    EXPECT_LE(inv.simplified_crossings, diagram.crossing_count());
    ++knots;
  }
  EXPECT_GT(knots, 2900);
}

TEST(OwnEngine, HomflyMatchesTheLinkTable) {
  int links = 0;
  for (const LinkTableEntry& e : LinkTable::shipped().entries()) {
    const KnotDiagram d = link_diagram(e);
    const std::uint64_t key = compute_invariants(d, KnotEngine::kOwn).fingerprint;
    EXPECT_NE(std::find(e.keys.begin(), e.keys.end(), key), e.keys.end()) << e.name;
    ++links;
  }
  EXPECT_GT(links, 1000);
}

TEST(OwnEngine, JonesFromHomflyEqualsTheKauffmanBracketStateSum) {
  int checked = 0;
  for (const auto& [e, diagram] : table_knots(10)) {
    EXPECT_EQ(jones_from_homfly(homfly_polynomial(diagram), 1), jones_by_state_sum(diagram)) << e->display_name();
    ++checked;
  }
  for (const LinkTableEntry& e : LinkTable::shipped().entries()) {
    if (e.crossings > 9) continue;
    const KnotDiagram d = link_diagram(e);
    EXPECT_EQ(jones_from_homfly(homfly_polynomial(d), d.component_count()), jones_by_state_sum(d)) << e.name;
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

#if S4D_WITH_REGINA
void expect_same_invariants(const KnotDiagram& d, const std::string& what) {
  const KnotInvariants own = compute_invariants(d, KnotEngine::kOwn);
  const KnotInvariants regina = compute_invariants(d, KnotEngine::kRegina);
  EXPECT_EQ(own.homfly, regina.homfly) << what << ": " << own.homfly_text() << " vs " << regina.homfly_text();
  EXPECT_EQ(own.jones, regina.jones) << what << ": " << own.jones_text() << " vs " << regina.jones_text();
  EXPECT_EQ(own.alexander, regina.alexander) << what;
  EXPECT_EQ(own.determinant, regina.determinant) << what;
  EXPECT_EQ(own.linking, regina.linking) << what;
  EXPECT_EQ(own.simplified_pieces, regina.simplified_pieces) << what;
}

TEST(OwnEngine, PolynomialsEqualReginasOnEveryTableKnotAndLink) {
  int n = 0;
  for (const auto& [e, diagram] : table_knots()) {
    expect_same_invariants(diagram, e->display_name());
    expect_same_invariants(diagram.mirrored(), e->display_name() + " mirror");
    ++n;
  }
  for (const LinkTableEntry& e : LinkTable::shipped().entries()) {
    const KnotDiagram d = link_diagram(e);
    expect_same_invariants(d, e.name);
    expect_same_invariants(d.with_component_reversed(d.component_count() - 1), e.name + " reversed");
    ++n;
  }
  EXPECT_GT(n, 4000);
}
#endif

// [SECTION] codes

#if S4D_WITH_REGINA
TEST(OwnEngine, KnotSignaturesReadAndWriteAsReginasDo) {
  int n = 0;
  for (const KnotTableEntry& e : KnotIndex::shipped().entries()) {
    if (e.crossings > kMaxCrossings || e.sig.empty()) continue;
    const KnotDiagram own = diagram_from_knot_sig(e.sig);
    const regina::Link link = regina::Link::fromKnotSig(e.sig);
    const KnotDiagram theirs = diagram_from_regina(link);
    EXPECT_EQ(own.signed_gauss_code(), theirs.signed_gauss_code()) << e.display_name();
    EXPECT_EQ(knot_sig(own), link.knotSig()) << e.display_name();
    ++n;
  }
  EXPECT_GT(n, 2900);
}

TEST(OwnEngine, CodeTextsAreReginas) {
  int n = 0;
  for (const auto& [e, diagram] : table_knots()) {
    const ReginaCodes own = regina_codes(diagram, KnotEngine::kOwn);
    const ReginaCodes regina = regina_codes(diagram, KnotEngine::kRegina);
    EXPECT_EQ(own.gauss, regina.gauss) << e->display_name();
    EXPECT_EQ(own.oriented_gauss, regina.oriented_gauss) << e->display_name();
    EXPECT_EQ(own.dt, regina.dt) << e->display_name();
    EXPECT_EQ(own.dt_alpha, regina.dt_alpha) << e->display_name();
    ++n;
  }
  EXPECT_GT(n, 2900);
}

TEST(OwnEngine, PdCodesReadAsReginaReadsThem) {
  for (const LinkTableEntry& e : LinkTable::shipped().entries()) {
    const KnotDiagram own = diagram_from_pd_numbers(e.pd);
    const KnotDiagram theirs = link_diagram(e);
    EXPECT_EQ(own.signed_gauss_code(), theirs.signed_gauss_code()) << e.name;
    EXPECT_EQ(homfly_polynomial(own), homfly_polynomial(theirs)) << e.name;
    EXPECT_EQ(own.linking_numbers(), theirs.linking_numbers()) << e.name;
  }
}
#endif

// [SECTION] naming

NamingOptions with_engine(KnotEngine e, bool fast) {
  NamingOptions o;
  o.engine = e;
  o.fast = fast;
  return o;
}

TEST(OwnEngine, SaysWhatItCannotDoAndLeavesTheNameNotProven) {
  // 10_132 and 5_1 share HOMFLY-PT; Regina's covers tell them apart, the own engine has none.
  const KnotNaming n = name_diagram(table_knot("10_132 mirror").diagram, with_engine(KnotEngine::kOwn, false));
  EXPECT_FALSE(n.proven());
  EXPECT_EQ(n.candidates(), (std::vector<std::string>{"5_1 mirror", "10_132 mirror"}));
  ASSERT_FALSE(n.unavailable.empty());
  EXPECT_NE(n.unavailable[0].find("covers"), std::string::npos);
  EXPECT_NE(n.headline().find("[without Regina: covers of the knot group of index 2 to 6 unavailable]"),
            std::string::npos)
      << n.headline();
  EXPECT_EQ(n.identification.invariants.engine, KnotEngine::kOwn);
}

#if S4D_WITH_REGINA
// The own engine's name of a curve against the desktop's. Where Regina's polynomials and
// simplification decide (its fast naming is proven), the own engine's full naming must give the
// same name, proven. Where they leave candidates (the desktop then runs its covers: seconds per
// knot, too slow to run here for all of them) the own engine must leave the same candidates or
// fewer (its Reidemeister search may prove one). Where the own R1/R2/R3 search keeps more
// crossings than Regina's simplification it cannot rule out the candidates of more crossings:
// then Regina's answers must be among its own, not proven (counted, and bounded).
struct Agreement {
  int equal = 0, candidates = 0, weaker = 0;  // weaker: more candidates than Regina (fewer crossings ruled out)
};

void expect_same_name(const Curve<3>& curve, const std::string& what, Agreement& a) {
  const KnotNaming own = name_knot(curve, with_engine(KnotEngine::kOwn, false));
  const KnotNaming regina = name_knot(curve, with_engine(KnotEngine::kRegina, true));
  SCOPED_TRACE(what + ": own '" + own.headline() + "', Regina '" + regina.headline() + "'");
  if (own.name() == regina.name() && own.proven() == regina.proven()) {
    ++a.equal;  // proven alike, or the same candidates (split and composite alternatives of links)
    return;
  }
  const auto mine = own.candidates(), theirs = regina.candidates();
  auto within = [](const std::vector<std::string>& x, const std::vector<std::string>& y) {
    return std::all_of(x.begin(), x.end(), [&](const std::string& c) { return std::find(y.begin(), y.end(), c) != y.end(); });
  };
  if (!regina.proven() && within(mine, theirs)) {
    ++a.candidates;  // the same candidates or fewer (the own Reidemeister search may prove one)
    return;
  }
  // The own simplification may keep more crossings than Regina's, and then cannot rule out a
  // candidate of more crossings: the desktop's answers must still be among the own ones.
  EXPECT_TRUE(within(theirs, mine));
  EXPECT_FALSE(own.proven());
  ++a.weaker;
}

TEST(OwnEngine, NamesEveryTableKnotAndLinkToTwelveCrossingsAsTheDesktopDoes) {
  DiagramEmbedding raw;
  raw.relax_iterations = 0;  // the drawing itself: fast, and its diagram is the table's
  Agreement a;
  int n = 0;
  for (const TableName& t : knot_table_names()) {
    if (t.crossings > kMaxCrossings || t.source == "torus") continue;
    expect_same_name(make_table_knot(t.name, raw), t.name, a);
    if (++n % 500 == 0) std::cout << "[ own engine ] " << n << " named\n" << std::flush;
  }
  std::cout << "[ own engine ] " << n << " table knots and links: " << a.equal << " named alike, "
            << a.candidates << " left to the refinements (the same candidates or fewer), " << a.weaker
            << " with more candidates than Regina's fast naming (weaker simplification)\n";
  EXPECT_GT(n, 4300);
  // Measured: 3,842 alike, 558 left to the refinements, 2 (10_18 and 10_68, whose drawings the own
  // R1/R2/R3 search leaves above 12 crossings) not proven by the own engine.
  EXPECT_LE(a.weaker, 4);
  EXPECT_EQ(a.equal + a.candidates + a.weaker, n);
}

TEST(OwnEngine, NamesRelaxedAndRedrawnCurvesAsTheDesktopDoes) {
  std::mt19937 rng(35);
  Agreement a;
  int n = 0;
  const auto names = knot_table_names();
  for (std::size_t i = 0; i < names.size(); i += 47) {
    const TableName& t = names[i];
    if (t.crossings > kMaxCrossings || t.source == "torus") continue;
    Curve<3> c = make_table_knot(t.name);
    std::uniform_real_distribution<double> angle(-3.0, 3.0);
    const Mat<3> turn = Eigen::AngleAxisd(angle(rng), Vec3(angle(rng), angle(rng), 1.0).normalized()).toRotationMatrix();
    for (auto& comp : c.components)
      for (Vec3& q : comp.points) q = turn * q;
    expect_same_name(c, t.name, a);
    ++n;
  }
  std::cout << "[ own engine ] " << n << " relaxed, turned curves: " << a.equal << " named alike, "
            << a.candidates << " left to the refinements, " << a.weaker << " with more candidates (weaker simplification)\n";
  EXPECT_GT(n, 80);
  EXPECT_LE(a.weaker, n / 10);
}
#endif

}  // namespace
}  // namespace s4d
