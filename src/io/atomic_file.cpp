// POSIX open/write/fsync/rename: the order that makes the replacement atomic and durable.
#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace s4d {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw Error("cannot write " + path.string() + ": " + what + " (" + std::strerror(errno) + ")");
}

void sync_folder(const std::filesystem::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;  // some file systems refuse: the rename is still atomic
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view text, int keep) {
  const std::filesystem::path dir = path.parent_path();
  const std::filesystem::path tmp = path.string() + ".tmp-" + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(tmp, "cannot create the temporary file");
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(fd);
      ::unlink(tmp.c_str());
      fail(tmp, "writing failed");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    ::close(fd);
    ::unlink(tmp.c_str());
    fail(tmp, "fsync failed");
  }
  ::close(fd);
  std::error_code ec;
  if (keep > 0 && std::filesystem::exists(path, ec)) {
    for (int k = keep; k >= 1; --k) {
      const std::filesystem::path from = k == 1 ? path : std::filesystem::path(path.string() + "." + std::to_string(k - 1));
      const std::filesystem::path to = path.string() + "." + std::to_string(k);
      if (!std::filesystem::exists(from, ec)) continue;
      if (k == 1) {  // a second name for the current file, made whole at once (no copying)
        const std::filesystem::path link = to.string() + ".tmp";
        ::unlink(link.c_str());
        if (::link(from.c_str(), link.c_str()) == 0) std::filesystem::rename(link, to, ec);
      } else {
        std::filesystem::rename(from, to, ec);
      }
    }
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    ::unlink(tmp.c_str());
    fail(path, "renaming the temporary file over it failed");
  }
  sync_folder(dir);
}

int remove_stale_temporaries(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const std::string prefix = path.filename().string() + ".tmp-";
  std::error_code ec;
  fs::directory_iterator it(path.parent_path().empty() ? fs::path(".") : path.parent_path(), ec);
  if (ec) return 0;
  int removed = 0;
  for (const fs::directory_entry& e : it) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const char* digits = name.c_str() + prefix.size();
    const char* end = name.c_str() + name.size();
    long pid = 0;
    const auto [rest, err] = std::from_chars(digits, end, pid);
    if (err != std::errc() || rest != end || pid <= 0) continue;
    // Still running (or not ours to ask about): it may be writing now.
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    if (fs::remove(e.path(), ec)) ++removed;
  }
  return removed;
}

}  // namespace s4d
