#include "app/browser.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#endif

#include <memory>
#include <utility>

namespace s4d {

#ifdef __EMSCRIPTEN__

namespace {

struct Frames {
  std::function<bool()> frame;
  std::function<void()> finish;
};

void one_frame(void* arg) {
  auto* f = static_cast<Frames*>(arg);
  if (f->frame()) return;
  emscripten_cancel_main_loop();
  f->finish();
}

}  // namespace

void run_frames(std::function<bool()> frame, std::function<void()> finish) {
  auto* f = new Frames{std::move(frame), std::move(finish)};  // lives as long as the page
  // fps 0: the browser's animation frames; false: return now (the caller's stack unwinds normally).
  emscripten_set_main_loop_arg(one_frame, f, 0, false);
}

void persist_browser_files() {
  // clang-format off
  EM_ASM({
    FS.syncfs(false, function(err) { if (err) console.error('shadow4d: the autosave did not reach IndexedDB: ' + err); });
  });
  // clang-format on
}

bool offer_download(const std::string& path) {
  // clang-format off
  return EM_ASM_INT({
    try {
      const path = UTF8ToString($0);
      const data = FS.readFile(path);
      const a = document.createElement('a');
      a.href = URL.createObjectURL(new Blob([data], {type: 'application/octet-stream'}));
      a.download = path.split('/').pop();
      document.body.appendChild(a);
      a.click();
      setTimeout(function() { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
      return 1;
    } catch (e) {
      console.error('shadow4d: cannot download ' + UTF8ToString($0) + ': ' + e);
      return 0;
    }
  }, path.c_str()) != 0;
  // clang-format on
}

#else

void run_frames(std::function<bool()> frame, std::function<void()> finish) {
  while (frame()) {
  }
  finish();
}

void persist_browser_files() {}

bool offer_download(const std::string&) { return false; }

#endif

}  // namespace s4d
