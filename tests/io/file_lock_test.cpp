// FileLock: one holder at a time, the holder's process id kept in the file, and the lock gone
// when its holder is (a process's death included: the kernel drops an flock, SIGKILL or not).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>

#include "io/file_lock.hpp"

namespace s4d {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(FileLock, OneHolderAtATimeAndFreeWhenItGoes) {
  const fs::path path = fresh_dir("s4d_file_lock") / "a.lock";
  std::string why;
  auto first = FileLock::try_lock(path, &why);
  ASSERT_TRUE(first.has_value()) << why;
  EXPECT_EQ(FileLock::holder(path), static_cast<long>(getpid()));
  EXPECT_FALSE(FileLock::try_lock(path, &why).has_value()) << "held by this very object";
  EXPECT_NE(why.find(std::to_string(getpid())), std::string::npos) << why;
  FileLock moved = std::move(*first);  // moving keeps it held
  EXPECT_FALSE(FileLock::try_lock(path).has_value());
  first.reset();
  EXPECT_FALSE(FileLock::try_lock(path).has_value()) << "a moved-from lock releases nothing";
  { FileLock gone = std::move(moved); }
  EXPECT_TRUE(FileLock::try_lock(path).has_value()) << "free once its holder is destroyed";
}

TEST(FileLock, AKilledHoldersLockIsFree) {
  const fs::path path = fresh_dir("s4d_file_lock_kill") / "b.lock";
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    auto lock = FileLock::try_lock(path);
    char c = lock ? 'y' : 'n';
    if (write(ready[1], &c, 1) != 1) _exit(2);
    pause();
    _exit(0);
  }
  char c = 0;
  ASSERT_EQ(read(ready[0], &c, 1), 1);
  ASSERT_EQ(c, 'y');
  EXPECT_FALSE(FileLock::try_lock(path).has_value()) << "the child holds it";
  EXPECT_EQ(FileLock::holder(path), static_cast<long>(pid));
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  EXPECT_TRUE(FileLock::try_lock(path).has_value()) << "SIGKILL freed it";
  close(ready[0]);
  close(ready[1]);
}

TEST(FileLock, AFolderThatCannotBeMadeSaysWhy) {
  std::string why;
  EXPECT_FALSE(FileLock::try_lock("/proc/no_such_dir/x.lock", &why).has_value());
  EXPECT_FALSE(why.empty());
}

}  // namespace
}  // namespace s4d
