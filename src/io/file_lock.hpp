// FileLock: an advisory lock (flock) on a small file, held while the object lives. The kernel
// releases it when the process ends, however it ends (a SIGKILL, a crash), so a lock that can be
// taken belongs to no running process: what the autosave slots use to tell a running window's
// work from a dead one's. The file keeps the holder's process id, for messages.
#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace s4d {

class FileLock {
 public:
  // Creates `path` when missing and takes its lock without waiting. Nothing when another process
  // (or another FileLock of this one) holds it, or when the file cannot be made (`why` says
  // which: "held by process 1234" or the system's reason).
  static std::optional<FileLock> try_lock(const std::filesystem::path& path, std::string* why = nullptr);
  // The process id the holder of `path`'s lock wrote into it; 0 when unknown.
  static long holder(const std::filesystem::path& path);

  FileLock(FileLock&& other) noexcept;
  FileLock& operator=(FileLock&& other) noexcept;
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  ~FileLock();

  const std::filesystem::path& path() const { return path_; }

 private:
  FileLock(int fd, std::filesystem::path path) : fd_(fd), path_(std::move(path)) {}
  int fd_ = -1;
  std::filesystem::path path_;
};

}  // namespace s4d
