// SIGINT, SIGTERM and SIGHUP as a request to stop: a logout, a task manager or Ctrl+C in the
// terminal ends a long-running loop cleanly (the window writes its last autosave) instead of being
// ignored or killing it mid-write. The handler only sets a flag the loop polls.
#pragma once
#include <string>

namespace s4d {

// Installs the handlers (once; later calls do nothing). Libraries that install their own (SDL)
// must be told not to (SDL_HINT_NO_SIGNAL_HANDLERS).
void install_stop_signals();
// Whether one of the signals arrived; which one (0: none).
bool stop_requested();
int stop_signal();
// "SIGINT", "SIGTERM", "SIGHUP", or "signal N": for messages and the autosave's closed_by.
std::string signal_name(int signal);

}  // namespace s4d
