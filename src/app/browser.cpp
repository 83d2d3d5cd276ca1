#include "app/browser.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#endif

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace s4d {

#ifdef __EMSCRIPTEN__

namespace {

// The files the picker copied into the page's memory, until the window takes them (the page has
// one thread for the window: the picker's callback runs between its frames).
std::vector<std::string>& chosen_files() {
  static std::vector<std::string> files;
  return files;
}

TouchGesture& touch_gesture() {
  static TouchGesture gesture;
  return gesture;
}

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

void follow_browser_window() {
  // Browser.setCanvasSize tells emscripten's GLFW (its resize listener), not glfwSetWindowSize:
  // that one asks for fullscreen when the size equals the screen's (a maximised borderless page).
  emscripten_set_resize_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, false,
                                 [](int, const EmscriptenUiEvent* e, void*) -> EM_BOOL {
                                   if (e->windowInnerWidth > 0 && e->windowInnerHeight > 0)
                                     EM_ASM({ Browser.setCanvasSize($0, $1); }, e->windowInnerWidth,
                                            e->windowInnerHeight);
                                   return EM_FALSE;
                                 });
}

bool choose_file_to_open(const std::vector<std::string>& extensions) {
  std::string accept;
  for (const std::string& e : extensions) accept += (accept.empty() ? "" : ",") + e;
  // clang-format off
  EM_ASM({
    let input = document.getElementById('s4d-open-file');
    if (!input) {
      input = document.createElement('input');
      input.type = 'file';
      input.id = 's4d-open-file';
      input.style.display = 'none';
      document.body.appendChild(input);
      input.addEventListener('change', function() {
        const file = input.files[0];
        if (!file) return;
        file.arrayBuffer().then(function(data) {
          FS.mkdirTree('/uploads');
          const path = '/uploads/' + file.name.split('/').join('_');
          FS.writeFile(path, new Uint8Array(data));
          const n = lengthBytesUTF8(path) + 1, p = _malloc(n);
          stringToUTF8(path, p, n);
          _s4d_file_chosen(p);
          _free(p);
        }).catch(function(e) { console.error('shadow4d: cannot read ' + file.name + ': ' + e); });
      });
    }
    input.accept = UTF8ToString($0);
    input.value = null;
    input.click();  // the browser shows it within a user's click or key (File > Open, Ctrl+O)
  }, accept.c_str());
  // clang-format on
  return true;
}

std::vector<std::string> take_chosen_files() { return std::exchange(chosen_files(), {}); }

TouchGesture take_touch_gesture() { return std::exchange(touch_gesture(), TouchGesture{}); }

#else

void run_frames(std::function<bool()> frame, std::function<void()> finish) {
  while (frame()) {
  }
  finish();
}

void persist_browser_files() {}

bool offer_download(const std::string&) { return false; }

void follow_browser_window() {}

bool choose_file_to_open(const std::vector<std::string>&) { return false; }

std::vector<std::string> take_chosen_files() { return {}; }

TouchGesture take_touch_gesture() { return {}; }

#endif

}  // namespace s4d

#ifdef __EMSCRIPTEN__
// Called by the picker's JS (choose_file_to_open) once the file is in the page's memory.
extern "C" EMSCRIPTEN_KEEPALIVE void s4d_file_chosen(const char* path) { s4d::chosen_files().emplace_back(path); }

// Called by index.html's touch handler for two fingers: they moved by (dx, dy), spread `scale` times.
extern "C" EMSCRIPTEN_KEEPALIVE void s4d_touch_gesture(double dx, double dy, double scale) {
  s4d::TouchGesture& g = s4d::touch_gesture();
  if (!std::isfinite(dx) || !std::isfinite(dy) || !(scale > 0) || !std::isfinite(scale)) return;
  g.dx += dx;
  g.dy += dy;
  g.scale *= scale;
}
#endif
