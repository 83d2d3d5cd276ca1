// The live panel's engine: known polynomials (from the skein relation and the Knot Atlas),
// writhe and linking signs, names with chirality, DT names above 10 crossings, candidates and
// proofs reported honestly, the worker thread, and errors for bad curves.
#include "knots/knot_info.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/plane.hpp"
#include "knots/braid_closure.hpp"
#include "knots/knot_table.hpp"
#include "shape/knot_curves.hpp"

namespace s4d {
namespace {

// A polynomial in s = t^(1/2) from coefficients of powers of t.
Laurent1 in_t(std::initializer_list<std::pair<long, std::int64_t>> terms) {
  Laurent1 p;
  for (const auto& [e, c] : terms) p.add(2 * e, c);
  return p;
}

// The Knot Atlas's 3_1 (braid sigma_1^-3) is the left-handed trefoil. By the skein relation
// a P+ - a^-1 P- = z P0 with P(unknot) = 1 (Regina's convention): P = 2a^2 - a^4 + a^2 z^2.
TEST(KnotInfo, TrefoilPolynomialsAndChirality) {
  const KnotInfo k = knot_info(make_table_knot("3_1"));
  Laurent2 h;
  h.add(2, 0, 2);
  h.add(4, 0, -1);
  h.add(2, 2, 1);
  EXPECT_EQ(k.identification.invariants.homfly, h) << k.homfly;
  EXPECT_EQ(k.identification.invariants.jones, in_t({{-4, -1}, {-3, 1}, {-1, 1}})) << k.jones;
  EXPECT_EQ(k.identification.invariants.alexander, in_t({{-1, 1}, {0, -1}, {1, 1}})) << k.alexander;
  EXPECT_EQ(k.alexander, "t - 1 + t^-1");
  EXPECT_EQ(k.determinant, 3);
  EXPECT_EQ(k.name, "3_1 (DT 3a_1)");
  EXPECT_TRUE(k.proven);
  EXPECT_NE(k.chirality.find("not its mirror image"), std::string::npos) << k.chirality;
  ASSERT_EQ(k.candidates.size(), 1u);
  EXPECT_FALSE(k.decided_by.empty());

  const KnotInfo m = knot_info(make_table_knot("3_1 mirror"));
  EXPECT_EQ(m.identification.invariants.homfly, h.mirror_alpha());
  EXPECT_EQ(m.identification.invariants.jones, in_t({{4, -1}, {3, 1}, {1, 1}})) << m.jones;
  EXPECT_EQ(m.name, "3_1 mirror (DT 3a_1)");
  EXPECT_NE(m.chirality.find("mirror image of 3_1"), std::string::npos) << m.chirality;
}

TEST(KnotInfo, FigureEightAndCinquefoil) {
  const KnotInfo f = knot_info(figure_eight_knot(200), std::nullopt);
  EXPECT_EQ(f.identification.invariants.jones, in_t({{-2, 1}, {-1, -1}, {0, 1}, {1, -1}, {2, 1}})) << f.jones;
  EXPECT_EQ(f.identification.invariants.alexander, in_t({{-1, -1}, {0, 3}, {1, -1}}));
  EXPECT_EQ(f.determinant, 5);
  EXPECT_EQ(f.name, "4_1 (DT 4a_1)");
  EXPECT_NE(f.chirality.find("amphichiral"), std::string::npos) << f.chirality;

  // 5_1 (Knot Atlas, left-handed): V = -t^-7 + t^-6 - t^-5 + t^-4 + t^-2, Delta = t^2 - t + 1 - ...
  const KnotInfo c = knot_info(make_table_knot("5_1"));
  EXPECT_EQ(c.identification.invariants.jones, in_t({{-7, -1}, {-6, 1}, {-5, -1}, {-4, 1}, {-2, 1}}))
      << c.jones;
  EXPECT_EQ(c.identification.invariants.alexander, in_t({{-2, 1}, {-1, -1}, {0, 1}, {1, -1}, {2, 1}}));
  EXPECT_EQ(c.determinant, 5);
}

TEST(KnotInfo, CrossingsGaussAndWritheInTheView) {
  // The positive braid sigma_1^3 seen from +z: three positive crossings, writhe +3; its mirror -3.
  const Curve<3> t = braid_closure(2, {1, 1, 1});
  const KnotInfo k = knot_info(t, Frame<3>());
  EXPECT_EQ(k.view_crossings, 3);
  EXPECT_EQ(k.simplified_crossings, 3);
  EXPECT_EQ(k.writhe, 3);
  EXPECT_EQ(k.gauss_code, "1, -2, 3, -1, 2, -3");
  EXPECT_EQ(knot_info(braid_closure(2, {-1, -1, -1})).writhe, -3);
  // A view from the side of the same curve: more crossings, the same knot.
  Frame<3> side;
  side.rotate(*parse_plane("yz", 3), 1.4);
  const KnotInfo s = knot_info(t, side);
  EXPECT_NE(s.view_crossings, 3);
  EXPECT_EQ(s.name, k.name);
  // Two extra crossings from a kink: 5 in the view, 3 after simplification.
  const KnotInfo kinked = knot_info(braid_closure(3, {1, 1, 1, 2, -2}), Frame<3>());
  EXPECT_EQ(kinked.view_crossings, 5);
  EXPECT_EQ(kinked.simplified_crossings, 3);
}

TEST(KnotInfo, LinkingNumbers) {
  const KnotInfo hopf = knot_info(make_table_knot("Hopf link"));
  ASSERT_EQ(hopf.components, 2);
  EXPECT_EQ(hopf.linking[0][1], 1);  // sigma_1^2: two positive crossings
  EXPECT_EQ(knot_info(make_table_knot("Hopf link mirror")).linking[0][1], -1);
  const KnotInfo white = knot_info(make_table_knot("Whitehead link"));
  EXPECT_EQ(white.linking[0][1], 0);
  // Named from the link table; proven since no other link of the table (nor a split or composite
  // one) has its invariants.
  EXPECT_TRUE(white.proven);
  EXPECT_EQ(white.name, "L5a1 (Whitehead link)");
  EXPECT_EQ(white.chirality.find("L5a1"), 0u) << white.chirality;
}

TEST(KnotInfo, TwelveCrossingKnotsHaveDTNames) {
  for (const char* name : {"12a_1", "12a_803", "12n_888"}) {
    const KnotInfo k = knot_info(make_table_knot(name));
    EXPECT_EQ(k.name, name);
    EXPECT_TRUE(k.proven) << name;
  }
}

TEST(KnotInfo, ThirteenAndFourteenCrossingKnotsUseDTNamesWhenTheIndexHasThem) {
  const KnotIndex& idx = KnotIndex::shipped();
  int named = 0;
  for (const auto& e : idx.entries()) named += e.crossings >= 13 && !e.dt_name.empty();
  if (named == 0)
    GTEST_SKIP()
        << "the shipped index has no DT names above 12 crossings (data/knots/README.md says how to add them)";
  for (const auto& e : idx.entries())
    if (e.crossings == 13 && !e.dt_name.empty()) {
      EXPECT_EQ(knot_info(make_table_knot(e.dt_name)).name, e.dt_name);
      break;
    }
}

TEST(KnotInfo, CandidatesAndProofsAreReportedHonestly) {
  // The Conway knot 11n_34 and the Kinoshita-Terasaka knot 11n_42 are mutants: the same
  // HOMFLY-PT, Jones and Alexander polynomials.
  const Curve<3> conway = make_table_knot("11n_34");
  KnotInfoOptions plain;
  plain.fast = true;
  const KnotInfo p = knot_info(conway, std::nullopt, plain);
  EXPECT_FALSE(p.proven);
  EXPECT_EQ(p.candidates, (std::vector<std::string>{"11n_34", "11n_42"}));
  EXPECT_NE(p.name.find("one of"), std::string::npos);
  EXPECT_TRUE(p.further_used.empty());
  // With the further invariants: they are tried and named; whatever they conclude keeps the truth.
  const KnotInfo r = knot_info(conway);
  EXPECT_FALSE(r.further_used.empty());
  EXPECT_NE(std::find(r.candidates.begin(), r.candidates.end(), "11n_34"), r.candidates.end());
  if (r.proven) {
    EXPECT_EQ(r.name, "11n_34");
    EXPECT_FALSE(r.decided_by.empty());
  }
  // 14 crossings and beyond the census: not proven, and it says why.
  const KnotInfo big = knot_info(make_table_knot("T(2,15)"), std::nullopt, plain);
  EXPECT_FALSE(big.proven);
  EXPECT_NE(big.name.find("unknown"), std::string::npos) << big.name;
}

TEST(KnotInfo, CoverSignaturesSeparateKnotGroups) {
  if (!regina_available()) GTEST_SKIP() << "covers of the knot group need Regina";
  const KnotDiagram t = braid_diagram(2, {1, 1, 1});
  const KnotDiagram m = braid_diagram(2, {-1, -1, -1});
  const KnotDiagram f = braid_diagram(3, {1, -2, 1, -2});
  EXPECT_EQ(cover_signature(t, 4), cover_signature(m, 4));  // mirror images: the same group
  EXPECT_NE(cover_signature(t, 4), cover_signature(f, 4));  // 3_1 and 4_1: different groups
  EXPECT_THROW(cover_signature(t, 8), Error);
}

TEST(KnotInfo, WorkerGivesTheNewestResultAndSaysWhyACurveIsRefused) {
  KnotInfoWorker w;
  EXPECT_EQ(w.latest(), nullptr);
  w.submit(torus_knot(2, 3, 200));
  w.submit(torus_knot(2, 5, 200));
  const std::uint64_t last = w.submit(figure_eight_knot(200));
  ASSERT_TRUE(w.wait_for(last, 20000));
  const auto r = w.latest();
  ASSERT_TRUE(r && r->info);
  EXPECT_EQ(r->request, last);
  EXPECT_EQ(r->info->name, "4_1 (DT 4a_1)");
  Curve<3> open = torus_knot(2, 3, 50);
  open.components[0].closed = false;
  const std::uint64_t bad = w.submit(open);
  ASSERT_TRUE(w.wait_for(bad, 20000));
  EXPECT_FALSE(w.latest()->info.has_value());
  EXPECT_FALSE(w.latest()->error.empty());
}

TEST(KnotInfo, BadCurvesAreRefused) {
  Curve<3> open = torus_knot(2, 3, 50);
  open.components[0].closed = false;
  EXPECT_THROW(knot_info(open), Error);
  EXPECT_THROW(knot_info(Curve<3>{}), Error);
}

}  // namespace
}  // namespace s4d
