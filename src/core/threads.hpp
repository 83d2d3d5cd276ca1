// Whether this build can start threads, and background work that runs in place when it cannot.
// The web page served without cross-origin isolation has no shared memory, hence no threads: its
// live simulation, checks, autosave and naming are stepped by their owner (the frame loop) instead.
#pragma once
#include <future>
#include <type_traits>
#include <utility>

namespace s4d {

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool kHaveThreads = false;
#else
inline constexpr bool kHaveThreads = true;
#endif

// std::async(std::launch::async, f); without threads, f runs now and the future is ready at once
// (its exception, if any, is in the future as with std::async).
template <class F>
std::future<std::invoke_result_t<std::decay_t<F>>> run_in_background(F&& f) {
  if constexpr (kHaveThreads) {
    return std::async(std::launch::async, std::forward<F>(f));
  } else {
    std::packaged_task<std::invoke_result_t<std::decay_t<F>>()> task(std::forward<F>(f));
    auto result = task.get_future();
    task();
    return result;
  }
}

}  // namespace s4d
