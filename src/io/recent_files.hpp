// The files a user opened or saved last (the start page lists them): a text file of paths, the
// newest first, kept beside the autosave. Unreadable lines and vanished files are dropped.
#pragma once
#include <filesystem>
#include <vector>

namespace s4d {

class RecentFiles {
 public:
  static constexpr std::size_t kMax = 8;
  explicit RecentFiles(std::filesystem::path list) : list_(std::move(list)) {}

  // The list's paths that still exist, newest first. Never throws.
  std::vector<std::filesystem::path> read() const;
  // Puts `file` first (absolute) and writes the list; returns false when it cannot be written
  // (the work is not affected: the list is a convenience).
  bool add(const std::filesystem::path& file) const;
  const std::filesystem::path& path() const { return list_; }

 private:
  std::filesystem::path list_;
};

}  // namespace s4d
