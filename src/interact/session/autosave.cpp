// Autosaves: the state taken on the UI thread, serialised and written atomically on a worker.
#include "interact/session/autosave.hpp"

#include <cstdlib>

#include "interact/session/session.hpp"
#include "io/atomic_file.hpp"

namespace s4d {

std::filesystem::path default_autosave_path() {
  namespace fs = std::filesystem;
  if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x) return fs::path(x) / "shadow4d" / "autosave.s4d";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".local" / "state" / "shadow4d" / "autosave.s4d";
  return fs::temp_directory_path() / "shadow4d-autosave.s4d";
}

std::optional<SessionFile> unfinished_autosave(const std::filesystem::path& path, std::string* why) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  try {
    SessionFile f = read_session(path);
    if (f.clean_exit) return std::nullopt;
    return f;
  } catch (const std::exception& e) {
    if (why) *why = std::string("the autosave cannot be read: ") + e.what();
    return std::nullopt;
  }
}

Autosaver::Autosaver(AutosaveOptions options) : options_(std::move(options)) {
  if (options_.path.empty()) options_.path = default_autosave_path();
  remove_stale_temporaries(options_.path);  // what a killed run was writing (its whole file is kept)
  last_ = std::chrono::steady_clock::now();
}

Autosaver::~Autosaver() {
  if (worker_.joinable()) worker_.join();
}

void Autosaver::write(SessionFile f) {
  std::lock_guard lock(mutex_);
  try {
    std::filesystem::create_directories(options_.path.parent_path());
    write_session(f, options_.path, options_.keep);
    error_.clear();
    ++saves_;
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
  worker_ = std::thread([this, f = std::move(f)]() mutable { write(std::move(f)); });
  return true;
}

bool Autosaver::save_now(const Session& session, bool clean_exit) {
  if (worker_.joinable()) worker_.join();
  SessionFile f = session.save_state();
  f.clean_exit = clean_exit;
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
