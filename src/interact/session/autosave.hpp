// Autosave: every `interval` seconds (and on quit, and when a signal ends the run) the session is
// written atomically beside the last few autosaves. Each running window (or headless session) has
// a file of its own, its slot — FILE, then FILE-2.s4d, FILE-3.s4d ... for windows open at once —
// locked while it runs (FILE.lock, an flock the kernel drops when the process dies, SIGKILL
// included), so no window rotates another's autosaves. A run that did not quit normally (a crash,
// a kill, a signal) leaves its autosave marked unfinished; a start takes the slot of the newest
// such autosave that no running process holds and offers it (`--restore` takes it without asking).
#pragma once
#include <chrono>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "io/file_lock.hpp"
#include "io/session_file.hpp"

namespace s4d {

class Session;

struct AutosaveOptions {
  std::filesystem::path path;  // the first slot; empty: default_autosave_path()
  double interval = 30;        // s between autosaves; 0 turns them off
  int keep = 3;                // older autosaves kept beside it (FILE.1 ...)
};

// $XDG_STATE_HOME/shadow4d/autosave.s4d, or ~/.local/state/shadow4d/autosave.s4d, or a file in
// the temporary folder when neither can be found.
std::filesystem::path default_autosave_path();
// Slot k of `first` (k >= 1): `first` itself, then STEM-k.EXT beside it.
std::filesystem::path autosave_slot(const std::filesystem::path& first, int k);
// The lock file of an autosave: FILE.lock.
std::filesystem::path autosave_lock(const std::filesystem::path& autosave);

// The autosave a run left when it did not quit normally; nothing when there is none, it was left
// by a clean quit, or it cannot be read (`why` says so then). Whether its run still goes on is
// the slot's lock's business (Autosaver).
std::optional<SessionFile> unfinished_autosave(const std::filesystem::path& path, std::string* why = nullptr);
// One sentence for the offer: which file, when it was saved (local time, and how long ago), what it
// began from, and how its run ended.
std::string describe_unfinished(const std::filesystem::path& path, const SessionFile& saved);

class Autosaver {
 public:
  // Claims a slot of options.path's (see above) and holds its lock while it lives. A slot no
  // running process holds whose autosave is unfinished is preferred (the newest of them): its
  // work is then offered by unfinished(). When no lock can be made (a read-only folder) the first
  // slot is used unlocked, and note() says so.
  explicit Autosaver(AutosaveOptions options);
  ~Autosaver();  // waits for a write under way
  Autosaver(const Autosaver&) = delete;
  Autosaver& operator=(const Autosaver&) = delete;

  // UI thread, each frame: when the interval has passed, takes the session's state and writes it
  // on a worker thread (the UI never waits on the disk). True when a save was started.
  bool tick(const Session& session, std::chrono::steady_clock::time_point now);
  // Writes now on this thread: quitting (clean_exit = true), or ended by a signal (clean_exit =
  // false, closed_by its name, so that the next start offers the work). Never throws; false on failure.
  bool save_now(const Session& session, bool clean_exit, const std::string& closed_by = {});
  // This run's own autosave file (its slot).
  const std::filesystem::path& path() const { return path_; }
  // Called after each successful write, on the writing thread (set before the first tick): the
  // web page copies its autosave folder to the browser's storage there (IndexedDB).
  void set_written(std::function<void()> written) { written_ = std::move(written); }
  double interval() const { return options_.interval; }
  std::string last_error() const;
  int saves() const;

  // The unfinished work the slot held when it was claimed (left by a run no longer running).
  const std::optional<SessionFile>& unfinished() const { return unfinished_; }
  // How many other slots hold unfinished work no running process owns (offered by later starts).
  int others_unfinished() const { return others_unfinished_; }
  // Why the slot's old autosave could not be read, or why it is not locked; empty when all is well.
  const std::string& note() const { return note_; }

 private:
  void claim();
  void write(SessionFile f);

  AutosaveOptions options_;
  std::filesystem::path path_;
  std::optional<FileLock> lock_;
  std::optional<SessionFile> unfinished_;
  int others_unfinished_ = 0;
  std::string note_;
  std::chrono::steady_clock::time_point last_{};
  mutable std::mutex mutex_;  // one write at a time; guards error_, saves_ and texts_
  StateTextCache texts_;      // the history's states as written last time
  std::string error_;
  int saves_ = 0;
  std::thread worker_;
  std::function<void()> written_;
};

}  // namespace s4d
