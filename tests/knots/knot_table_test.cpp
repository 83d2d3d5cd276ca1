// The knot table: names resolve (in every usual spelling) to diagrams, made curves are named back
// as themselves with the same chirality, torus knots and links come out right, and unknown names
// get an Error listing close matches.
#include "knots/knot_table.hpp"

#include <gtest/gtest.h>

#if S4D_WITH_REGINA
#include <link/link.h>
#endif

#include "core/error.hpp"
#include "knots/diagram_embedding.hpp"
#include "knots/knot_identify.hpp"
#include "knots/own_codes.hpp"
#if S4D_WITH_REGINA
#include "knots/regina_link.hpp"
#endif
#include "shape/knot_curves.hpp"

namespace s4d {
namespace {

// The single prime candidate's entry and chirality, or null.
const KnotFactor* single_prime(const KnotIdentification& id) {
  if (id.candidates.size() != 1 || id.candidates[0].size() != 1) return nullptr;
  return &id.candidates[0][0];
}

// The made curve is named as the table's knot (one candidate, that entry), with the chirality it
// was asked for (amphichiral or HOMFLY-blind knots say so instead).
void expect_named_back(const std::string& name, bool mirror) {
  SCOPED_TRACE(name + (mirror ? " mirror" : ""));
  const KnotTableEntry* e = KnotIndex::shipped().find_name(name);
  ASSERT_NE(e, nullptr);
  const Curve<3> c = make_table_knot(mirror ? name + " mirror" : name);
  const auto id = identify_knot(c);
  // The relaxed curve's fewest-crossing view need not be minimal; the name must still be unique.
  bool found = false;
  for (const auto& f : id.candidates)
    if (f.size() == 1 && f[0].entry == e) {
      found = true;
      if (e->homfly_symmetric)
        EXPECT_TRUE(f[0].chirality == Chirality::kAmphichiral || f[0].chirality == Chirality::kUnknown);
      else
        EXPECT_EQ(f[0].chirality, mirror ? Chirality::kMirror : Chirality::kAsTable);
    }
  EXPECT_TRUE(found) << "named " << id.name;
}

#if S4D_WITH_REGINA
TEST(KnotTable, DiagramFromReginaKeepsTheKnot) {
  // The index's diagram of 7_4, through our diagram: 7 crossings and the index's own key.
  const regina::Link l = regina::Link::fromKnotSig(KnotIndex::shipped().find_name("7_4")->sig);
  const KnotDiagram d = diagram_from_regina(l);
  EXPECT_EQ(d.crossing_count(), 7);
  EXPECT_EQ(compute_invariants(d).fingerprint, KnotIndex::shipped().find_name("7_4")->key);
}
#endif

TEST(KnotTable, CurvesOfCensusDiagramsKeepSignsAndKnot) {
  // curve_from_diagram without relaxation: the drawing's own diagram has the same crossings and
  // the same knot, in the same chirality.
  for (const char* name : {"3_1", "4_1", "7_4", "11n_34", "12a_803", "13nh_517", "14nh_7499"}) {
    SCOPED_TRACE(name);
    const KnotTableEntry* e = KnotIndex::shipped().find_name(name);
    ASSERT_NE(e, nullptr);
    const KnotDiagram d = diagram_from_knot_sig(e->sig);
    DiagramEmbedding raw;
    raw.relax_iterations = 0;
    const Curve<3> c = curve_from_diagram(d, raw);
    const KnotDiagram drawn = diagram_from_curve(c, Frame<3>());
    EXPECT_EQ(drawn.crossing_count(), d.crossing_count());
    EXPECT_EQ(drawn.writhe(), d.writhe());
    EXPECT_EQ(compute_invariants(drawn).fingerprint, e->key);
  }
}

TEST(KnotTable, TableKnotsAreNamedBackAsThemselvesWithTheirChirality) {
  for (const char* name : {"3_1", "4_1", "5_1", "5_2", "6_1", "7_4", "8_19", "9_42", "10_132", "10_165",
                           "11a_1", "11n_34", "12a_1", "12n_888", "13ah_1", "14nh_7499"}) {
    expect_named_back(name, false);
    expect_named_back(name, true);
  }
}

TEST(KnotTable, SpellingsAndMirrors) {
  EXPECT_EQ(table_knot("12a_0803").name, "12a_803");
  EXPECT_EQ(table_knot("K11n34").name, "11n_34");
  EXPECT_EQ(table_knot("11n34").name, "11n_34");
  EXPECT_TRUE(table_knot("m3_1").mirror);
  EXPECT_TRUE(table_knot("3_1*").mirror);
  EXPECT_EQ(table_knot("3_1 mirror").name, "3_1 mirror");
  EXPECT_FALSE(table_knot("T(2,5)").mirror);
  EXPECT_TRUE(table_knot("T(2,-5)").mirror);
  EXPECT_EQ(table_knot("L5a1").name, "L5a1");
  EXPECT_EQ(table_knot("Whitehead link").name, "L5a1");
}

TEST(KnotTable, TorusKnotsAreTheirTableKnots) {
  const std::vector<std::pair<std::string, std::string>> cases = {{"T(2,3)", "3_1"},  {"T(2,5)", "5_1"},
                                                                  {"T(3,4)", "8_19"}, {"T(3,5)", "10_124"},
                                                                  {"T(2,7)", "7_1"},  {"T(3,7)", "14n_21881"}};  // KnotInfo's name for T(3,7)
  for (const auto& [torus, knot] : cases) {
    SCOPED_TRACE(torus);
    for (bool mirror : {false, true}) {
      const auto made = identify_knot(make_table_knot(torus + (mirror ? " mirror" : "")));
      // The curve and the braid diagram of the name agree on chirality.
      const auto from_diagram = identify_diagram(table_knot(torus + (mirror ? " mirror" : "")).diagram);
      const KnotFactor* a = single_prime(made);
      const KnotFactor* b = single_prime(from_diagram);
      ASSERT_TRUE(a && b) << made.name;
      EXPECT_EQ(a->entry->display_name(), knot);
      EXPECT_EQ(a->entry, b->entry);
      EXPECT_EQ(a->chirality, b->chirality);
    }
  }
}

TEST(KnotTable, LinksOfTheTable) {
  const auto hopf = identify_knot(make_table_knot("Hopf link"));
  ASSERT_EQ(hopf.invariants.components, 2);
  EXPECT_EQ(std::abs(hopf.invariants.linking[0][1]), 1);
  const auto white = identify_knot(make_table_knot("Whitehead link"));
  ASSERT_EQ(white.invariants.components, 2);
  EXPECT_EQ(white.invariants.linking[0][1], 0);
  EXPECT_EQ(white.invariants.simplified_crossings, 5);
  EXPECT_EQ(white.components[0].name, "unknot");
  EXPECT_EQ(white.components[1].name, "unknot");
  EXPECT_EQ(white.link_name.find("unlink"), std::string::npos);
  const auto borromean = identify_knot(make_table_knot("Borromean rings"));
  EXPECT_EQ(borromean.invariants.components, 3);
  EXPECT_NE(borromean.link_name.find("Borromean"), std::string::npos);
}

TEST(KnotTable, NamesForThePicker) {
  const auto names = knot_table_names();
  ASSERT_GT(names.size(), 59937u);
  EXPECT_EQ(names[0].name, "unknot");
  EXPECT_EQ(names[1].name, "3_1");
  EXPECT_EQ(names[2].name, "4_1");
  int rolfsen = 0, torus = 0, links = 0;
  for (const auto& n : names) {
    rolfsen += n.source == "Rolfsen";
    torus += n.source == "torus";
    links += n.source == "link";
  }
  EXPECT_EQ(rolfsen, 249);
  EXPECT_GE(torus, 8);
  EXPECT_EQ(links, 1424);  // Thistlethwaite's table to 11 crossings
  // 8_2 before 8_10 (numbers, not text)
  auto at = [&](const std::string& s) {
    return std::find_if(names.begin(), names.end(), [&](const TableName& t) { return t.name == s; }) -
           names.begin();
  };
  EXPECT_LT(at("8_2"), at("8_10"));
  EXPECT_LT(at("10_165"), at("11a_1"));
}

TEST(KnotTable, UnknownNamesListCloseMatches) {
  try {
    table_knot("3_2");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no knot or link called '3_2'"), std::string::npos) << what;
    EXPECT_NE(what.find("3_1"), std::string::npos) << what;
  }
  EXPECT_THROW(table_knot(""), Error);
  EXPECT_THROW(table_knot("T(1,5)"), Error);
  EXPECT_THROW(table_knot("11n_9999"), Error);
  EXPECT_THROW(table_knot("banana"), Error);
}

TEST(KnotTable, DrawingRefusesWhatItCannotDraw) {
  KnotDiagram two_circles;
  two_circles.components.resize(2);
  EXPECT_THROW(curve_from_diagram(two_circles), Error);
  EXPECT_THROW(curve_from_diagram(KnotDiagram{}), Error);
}

}  // namespace
}  // namespace s4d
