// Autosave: every `interval` seconds (and on quit) the session is written atomically beside the
// last few autosaves; a run that did not quit normally (a crash, a kill) leaves one marked
// unclean, which the next start offers to restore (`--restore` takes it without asking).
#pragma once
#include <chrono>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "io/session_file.hpp"

namespace s4d {

class Session;

struct AutosaveOptions {
  std::filesystem::path path;  // empty: default_autosave_path()
  double interval = 30;        // s between autosaves; 0 turns them off
  int keep = 3;                // older autosaves kept beside it (FILE.1 ...)
};

// $XDG_STATE_HOME/shadow4d/autosave.s4d, or ~/.local/state/shadow4d/autosave.s4d, or a file in
// the temporary folder when neither can be found.
std::filesystem::path default_autosave_path();

// The autosave a run left when it did not quit normally; nothing when there is none, it was left
// by a clean quit, or it cannot be read (`why` says so then).
std::optional<SessionFile> unfinished_autosave(const std::filesystem::path& path, std::string* why = nullptr);

class Autosaver {
 public:
  explicit Autosaver(AutosaveOptions options);
  ~Autosaver();  // waits for a write under way
  Autosaver(const Autosaver&) = delete;
  Autosaver& operator=(const Autosaver&) = delete;

  // UI thread, each frame: when the interval has passed, takes the session's state and writes it
  // on a worker thread (the UI never waits on the disk). True when a save was started.
  bool tick(const Session& session, std::chrono::steady_clock::time_point now);
  // Writes now on this thread (quitting: clean_exit = true). Never throws; false on failure.
  bool save_now(const Session& session, bool clean_exit);
  const std::filesystem::path& path() const { return options_.path; }
  double interval() const { return options_.interval; }
  std::string last_error() const;
  int saves() const;

 private:
  void write(SessionFile f);

  AutosaveOptions options_;
  std::chrono::steady_clock::time_point last_{};
  mutable std::mutex mutex_;  // one write at a time; guards error_ and saves_
  std::string error_;
  int saves_ = 0;
  std::thread worker_;
};

}  // namespace s4d
