// The explore tool on a headless Session: the probe, run inside the live simulation's tick,
// keeps to its sheet across the shadow's intersection line and reports one pass, below in w.
#include <gtest/gtest.h>

#include <filesystem>

#include "interact/tools/explore_tool.hpp"
#include "interact/live/live_simulation.hpp"
#include "interact/session/session.hpp"

namespace s4d {
namespace {

TEST(ExploreTool, TheProbeKeepsItsSheetAndHearsOnePassBelow) {
  // Sheet A: z = 0 at w = -0.5; sheet B: z = (y - 0.1) / 2 at w = +0.5 (see the file).
  Document d = load_document((std::filesystem::path(S4D_SOURCE_DIR) / "tests/interact/data/explore_two_sheets.4off").string());
  SessionOptions o;
  o.threaded = false;
  o.async_physics = false;
  Session session;
  session.open(std::move(d), o);
  ASSERT_TRUE(session.simulating()) << session.physics_error();
  session.set_mapping(DeviceMapping::fit(Vec3::Zero(), 1.5, Mat<3>::Identity(), Vec3::Zero(), Vec3::Constant(0.1)));
  session.loop()->run_ticks(1);
  session.refresh();

  ExploreTool tool;
  ToolInput in;
  in.view.eye = Vec3(0, -0.5, 5);  // A (z = 0) is nearer this eye than B (z = -0.3) here
  in.view.ray = Vec3(0, 0, -1);
  ASSERT_TRUE(tool.press(in, session));
  // The hand walks along y across the line y = 0.1 where the two shadows cross, in A's plane.
  for (int i = 0; i <= 100; ++i) {
    in.view.eye = Vec3(0, -0.5 + 0.01 * i, 5);
    tool.drag(in, session);
    session.loop()->run_ticks(20);
    session.refresh();
    tool.update(in, session);
    ASSERT_TRUE(session.snapshot()->status.exploring);
    EXPECT_NEAR(session.snapshot()->status.probe_w, -0.5, 1e-9) << "the probe stays on A, step " << i;
  }
  const HapticSnapshot& snap = *session.snapshot();
  EXPECT_GT(snap.status.probe.y(), 0.3) << "it followed the hand past the line";
  EXPECT_NEAR(snap.status.probe.z(), 0, 1e-9) << "on A's plane, not B's";
  ASSERT_EQ(tool.passes().size(), 1u);
  EXPECT_EQ(tool.passes()[0].kind, kEventPassedBelow) << "B is nearer in w where they cross";
  EXPECT_NEAR(tool.passes()[0].point[1], 0.1, 0.02);
  EXPECT_NEAR(tool.passes()[0].w_other, 0.5, 1e-9);
  EXPECT_EQ(tool.take_new_passes().size(), 1u);
  EXPECT_TRUE(tool.take_new_passes().empty()) << "each pass is played once";
  EXPECT_GT(snap.max_force_output, 0) << "the navigation spring is felt";
  tool.release(in, session);
  session.loop()->run_ticks(1);
  session.refresh();
  EXPECT_FALSE(session.snapshot()->status.exploring);
}

TEST(ExploreTool, AWorldOfR3HasNoWToExplore) {
  Document d = load_document("trefoil-ribbon-3d");
  SessionOptions o;
  o.threaded = false;
  o.async_physics = false;
  Session session;
  session.open(std::move(d), o);
  ASSERT_TRUE(session.simulating());
  session.loop()->run_ticks(1);
  session.refresh();
  ExploreTool tool;
  ToolInput in;
  in.view.eye = Vec3(0, 0, 10);
  in.view.ray = Vec3(0, 0, -1);
  for (double x = -2; x <= 2 && !tool.press(in, session); x += 0.05) in.view.eye = Vec3(x, 0, 10);
  EXPECT_FALSE(session.snapshot()->status.exploring);
}

}  // namespace
}  // namespace s4d
