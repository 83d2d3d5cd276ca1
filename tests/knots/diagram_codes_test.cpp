// PD and DT codes in and out: round trips over the tables (every knot to 12 crossings, every link
// of Thistlethwaite's table), the spellings of KnotInfo, KnotTheory` and SnapPy, the chirality a
// PD code carries, and clear errors for what is no code.
#include "knots/diagram_codes.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "knots/diagram_embedding.hpp"
#include "knots/knot_identify.hpp"
#include "knots/knot_table.hpp"

namespace s4d {
namespace {

TEST(DiagramCodes, PdRoundTripsForEveryTableKnotAndLink) {
  int knots = 0, links = 0;
  for (const KnotTableEntry& e : KnotIndex::shipped().entries()) {
    if (e.crossings > 12) continue;
    const KnotDiagram d = table_knot(e.display_name()).diagram;
    const KnotDiagram back = diagram_from_pd(pd_list(d));
    ASSERT_EQ(back.signed_gauss_code(), d.signed_gauss_code()) << e.display_name();
    ++knots;
  }
  for (const LinkTableEntry& e : LinkTable::shipped().entries()) {
    const KnotDiagram d = link_diagram(e);
    const KnotDiagram back = diagram_from_pd(pd_list(d));
    ASSERT_EQ(back.signed_gauss_code(), d.signed_gauss_code()) << e.name;
    ASSERT_EQ(diagram_from_pd(e.pd).signed_gauss_code(), d.signed_gauss_code()) << "the table's own code, " << e.name;
    ++links;
  }
  EXPECT_EQ(knots, 249 + 552 + 2176);
  EXPECT_EQ(links, 1424);
}

// A DT code names a prime knot up to mirror image: read back, the same code and the same HOMFLY-PT
// polynomial or its mirror's.
TEST(DiagramCodes, DtRoundTripsForEveryTableKnotUpToMirrorImage) {
  if (!regina_available()) GTEST_SKIP() << "reading DT codes needs Regina";
  int knots = 0;
  for (const KnotTableEntry& e : KnotIndex::shipped().entries()) {
    if (e.crossings > 12) continue;
    const KnotDiagram d = table_knot(e.display_name()).diagram;
    const std::string dt = dt_code(d);
    const KnotDiagram back = diagram_from_dt(dt);
    ASSERT_EQ(dt_code(back), dt) << e.display_name();
    if (e.crossings <= 10) {
      const std::uint64_t key = compute_invariants(back).fingerprint;
      EXPECT_TRUE(key == e.key || key == e.mirror_key) << e.display_name();
    }
    ++knots;
  }
  EXPECT_EQ(knots, 249 + 552 + 2176);
}

TEST(DiagramCodes, TheSpellingsOfEverySourceAreOneCode) {
  if (!regina_available()) GTEST_SKIP() << "reading DT codes needs Regina";
  const std::string want = diagram_from_pd("[[1,5,2,4],[3,1,4,6],[5,3,6,2]]").signed_gauss_code();
  EXPECT_EQ(diagram_from_pd("PD[X[1, 5, 2, 4], X[3, 1, 4, 6], X[5, 3, 6, 2]]").signed_gauss_code(), want);
  EXPECT_EQ(diagram_from_pd("[(1,5,2,4),(3,1,4,6),(5,3,6,2)]").signed_gauss_code(), want);
  EXPECT_EQ(diagram_from_pd("{{1,5,2,4},{3,1,4,6},{5,3,6,2}}").signed_gauss_code(), want);
  const std::string dt = diagram_from_dt("4 6 2").signed_gauss_code();
  for (const char* s : {"[4, 6, 2]", "(4,6,2)", "DT[4, 6, 2]", "bca"}) EXPECT_EQ(diagram_from_dt(s).signed_gauss_code(), dt) << s;
}

// The Knot Atlas's 3_1 is the left-handed trefoil: its PD code comes back as 3_1, the example of
// issue 37 (its mirror image) as 3_1 mirror, and both are drawn as curves that keep it.
TEST(DiagramCodes, APdCodeCarriesItsChiralityIntoTheCurve) {
  DiagramEmbedding raw;
  raw.relax_iterations = 0;
  const auto left = identify_knot(curve_from_diagram(diagram_from_pd("X[1,4,2,5], X[3,6,4,1], X[5,2,6,3]"), raw));
  EXPECT_EQ(left.name, "3_1 (DT 3a_1)");
  const auto right = identify_knot(curve_from_diagram(diagram_from_pd("[[1,5,2,4],[3,1,4,6],[5,3,6,2]]"), raw));
  EXPECT_EQ(right.name, "3_1 mirror (DT 3a_1)");
  const auto borromean = identify_knot(curve_from_diagram(diagram_from_pd(table_knot("L6a4").link->pd), raw));
  EXPECT_EQ(borromean.name, "L6a4 (Borromean rings)");
}

// The census diagrams of 7_7 and 9_40, drawn with their largest face outside, lost a crossing; the
// drawing then takes the next face. (A scratch run drew all 801 knots to 11 crossings.)
TEST(DiagramCodes, CodesWhoseFirstDrawingLosesACrossingAreDrawnWithAnotherFaceOutside) {
  DiagramEmbedding raw;
  raw.relax_iterations = 0;
  for (const char* name : {"7_7", "9_40"}) {
    const KnotDiagram d = diagram_from_pd(pd_list(table_knot(name).diagram));
    const auto id = identify_knot(curve_from_diagram(d, raw));
    EXPECT_EQ(id.name.rfind(name, 0), 0u) << id.name;
    EXPECT_EQ(identify_knot(curve_from_diagram(d.mirrored(), raw)).invariants.homfly, id.invariants.homfly.mirror_alpha());
  }
}

TEST(DiagramCodes, WhatIsNoCodeIsRefusedWithAReason) {
  for (const char* bad : {"", "hello", "[[1,2,3]]", "[[1,5,2,4],[3,1,4,6]]"}) EXPECT_THROW(diagram_from_pd(bad), Error) << bad;
  for (const char* bad : {"", "4 6", "3 5 7", "[]"}) EXPECT_THROW(diagram_from_dt(bad), Error) << bad;
  EXPECT_THROW(dt_code(link_diagram(*LinkTable::shipped().find_name("L2a1"))), Error);
}

}  // namespace
}  // namespace s4d
