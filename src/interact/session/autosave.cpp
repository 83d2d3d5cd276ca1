// Autosaves: a slot claimed under its lock, the state taken on the UI thread, serialised and
// written atomically on a worker.
#include "interact/session/autosave.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "core/threads.hpp"
#include "interact/session/session.hpp"
#include "io/atomic_file.hpp"

namespace s4d {

namespace fs = std::filesystem;

fs::path default_autosave_path() {
  if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x) return fs::path(x) / "shadow4d" / "autosave.s4d";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".local" / "state" / "shadow4d" / "autosave.s4d";
  return fs::temp_directory_path() / "shadow4d-autosave.s4d";
}

fs::path autosave_slot(const fs::path& first, int k) {
  if (k <= 1) return first;
  return first.parent_path() / (first.stem().string() + "-" + std::to_string(k) + first.extension().string());
}

fs::path autosave_lock(const fs::path& autosave) { return autosave.string() + ".lock"; }

std::optional<SessionFile> unfinished_autosave(const fs::path& path, std::string* why) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::nullopt;
  try {
    SessionFile f = read_session(path);
    if (f.clean_exit) return std::nullopt;
    return f;
  } catch (const std::exception& e) {
    if (why) *why = std::string("the autosave cannot be read: ") + e.what();
    return std::nullopt;
  }
}

std::string describe_unfinished(const fs::path& path, const SessionFile& saved) {
  const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  const double ago = std::max(0.0, now - saved.saved_at);
  char when[64] = "an unknown time";
  const std::time_t t = static_cast<std::time_t>(saved.saved_at);
  std::tm local{};
  if (std::isfinite(saved.saved_at) && saved.saved_at > 0 && localtime_r(&t, &local))
    std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", &local);
  char since[48];
  if (ago < 120) std::snprintf(since, sizeof since, "%.0f s ago", ago);
  else if (ago < 7200) std::snprintf(since, sizeof since, "%.0f min ago", ago / 60);
  else if (ago < 172800) std::snprintf(since, sizeof since, "%.1f h ago", ago / 3600);
  else std::snprintf(since, sizeof since, "%.0f days ago", ago / 86400);
  std::string s = path.string() + ", saved " + when + " (" + since + ")";
  if (!saved.opened.empty()) s += " from '" + saved.opened + "'";
  s += saved.closed_by.empty() ? ": its window did not quit (it was killed or crashed)"
                               : ": its window was closed by " + saved.closed_by;
  return s;
}

namespace {

// The slot numbers in use beside `first`: 1, and k for every STEM-k.EXT (or its lock) there.
int highest_slot(const fs::path& first) {
  int highest = 1;
  const std::string prefix = first.stem().string() + "-", ext = first.extension().string();
  std::error_code ec;
  fs::directory_iterator it(first.parent_path().empty() ? fs::path(".") : first.parent_path(), ec);
  if (ec) return highest;
  for (const fs::directory_entry& e : it) {
    std::string name = e.path().filename().string();
    if (name.ends_with(".lock")) name.erase(name.size() - 5);
    if (!name.starts_with(prefix) || !name.ends_with(ext) || name.size() <= prefix.size() + ext.size()) continue;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - ext.size());
    if (digits.size() > 6 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      continue;
    highest = std::max(highest, std::atoi(digits.c_str()));
  }
  return highest;
}

}  // namespace

Autosaver::Autosaver(AutosaveOptions options) : options_(std::move(options)) {
  if (options_.path.empty()) options_.path = default_autosave_path();
  claim();
  remove_stale_temporaries(path_);  // what a killed run was writing (its whole file is kept)
  last_ = std::chrono::steady_clock::now();
}

// Every slot is tried under its lock: held ones belong to running windows; of the others, the
// newest unfinished autosave is taken (its work offered), else the first free slot.
void Autosaver::claim() {
  std::error_code ec;
  fs::create_directories(options_.path.parent_path(), ec);
  struct Candidate {
    int slot = 0;
    FileLock lock;
    double saved_at = 0;
  };
  std::vector<Candidate> free, left;
  std::string lock_problem, read_problem;
  const auto unreadable = [&](const fs::path& p, const std::string& what) {
    if (read_problem.empty()) read_problem = p.string() + ": the autosave cannot be read: " + what;
  };
  const int highest = highest_slot(options_.path);
  for (int k = 1; k <= highest + 1; ++k) {
    if (k == highest + 1 && (!free.empty() || !left.empty())) break;  // no new slot needed
    const fs::path p = autosave_slot(options_.path, k);
    std::string why;
    std::optional<FileLock> lock = FileLock::try_lock(autosave_lock(p), &why);
    if (!lock) {
      if (why.rfind("held", 0) != 0 && lock_problem.empty()) lock_problem = why;
      continue;
    }
    // Only the summary: a slot's whole document (its history may be megabytes) is read once it
    // is chosen, not for every slot at every start.
    std::optional<SessionSummary> summary;
    if (fs::exists(p, ec)) {
      try {
        summary = read_session_summary(p);
      } catch (const std::exception& e) {
        unreadable(p, e.what());
      }
    }
    const bool unfinished = summary && !summary->clean_exit;
    (unfinished ? left : free).push_back({k, std::move(*lock), summary ? summary->saved_at : 0.0});
  }
  // The newest unfinished slot whose document reads; one that does not is free to overwrite.
  std::stable_sort(left.begin(), left.end(), [](const Candidate& a, const Candidate& b) { return a.saved_at > b.saved_at; });
  Candidate* chosen = nullptr;
  int others = 0;
  for (Candidate& c : left) {
    const fs::path p = autosave_slot(options_.path, c.slot);
    if (chosen) {
      ++others;
      continue;
    }
    try {
      unfinished_ = read_session(p);
      chosen = &c;
    } catch (const std::exception& e) {
      unreadable(p, e.what());
      free.push_back(std::move(c));
    }
  }
  if (!chosen && !free.empty()) chosen = &free.front();
  if (!chosen) {  // no lock could be made: the first slot, unguarded, as before slots existed
    path_ = options_.path;
    std::string why;
    unfinished_ = unfinished_autosave(path_, &why);
    note_ = "the autosave is not locked (" + (lock_problem.empty() ? std::string("no slot free") : lock_problem) +
            "): another window may write the same file";
    if (!why.empty()) note_ += "; " + why;
    return;
  }
  path_ = autosave_slot(options_.path, chosen->slot);
  lock_ = std::move(chosen->lock);
  others_unfinished_ = others;
  note_ = read_problem;
  // The other slots' locks are dropped here, as `free` and `left` go.
}

Autosaver::~Autosaver() {
  if (worker_.joinable()) worker_.join();
}

void Autosaver::write(SessionFile f) {
  std::lock_guard lock(mutex_);
  try {
    fs::create_directories(path_.parent_path());
    write_session(f, path_, options_.keep, &texts_);
    error_.clear();
    ++saves_;
    if (written_) written_();
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

bool Autosaver::tick(const Session& session, std::chrono::steady_clock::time_point now) {
  if (!(options_.interval > 0) || std::chrono::duration<double>(now - last_).count() < options_.interval) return false;
  last_ = now;
  SessionFile f = session.save_state();
  f.clean_exit = false;
  if (worker_.joinable()) worker_.join();  // the last one is long done after an interval
  if constexpr (kHaveThreads) worker_ = std::thread([this, f = std::move(f)]() mutable { write(std::move(f)); });
  else write(std::move(f));  // no threads (the web page): a page's session is small, and one write is quick
  return true;
}

bool Autosaver::save_now(const Session& session, bool clean_exit, const std::string& closed_by) {
  if (worker_.joinable()) worker_.join();
  SessionFile f = session.save_state();
  f.clean_exit = clean_exit;
  f.closed_by = closed_by;
  write(std::move(f));
  return last_error().empty();
}

std::string Autosaver::last_error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

int Autosaver::saves() const {
  std::lock_guard lock(mutex_);
  return saves_;
}

}  // namespace s4d
