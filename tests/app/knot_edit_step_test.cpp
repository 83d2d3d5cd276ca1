// The Knot panel's toolbar edits on a headless Session: each is one step of the history whose undo
// puts the curve back, a simulated knot takes the edit, and a refused edit changes nothing.
#include "app/knot_edit_step.hpp"

#include <gtest/gtest.h>

#include "knots/curve_edits.hpp"
#include "knots/knot_identify.hpp"
#include "knots/knot_table.hpp"

namespace s4d {
namespace {

void open_stepped(Session& s, const std::string& name, Curve<3> curve) {
  Document d;
  SceneObject o;
  o.name = name;
  o.shape = std::move(curve);
  d.scene.objects.push_back(o);
  d.scene.physics.thickness = 0.05;
  SessionOptions opt;
  opt.threaded = false;
  opt.async_physics = false;
  s.open(std::move(d), opt);
}

const Curve<3>& curve(Session& s) { return std::get<Curve<3>>(s.scene().objects[0].shape); }

TEST(KnotEditStep, MirrorIsOneStepAndItsUndoPutsTheKnotBack) {
  Session s;
  open_stepped(s, "k", make_table_knot("5_2"));
  ASSERT_TRUE(s.simulating()) << s.physics_error();
  const Curve<3> before = curve(s);
  EXPECT_EQ(edit_curve_object(s, 0, "mirror", mirrored_curve), "mirror 'k'");
  ASSERT_EQ(s.history().done_labels().size(), 1u);
  EXPECT_EQ(s.history().done_labels().back(), "mirror 'k'");
  EXPECT_EQ(identify_knot(curve(s)).name, "5_2 mirror (DT 5a_1)");
  s.loop()->run_ticks(20);
  s.refresh();
  EXPECT_EQ(identify_knot(curve(s)).name, "5_2 mirror (DT 5a_1)") << "the simulated knot took the mirror image";
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(identify_knot(curve(s)).name, "5_2 (DT 5a_1)");
  const auto& p = curve(s).components[0].points;
  for (std::size_t i = 0; i < p.size(); ++i) ASSERT_LT((p[i] - before.components[0].points[i]).norm(), 1e-9) << i;
  ASSERT_TRUE(s.redo());
  EXPECT_EQ(identify_knot(curve(s)).name, "5_2 mirror (DT 5a_1)");
}

TEST(KnotEditStep, ReverseAndDeleteAComponentOfALinkAndUndoThem) {
  Session s;
  open_stepped(s, "hopf", make_table_knot("Hopf link"));
  ASSERT_TRUE(s.simulating()) << s.physics_error();
  const int lk = identify_knot(curve(s)).invariants.linking[0][1];
  edit_curve_object(s, 0, "reverse component 2 of", [](const Curve<3>& c) { return with_component_reversed(c, 1); });
  EXPECT_EQ(identify_knot(curve(s)).invariants.linking[0][1], -lk);
  edit_curve_object(s, 0, "delete component 2 of", [](const Curve<3>& c) { return with_component_deleted(c, 1); });
  EXPECT_EQ(curve(s).components.size(), 1u);
  EXPECT_TRUE(s.simulating()) << "the bodies are built again with one component";
  EXPECT_EQ(s.history().done_labels(),
            (std::vector<std::string>{"reverse component 2 of 'hopf'", "delete component 2 of 'hopf'"}));
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(curve(s).components.size(), 2u);
  EXPECT_EQ(identify_knot(curve(s)).invariants.linking[0][1], -lk);
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(identify_knot(curve(s)).invariants.linking[0][1], lk);
}

TEST(KnotEditStep, ARefusedEditChangesNothing) {
  Session s;
  open_stepped(s, "k", make_table_knot("3_1"));
  const std::string line =
      edit_curve_object(s, 0, "delete component 1 of", [](const Curve<3>& c) { return with_component_deleted(c, 0); });
  EXPECT_EQ(line, "cannot delete component 1 of: cannot delete the only component: a knot needs a curve");
  EXPECT_TRUE(s.history().done_labels().empty());
  EXPECT_EQ(curve(s).components.size(), 1u);
  EXPECT_EQ(edit_curve_object(s, 3, "mirror", mirrored_curve), "no such curve");
}

}  // namespace
}  // namespace s4d
