// Session files: every part round-trips exactly, old versions open, newer and damaged ones are
// refused with the reason, and the write is atomic (the old file survives a failed write).
#include <gtest/gtest.h>

#include <memory>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/session_file.hpp"
#include "io/text_scanner.hpp"
#include "shape/generators.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("s4d_session_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

SessionFile sample() {
  SessionFile s;
  SceneObject cloth;
  cloth.name = "cloth";
  cloth.shape = generate("cloth", {{"n", 4}, {"size", 1}});
  std::get<Surface<4>>(cloth.shape).vertices[5] = Vec4(0.1, -0.2, 0.3, 1.0 / 3);  // moved by the simulation
  cloth.mass = 0.002;
  s.scene.objects.push_back(cloth);
  SceneObject knot;
  knot.name = "sketch-1";
  Curve<3> k = std::get<Curve<3>>(generate("torus-knot", {{"n", 40}}));
  k.components.push_back(Polyline<3>{{Vec3(0, 0, 0), Vec3(1, 0.5, 0.25)}, false});
  knot.shape = k;
  s.scene.objects.push_back(knot);
  s.scene.physics.friction = 0;
  s.scene.view.opacity = 0.5;
  s.scene.frame.rotate(Plane{0, 3}, 0.4);
  s.opened = "scenes/cloth.json";
  s.simulation.dim = 4;
  for (int i = 0; i < 16 * 4; ++i) {
    s.simulation.positions.push_back(0.1 * i + 1.0 / 7);
    s.simulation.velocities.push_back(-0.01 * i);
  }
  s.simulation.pinned = {0, 3};
  s.simulation.time = 2.5;
  s.simulation.playing = true;
  s.view.angles = {0, 0, 30, 0, 15.5f, 0};
  s.view.trackball = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  s.view.zoom = 1.7;
  s.tool = "Touch";
  s.history = {"drag vertex 5", "pin vertex 0", "pin vertex 3"};
  s.history_head = 2;
  for (int i = 0; i < 3; ++i) {  // version 3: the states undo and redo restore
    auto d = std::make_shared<DocumentState>();
    d->scene.objects.push_back(knot);
    std::get<Curve<3>>(d->scene.objects[0].shape).components[0].points[0].x() = i;
    d->pinned = {i};
    d->angles[2] = 10.0f * i;
    d->zoom = 1 + i;
    d->settings["ribbon.width"] = 0.1 * (i + 1);
    s.history_states.push_back(std::move(d));
  }
  s.clean_exit = false;
  s.closed_by = "SIGHUP";
  return s;
}

TEST(SessionFile, EveryPartRoundTripsExactly) {
  const SessionFile a = sample();
  const SessionFile b = parse_session(session_text(a), "t.s4d");
  ASSERT_EQ(b.scene.objects.size(), 2u);
  const auto& sa = std::get<Surface<4>>(a.scene.objects[0].shape);
  const auto& sb = std::get<Surface<4>>(b.scene.objects[0].shape);
  EXPECT_EQ(sb.vertices, sa.vertices) << "shapes are inline, bit for bit";
  EXPECT_EQ(sb.triangles, sa.triangles);
  EXPECT_EQ(sb.grid, sa.grid);
  EXPECT_EQ(b.scene.objects[0].mass, 0.002);
  const auto& ka = std::get<Curve<3>>(a.scene.objects[1].shape);
  const auto& kb = std::get<Curve<3>>(b.scene.objects[1].shape);
  ASSERT_EQ(kb.components.size(), 2u);
  EXPECT_EQ(kb.components[0].points, ka.components[0].points);
  EXPECT_FALSE(kb.components[1].closed);
  EXPECT_EQ(b.scene.physics.friction, 0);
  EXPECT_EQ(b.scene.view.opacity, 0.5);
  EXPECT_LT((b.scene.frame.matrix() - a.scene.frame.matrix()).norm(), 1e-15);
  EXPECT_EQ(b.opened, a.opened);
  EXPECT_EQ(b.simulation.positions, a.simulation.positions);
  EXPECT_EQ(b.simulation.velocities, a.simulation.velocities);
  EXPECT_EQ(b.simulation.pinned, a.simulation.pinned);
  EXPECT_EQ(b.simulation.time, 2.5);
  EXPECT_TRUE(b.simulation.playing);
  EXPECT_EQ(b.view.angles, a.view.angles);
  EXPECT_LT((b.view.trackball.coeffs() - a.view.trackball.coeffs()).norm(), 1e-15);
  EXPECT_EQ(b.view.zoom, 1.7);
  EXPECT_EQ(b.tool, "Touch");
  EXPECT_EQ(b.history, a.history);
  EXPECT_EQ(b.history_head, 2);
  ASSERT_EQ(b.history_states.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const DocumentState& d = *b.history_states[i];
    ASSERT_EQ(d.scene.objects.size(), 1u);
    EXPECT_EQ(std::get<Curve<3>>(d.scene.objects[0].shape).components[0].points[0].x(), i);
    EXPECT_EQ(d.pinned, std::vector<int>{i});
    EXPECT_EQ(d.angles[2], 10.0f * i);
    EXPECT_EQ(d.zoom, 1 + i);
    EXPECT_EQ(d.settings.at("ribbon.width"), 0.1 * (i + 1));
  }
  EXPECT_FALSE(b.clean_exit);
  EXPECT_EQ(b.closed_by, "SIGHUP");
}

// One file per format version is kept: version 1's must always open.
TEST(SessionFile, AVersionOneFileOpens) {
  const SessionFile s = read_session(fs::path(S4D_TEST_DATA) / "io" / "sessions" / "v1.s4d");
  ASSERT_EQ(s.scene.objects.size(), 1u);
  EXPECT_EQ(s.scene.objects[0].name, "square");
  EXPECT_EQ(s.simulation.dim, 4);
  EXPECT_EQ(s.simulation.pinned, std::vector<int>{2});
  EXPECT_EQ(s.history.size(), 1u);
}

std::string error_of(const std::string& text) {
  try {
    parse_session(text, "bad.s4d");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

// Version 2 adds the tool settings and the vertices the hand held.
TEST(SessionFile, AVersionTwoFileOpensWithItsToolSettingsAndHeldVertices) {
  const SessionFile s = read_session(fs::path(S4D_TEST_DATA) / "io" / "sessions" / "v2.s4d");
  EXPECT_EQ(s.simulation.pinned, std::vector<int>{2});
  EXPECT_EQ(s.simulation.held, std::vector<int>{1});
  EXPECT_EQ(s.tool, "Sketch a ribbon");
  EXPECT_EQ(s.tool_settings.at("ribbon.width"), 0.125);
  EXPECT_EQ(s.tool_settings.at("hand.K"), 250);
  EXPECT_TRUE(read_session(fs::path(S4D_TEST_DATA) / "io" / "sessions" / "v1.s4d").tool_settings.empty());
  EXPECT_TRUE(s.history_states.empty()) << "before version 3 the history is labels only";
  // Written and read back unchanged.
  const SessionFile back = parse_session(session_text(s), "back.s4d");
  EXPECT_EQ(back.tool_settings, s.tool_settings);
  EXPECT_EQ(back.simulation.held, s.simulation.held);
  EXPECT_NE(error_of(R"({"shadow4d_session": 2, "scene": {"version": 1}, "tool_settings": {"hand.K": "x"}})")
                .find("tool_settings.hand.K: must be a number"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"shadow4d_session": 2, "scene": {"version": 1}, "simulation": {"dim": 3, "positions": [1, 2, 3], "held": [4]}})")
                .find("simulation.held: vertex 4 is not one of the 1"),
            std::string::npos);
}

TEST(SessionFile, NewerAndDamagedOnesAreRefusedSayingWhy) {
  std::string good = session_text(sample());
  std::string newer = good;
  newer.replace(newer.find("\"shadow4d_session\": 3"), 21, "\"shadow4d_session\": 7");
  EXPECT_NE(error_of(newer).find("written by a newer shadow4d (version 7); this one reads 3"), std::string::npos)
      << error_of(newer);
  EXPECT_NE(error_of(good.substr(0, good.size() / 2)).find("damaged or not JSON"), std::string::npos);
  EXPECT_NE(error_of(R"({"version": 1})").find("this is no session file"), std::string::npos);
  EXPECT_NE(error_of(R"({"shadow4d_session": 1, "scene": {"version": 1}, "simulation": {"dim": 4, "positions": [1, 2, 3]}})")
                .find("not a whole number of points of R^4"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"shadow4d_session": 1, "scene": {"version": 1}, "simulation": {"dim": 3, "positions": [1, 2, 3], "pinned": [1]}})")
                .find("vertex 1 is not one of the 1"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"shadow4d_session": 1, "scene": {"version": 1, "objects": [{"geometry": {"dim": 4, "vertices": [[0,0,0,0]], "triangles": [[0, 0, 9]]}}]}})")
                .find("vertex index 9 is not one of the 1 vertices"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"shadow4d_session": 1, "scene": {"version": 1}, "history": ["a"], "history_head": 2})")
                .find("history_head: is outside the history"),
            std::string::npos);
  // Beyond an int, or between two steps: refused before any conversion (UBSan found the first).
  for (const char* head : {"1e300", "-1e300", "0.5"})
    EXPECT_NE(error_of(std::string(R"({"shadow4d_session": 1, "scene": {"version": 1}, "history": ["a"], "history_head": )") +
                       head + "}")
                  .find("history_head: is outside the history"),
              std::string::npos)
        << head;
  EXPECT_NE(error_of(R"({"shadow4d_session": 1, "scene": {"version": 1}, "simulation": {"dim": 1e300}})")
                .find("simulation.dim: must be 0, 3 or 4"),
            std::string::npos);
}

// Issue 37: the view's 4D perspective is kept (written only when on: orthographic files are as
// they were), and a bad distance is refused saying why.
TEST(SessionFile, ThePerspectiveIsKeptAndABadOneRefused) {
  SessionFile a = sample();
  EXPECT_EQ(session_text(a).find("perspective"), std::string::npos) << "orthographic: not written";
  EXPECT_EQ(parse_session(session_text(a), "t.s4d").view.perspective, 0);
  a.view.perspective = 2.75;
  EXPECT_EQ(parse_session(session_text(a), "t.s4d").view.perspective, 2.75);
  std::string text = session_text(a);
  for (const char* bad : {"-1", "1e9"}) {
    std::string t = text;
    t.replace(t.find("2.75"), 4, bad);
    EXPECT_NE(error_of(t).find("view.perspective: the perspective distance must be"), std::string::npos) << error_of(t);
  }
}

// A writer killed between creating its temporary and the rename leaves FILE.tmp-PID: the next
// start removes those of processes that are gone, and never one a running writer may still own.
// The autosave's cache of states' text writes what the plain writer writes, and forgets the
// states the history no longer has.
TEST(SessionFile, CachedStateTextsWriteTheSameFile) {
  SessionFile a = sample();
  StateTextCache cache;
  EXPECT_EQ(session_text(a, &cache), session_text(a));
  EXPECT_EQ(cache.size(), 3u);
  EXPECT_EQ(session_text(a, &cache), session_text(a)) << "from the cache";
  auto changed = std::make_shared<DocumentState>(*a.history_states[1]);
  changed->zoom = 9;
  a.history_states[1] = changed;  // another state, maybe at a reused address: its own text
  a.history_states.pop_back();
  a.history.pop_back();
  EXPECT_EQ(session_text(a, &cache), session_text(a));
  EXPECT_EQ(cache.size(), 2u);
}

TEST(AtomicFile, StaleTemporariesOfDeadWritersAreRemoved) {
  const fs::path d = temp_dir("stale");
  const fs::path f = d / "auto.s4d";
  write_file_atomically(f, "whole");
  const pid_t gone = fork();
  ASSERT_GE(gone, 0);
  if (gone == 0) _exit(0);
  int status = 0;
  waitpid(gone, &status, 0);  // reaped: its pid names no process now
  for (const std::string& name : {"auto.s4d.tmp-" + std::to_string(gone), "auto.s4d.tmp-" + std::to_string(getpid()),
                                  std::string("auto.s4d.tmp-x1"), std::string("other.s4d.tmp-") + std::to_string(gone)})
    std::ofstream(d / name) << "half";
  EXPECT_EQ(remove_stale_temporaries(f), 1);
  EXPECT_FALSE(fs::exists(d / ("auto.s4d.tmp-" + std::to_string(gone))));
  EXPECT_TRUE(fs::exists(d / ("auto.s4d.tmp-" + std::to_string(getpid())))) << "a live writer's";
  EXPECT_TRUE(fs::exists(d / "auto.s4d.tmp-x1")) << "not a temporary of ours";
  EXPECT_TRUE(fs::exists(d / ("other.s4d.tmp-" + std::to_string(gone)))) << "another file's";
  EXPECT_EQ(read_text_file(f), "whole");
}

TEST(AtomicFile, ReplacesWholeKeepsVersionsAndLeavesTheOldFileOnFailure) {
  const fs::path d = temp_dir("atomic");
  const fs::path f = d / "work.s4d";
  write_file_atomically(f, "one", 2);
  write_file_atomically(f, "two", 2);
  write_file_atomically(f, "three", 2);
  write_file_atomically(f, "four", 2);
  EXPECT_EQ(read_text_file(f), "four");
  EXPECT_EQ(read_text_file(d / "work.s4d.1"), "three");
  EXPECT_EQ(read_text_file(d / "work.s4d.2"), "two");
  EXPECT_FALSE(fs::exists(d / "work.s4d.3"));
  for (const auto& e : fs::directory_iterator(d))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << "no temporary file is left: " << e.path();
  // A folder that cannot be written: the error names the file, the old one stays whole.
  if (::geteuid() != 0) {  // root writes anyway
    ::chmod(d.c_str(), 0555);
    EXPECT_THROW(write_file_atomically(f, "five"), Error);
    ::chmod(d.c_str(), 0755);
    EXPECT_EQ(read_text_file(f), "four");
  }
  EXPECT_THROW(write_file_atomically(d / "no" / "such" / "folder.s4d", "x"), Error);
}

}  // namespace
}  // namespace s4d
