// flock(2) on a descriptor opened close-on-exec: a child the process starts does not inherit it.
#include "io/file_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <utility>

namespace s4d {

std::optional<FileLock> FileLock::try_lock(const std::filesystem::path& path, std::string* why) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    if (why) *why = "cannot open the lock file " + path.string() + " (" + std::strerror(errno) + ")";
    return std::nullopt;
  }
  int r = 0;
  while ((r = ::flock(fd, LOCK_EX | LOCK_NB)) != 0 && errno == EINTR) {
  }
  if (r != 0) {
    const int err = errno;
    ::close(fd);
    if (why) {
      if (err == EWOULDBLOCK) {
        const long pid = holder(path);
        *why = pid > 0 ? "held by process " + std::to_string(pid) : std::string("held by another process");
      } else {
        *why = "cannot lock " + path.string() + " (" + std::strerror(err) + ")";
      }
    }
    return std::nullopt;
  }
  // Our process id, for the messages of those who find it held (best effort: the lock is what counts).
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd, 0) == 0) {
    [[maybe_unused]] const ssize_t n = ::pwrite(fd, pid.data(), pid.size(), 0);
  }
  return FileLock(fd, path);
}

long FileLock::holder(const std::filesystem::path& path) {
  std::ifstream in(path);
  long pid = 0;
  if (!(in >> pid) || pid <= 0) return 0;
  return pid;
}

FileLock::FileLock(FileLock&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), path_(std::move(other.path_)) {}

FileLock& FileLock::operator=(FileLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
    path_ = std::move(other.path_);
  }
  return *this;
}

FileLock::~FileLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

}  // namespace s4d
