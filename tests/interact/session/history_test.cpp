// History: undo gives back the state before a step, redo the one after; a new step drops what
// was undone; the bounds on steps and bytes hold.
#include <gtest/gtest.h>

#include "interact/session/history.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

DocumentState state_with(double x, int objects = 1) {
  DocumentState s;
  for (int i = 0; i < objects; ++i) {
    SceneObject o;
    o.name = "o";
    o.name += std::to_string(i);  // not "o" + ...: gcc 12 -O3 warns falsely (-Wrestrict)
    Surface<4> m;
    m.vertices = {Vec4(x, 0, 0, 0), Vec4(1, 0, 0, 0), Vec4(0, 1, 0, 0)};
    m.triangles = {{0, 1, 2}};
    o.shape = m;
    s.scene.objects.push_back(o);
  }
  return s;
}

double x_of(const DocumentState& s) { return std::get<Surface<4>>(s.scene.objects[0].shape).vertices[0].x(); }

TEST(History, UndoAndRedoWalkTheSteps) {
  History h;
  EXPECT_FALSE(h.undo(state_with(0)).has_value()) << "nothing to undo";
  h.record("drag 1", state_with(0));  // the state before each step
  h.record("drag 2", state_with(1));
  h.record("pin", state_with(2));
  // Now the document is at 3.
  auto s = h.undo(state_with(3));
  ASSERT_TRUE(s);
  EXPECT_EQ(x_of(*s), 2);
  s = h.undo(*s);
  EXPECT_EQ(x_of(*s), 1);
  EXPECT_EQ(h.done_labels(), (std::vector<std::string>{"drag 1"}));
  EXPECT_EQ(h.undone_labels(), (std::vector<std::string>{"drag 2", "pin"}));
  s = h.redo(*s);
  EXPECT_EQ(x_of(*s), 2);
  s = h.redo(*s);
  EXPECT_EQ(x_of(*s), 3) << "redo ends where the user was";
  EXPECT_FALSE(h.redo(*s).has_value());
  // Undo then a new step: the undone one cannot come back.
  s = h.undo(*s);
  h.record("crossing change", *s);
  EXPECT_FALSE(h.can_redo());
  EXPECT_EQ(h.done_labels(), (std::vector<std::string>{"drag 1", "drag 2", "crossing change"}));
}

TEST(History, BoundedInStepsAndBytes) {
  History few(3, std::size_t{1} << 30);
  for (int i = 0; i < 10; ++i) few.record("step " + std::to_string(i), state_with(i));
  EXPECT_EQ(few.done_labels(), (std::vector<std::string>{"step 7", "step 8", "step 9"}));
  EXPECT_EQ(few.dropped(), 7u);

  const std::size_t one = state_with(0, 50).bytes();
  History small(200, 5 * one + one / 2);
  for (int i = 0; i < 20; ++i) small.record("step", state_with(i, 50));
  EXPECT_EQ(small.done_labels().size(), 5u);
  EXPECT_LE(small.bytes(), 5 * one + one / 2);
  auto s = small.undo(state_with(20, 50));
  ASSERT_TRUE(s);
  EXPECT_EQ(x_of(*s), 19);
  EXPECT_LE(small.bytes(), 5 * one + one / 2) << "the redo state counts too";

  History defaults;
  EXPECT_EQ(History::kMaxSteps, 200u);
  EXPECT_EQ(History::kMaxBytes, std::size_t{256} << 20);
}

// What a session file keeps: the newest steps within its byte bound (the oldest done ones go
// first), and a load that does not match its labels is refused, leaving nothing to undo.
TEST(History, SavedWithinItsBoundAndLoadedBack) {
  History h;
  for (int i = 0; i < 6; ++i) h.record("step " + std::to_string(i), state_with(i, 20));
  auto s = h.undo(state_with(6, 20));  // one step undone: a redo state
  ASSERT_TRUE(s);
  const std::size_t one = state_with(0, 20).bytes();
  const History::Saved all = h.to_save();
  EXPECT_EQ(all.labels.size(), 6u);
  EXPECT_EQ(all.head, 5u);
  const History::Saved some = h.to_save(3 * one + one / 2);
  ASSERT_EQ(some.states.size(), 3u);
  EXPECT_EQ(some.head, 2u) << "the oldest done steps are left out, the redo step kept";
  EXPECT_EQ(some.labels.front(), "step 3");
  EXPECT_EQ(x_of(*some.states.back()), 6) << "the redo step's state: after it";

  History back;
  ASSERT_TRUE(back.load(some.labels, some.states, some.head));
  auto u = back.undo(state_with(5, 20));
  ASSERT_TRUE(u);
  EXPECT_EQ(x_of(*u), 4);
  EXPECT_EQ(back.undone_labels().size(), 2u);

  History wrong;
  EXPECT_FALSE(wrong.load({"a", "b"}, {some.states.front()}, 1)) << "one state for two labels";
  EXPECT_FALSE(wrong.can_undo());
  EXPECT_FALSE(wrong.load({"a"}, {some.states.front()}, 2)) << "a head past the end";
}

}  // namespace
}  // namespace s4d
