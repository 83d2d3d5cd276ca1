// Identification of curves: torus knots, mirrors, the knot table's own diagrams, links, and the
// invariance of the answer under rotations, reversals and resampling.
#include "knots/knot_identify.hpp"

#include <gtest/gtest.h>

#include <random>

#include "knots/braid_closure.hpp"
#include "knots/resample.hpp"
#include "shape/knot_curves.hpp"

namespace s4d {
namespace {

std::string prime_name(const KnotIdentification& id) {
  if (id.candidates.size() != 1 || id.candidates[0].size() != 1) return "?";
  return id.candidates[0][0].entry->display_name();
}
Chirality prime_chirality(const KnotIdentification& id) { return id.candidates.at(0).at(0).chirality; }

Curve<3> rotated(const Curve<3>& c, const Mat<3>& r) {
  Curve<3> out = c;
  for (auto& pl : out.components)
    for (auto& p : pl.points) p = r * p;
  return out;
}

Curve<3> reversed(const Curve<3>& c) {
  Curve<3> out = c;
  for (auto& pl : out.components) std::reverse(pl.points.begin(), pl.points.end());
  return out;
}

Curve<3> mirrored(const Curve<3>& c) {
  Curve<3> out = c;
  for (auto& pl : out.components)
    for (auto& p : pl.points) p.z() = -p.z();
  return out;
}

Mat<3> random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized().toRotationMatrix();
}

TEST(KnotIdentify, TorusKnotT23IsTheTrefoil) {
  const auto id = identify_knot(torus_knot(2, 3, 120));
  EXPECT_EQ(id.kind, KnotKind::kPrime);
  EXPECT_EQ(prime_name(id), "3_1");
  EXPECT_TRUE(id.proven);
  EXPECT_EQ(id.invariants.determinant, 3);
  EXPECT_EQ(id.invariants.simplified_crossings, 3);
}

TEST(KnotIdentify, TorusKnotT25IsCinquefoilNot10_132) {
  // 5_1 and 10_132 share HOMFLY-PT; the 5-crossing diagram rules 10_132 out.
  const auto id = identify_knot(torus_knot(2, 5, 200));
  EXPECT_EQ(prime_name(id), "5_1");
  EXPECT_TRUE(id.proven);
}

TEST(KnotIdentify, TorusKnotT34Is8_19) {
  const auto id = identify_knot(torus_knot(3, 4, 300));
  EXPECT_EQ(prime_name(id), "8_19");
  EXPECT_EQ(id.candidates[0][0].entry->dt_name, "8n_3");
}

TEST(KnotIdentify, T23AndT32AreTheSameKnot) {
  const auto c = compare_knots(torus_knot(2, 3, 120), torus_knot(3, 2, 120));
  EXPECT_EQ(c.verdict, Sameness::kSame) << c.reason;
}

TEST(KnotIdentify, T23AndT2Minus3AreMirrorImages) {
  const auto a = identify_knot(torus_knot(2, 3, 120));
  const auto b = identify_knot(torus_knot(2, -3, 120));
  EXPECT_EQ(prime_name(a), "3_1");
  EXPECT_EQ(prime_name(b), "3_1");
  EXPECT_NE(prime_chirality(a), prime_chirality(b));
  EXPECT_EQ(compare_knots(torus_knot(2, 3, 120), torus_knot(2, -3, 120)).verdict, Sameness::kMirror);
}

TEST(KnotIdentify, FigureEightIsAmphichiral) {
  const Curve<3> k = figure_eight_knot(200);
  const auto id = identify_knot(k);
  EXPECT_EQ(prime_name(id), "4_1");
  EXPECT_EQ(prime_chirality(id), Chirality::kAmphichiral);
  EXPECT_EQ(compare_knots(k, mirrored(k)).verdict, Sameness::kSame);
}

TEST(KnotIdentify, EveryRolfsenTableEntryIdentifiesAsItself) {
  const auto table = load_braid_table(S4D_SOURCE_DIR "/data/knots/rolfsen_braids.txt");
  ASSERT_EQ(table.size(), 249u);
  int checked = 0;
  for (const auto& b : table) {
    const auto id = identify_knot(braid_closure(b.strands, b.word, 5));
    ASSERT_FALSE(id.candidates.empty()) << b.name;
    bool found = false;
    for (const auto& f : id.candidates)
      if (f.size() == 1 && f[0].entry->rolfsen_name == b.name) {
        found = true;
        // The table's own diagram is the reference chirality.
        EXPECT_TRUE(f[0].chirality == Chirality::kAsTable ||
                    f[0].chirality == Chirality::kAmphichiral ||
                    f[0].chirality == Chirality::kUnknown)
            << b.name;
      }
    EXPECT_TRUE(found) << b.name << " identified as " << id.name;
    ++checked;
  }
  EXPECT_EQ(checked, 249);
}

TEST(KnotIdentify, RotationsReversalsAndResamplingNeverChangeTheAnswer) {
  std::mt19937 rng(7);
  const auto table = load_braid_table(S4D_SOURCE_DIR "/data/knots/rolfsen_braids.txt");
  for (const char* name : {"3_1", "5_2", "7_4", "8_19", "9_42", "10_132"}) {
    const auto it = std::find_if(table.begin(), table.end(), [&](const auto& b) { return b.name == name; });
    ASSERT_NE(it, table.end());
    const Curve<3> base = braid_closure(it->strands, it->word, 7);
    const auto ref = identify_knot(base);
    for (int trial = 0; trial < 4; ++trial) {
      Curve<3> c = rotated(base, random_rotation(rng));
      if (trial % 2) c = reversed(c);
      if (trial >= 2) c = resample_curve_to_count(c, 300 + 50 * trial);
      const auto id = identify_knot(c);
      EXPECT_EQ(id.name, ref.name) << name << " trial " << trial;
    }
  }
}

TEST(KnotIdentify, UnknotWithManyCrossingsInSomeProjection) {
  // A closed braid conjugated by a long word: the unknot, drawn with dozens of crossings.
  std::vector<int> w{1, -2, 3, 2, -1, 2, 3, -2, -3, 1, 1, 2};
  std::vector<int> word = w;
  for (int g : {1, 2, 3}) word.push_back(g);
  for (auto it = w.rbegin(); it != w.rend(); ++it) word.push_back(-*it);
  const Curve<3> c = braid_closure(4, word, 5);
  const KnotDiagram d = diagram_from_curve(c, Frame<3>());
  EXPECT_EQ(d.crossing_count(), static_cast<int>(word.size()));
  const auto id = identify_knot(c);
  EXPECT_EQ(id.kind, KnotKind::kUnknot);
  EXPECT_TRUE(id.proven);

  // And a curve with 0 crossings seen from above, many seen from the side: T(1, 9) on a torus.
  const Curve<3> t = torus_knot(1, 9, 400);
  const KnotDiagram top = diagram_from_curve(t, Frame<3>());
  Frame<3> side;
  side.rotate(Plane{1, 2}, 1.3);
  const KnotDiagram sd = diagram_from_curve(t, side);
  EXPECT_EQ(top.crossing_count(), 0);
  EXPECT_GE(sd.crossing_count(), 8);
  IdentifyOptions o;
  o.frame = side;
  o.choose_view = false;
  EXPECT_EQ(identify_knot(t, o).kind, KnotKind::kUnknot);
}

TEST(KnotIdentify, CrossingChangeOnTheTrefoilGivesTheUnknot) {
  const KnotDiagram d = braid_diagram(2, {1, 1, 1});
  EXPECT_EQ(identify_diagram(d).kind, KnotKind::kPrime);
  for (int k = 0; k < 3; ++k) {
    const auto id = identify_diagram(d.with_crossing_changed(k));
    EXPECT_EQ(id.kind, KnotKind::kUnknot);
    EXPECT_TRUE(id.proven);
  }
}

TEST(KnotIdentify, CompositeKnotsFactorise) {
  // Granny knot 3_1 # 3_1 and square knot 3_1 # 3_1 mirror, as braids on 3 strands.
  const auto granny = identify_knot(braid_closure(3, {1, 1, 1, 2, 2, 2}));
  EXPECT_EQ(granny.kind, KnotKind::kComposite) << granny.name;
  ASSERT_FALSE(granny.candidates.empty());
  EXPECT_EQ(granny.candidates[0].size(), 2u);
  EXPECT_EQ(granny.candidates[0][0].chirality, granny.candidates[0][1].chirality);
  const auto square = identify_knot(braid_closure(3, {1, 1, 1, -2, -2, -2}));
  EXPECT_EQ(square.kind, KnotKind::kComposite) << square.name;
  ASSERT_FALSE(square.candidates.empty());
  EXPECT_NE(square.candidates[0][0].chirality, square.candidates[0][1].chirality);
  EXPECT_EQ(
      compare_knots(braid_closure(3, {1, 1, 1, 2, 2, 2}), braid_closure(3, {1, 1, 1, -2, -2, -2})).verdict,
      Sameness::kDifferent);
}

TEST(KnotIdentify, LinksByComponentsAndLinkingNumbers) {
  const auto hopf = identify_knot(braid_closure(2, {1, 1}));
  EXPECT_EQ(hopf.kind, KnotKind::kLink);
  ASSERT_EQ(hopf.components.size(), 2u);
  EXPECT_EQ(hopf.components[0].kind, KnotKind::kUnknot);
  EXPECT_EQ(std::abs(hopf.invariants.linking[0][1]), 1);
  EXPECT_NE(hopf.link_name.find("Hopf"), std::string::npos) << hopf.name;

  const auto borromean = identify_knot(braid_closure(3, {1, -2, 1, -2, 1, -2}));
  ASSERT_EQ(borromean.components.size(), 3u);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(borromean.invariants.linking[i][j], 0);
  EXPECT_NE(borromean.link_name.find("Borromean"), std::string::npos) << borromean.name;

  // T(2,4) from the shape generator: two components, linking number 2.
  const auto t24 = identify_knot(torus_knot(2, 4, 200));
  EXPECT_EQ(std::abs(t24.invariants.linking[0][1]), 2);
  // Both chiralities are recognised (a link's mirror flips the sign of odd powers of alpha).
  EXPECT_NE(t24.link_name.find("Solomon"), std::string::npos) << t24.name;
  const auto t2m4 = identify_knot(torus_knot(2, -4, 200));
  EXPECT_NE(t2m4.link_name.find("Solomon"), std::string::npos) << t2m4.name;
  // As the link table draws L4a1 or its mirror image: one of them is named a mirror.
  EXPECT_NE(t24.name, t2m4.name);
  EXPECT_NE((t24.name + t2m4.name).find("L4a1 mirror"), std::string::npos) << t24.name << " / " << t2m4.name;
}

}  // namespace
}  // namespace s4d
