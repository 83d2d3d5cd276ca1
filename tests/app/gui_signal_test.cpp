// A logout, a task manager or Ctrl+C ends the window cleanly: SIGTERM, SIGINT and SIGHUP close a
// running window with exit code 0 within 3 s, leaving a whole autosave that is offered back at the
// next start. Runs the shadow4d binary (ctest passes it as S4D_BIN) on the test's display.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>
#include <vector>

#include "interact/session/autosave.hpp"
#include "io/session_file.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

TEST(GuiSignals, TermIntAndHupCloseTheWindowWithAnAutosaveThatIsOfferedBack) {
  const char* display = std::getenv("DISPLAY");
  const char* bin = std::getenv("S4D_BIN");
  if (!display || !*display || !bin || !*bin) GTEST_SKIP() << "needs a display and S4D_BIN; ctest runs it under xvfb-run";
  for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
    SCOPED_TRACE(strsignal(sig));
    const fs::path dir = fs::temp_directory_path() / ("s4d_gui_signal_" + std::to_string(sig));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path autosave = dir / "autosave.s4d";
    const std::string scene = std::string(S4D_SOURCE_DIR) + "/scenes/cloth.json";
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      execl(bin, bin, scene.c_str(), "--autosave", autosave.c_str(), "--autosave-seconds", "30",
            static_cast<char*>(nullptr));
      _exit(127);
    }
    std::this_thread::sleep_for(std::chrono::seconds(4));  // the window is up and simulating
    ASSERT_EQ(kill(pid, sig), 0);
    const auto sent = std::chrono::steady_clock::now();
    int status = 0;
    pid_t done = 0;
    while ((done = waitpid(pid, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() - sent < std::chrono::seconds(3))
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (done == 0) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      FAIL() << "the window did not close within 3 s of the signal";
    }
    ASSERT_TRUE(WIFEXITED(status)) << "ended by the signal itself, not cleanly (status " << status << ")";
    EXPECT_EQ(WEXITSTATUS(status), 0);
    ASSERT_TRUE(fs::exists(autosave)) << "no last autosave";
    const SessionFile f = read_session(autosave);  // whole: it parses
    EXPECT_FALSE(f.clean_exit) << "kept to be offered back";
    EXPECT_EQ(f.closed_by, sig == SIGTERM ? "SIGTERM" : sig == SIGINT ? "SIGINT" : "SIGHUP");
    EXPECT_EQ(f.scene.objects.size(), 1u);
    std::string why;
    EXPECT_TRUE(unfinished_autosave(autosave, &why).has_value()) << "the next start offers it: " << why;
  }
}

pid_t start_window(const char* bin, const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(bin)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(bin, argv.data());
    _exit(127);
  }
  return pid;
}

// Two windows write two autosaves; one killed outright (SIGKILL: no handler runs, no last save),
// a third window started while the other still runs offers exactly the killed one's work, and
// says which file it is.
TEST(GuiSignals, TwoWindowsTwoAutosavesAndOnlyTheKilledOnesWorkIsOffered) {
  const char* display = std::getenv("DISPLAY");
  const char* bin = std::getenv("S4D_BIN");
  if (!display || !*display || !bin || !*bin) GTEST_SKIP() << "needs a display and S4D_BIN; ctest runs it under xvfb-run";
  const fs::path dir = fs::temp_directory_path() / "s4d_gui_two_windows";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string autosave = (dir / "autosave.s4d").string();
  const std::string cloth = std::string(S4D_SOURCE_DIR) + "/scenes/cloth.json";
  const std::string knot = "torus-knot:p=2,q=3";
  // Autosaves every second, so that both have written before the kill.
  const pid_t first = start_window(bin, {cloth, "--autosave", autosave, "--autosave-seconds", "1"});
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // the first claims the first slot
  const pid_t second = start_window(bin, {knot, "--autosave", autosave, "--autosave-seconds", "1"});
  ASSERT_GT(first, 0);
  ASSERT_GT(second, 0);
  const fs::path second_file = dir / "autosave-2.s4d";
  const auto t0 = std::chrono::steady_clock::now();
  while (!(fs::exists(autosave) && fs::exists(second_file)) && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(20))
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_TRUE(fs::exists(autosave) && fs::exists(second_file)) << "two windows, two autosave files";
  EXPECT_NE(read_session(autosave).opened, read_session(second_file).opened) << "each wrote its own work";
  EXPECT_EQ(read_session(second_file).opened, knot);
  kill(second, SIGKILL);
  waitpid(second, nullptr, 0);

  const fs::path events = dir / "third.txt", dump = dir / "third.json";
  std::ofstream(events) << "20 dump " << dump.string() << "\n21 quit\n";
  const pid_t third = start_window(bin, {"--autosave", autosave, "--input", events.string()});
  int status = 0;
  waitpid(third, &status, 0);
  kill(first, SIGTERM);
  waitpid(first, nullptr, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  std::ifstream in(dump);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("autosave").get<std::string>(), second_file.string()) << "it took the killed window's slot";
  ASSERT_TRUE(j.at("restore_offered").get<bool>());
  EXPECT_EQ(j.at("restore_offer").at("opened").get<std::string>(), knot) << "exactly the killed one's work";
  EXPECT_EQ(j.at("restore_offer").at("closed_by").get<std::string>(), "") << "killed: no signal handler ran";
}

}  // namespace
}  // namespace s4d
