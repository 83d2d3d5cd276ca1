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
    EXPECT_EQ(f.scene.objects.size(), 1u);
    std::string why;
    EXPECT_TRUE(unfinished_autosave(autosave, &why).has_value()) << "the next start offers it: " << why;
  }
}

}  // namespace
}  // namespace s4d
