// The browser around the web page (the emscripten build): its frame loop and its storage. The
// desktop build compiles the same calls to what a desktop does (a loop of its own, files that are
// on disk already), so the window's code has one path for both.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace s4d {

// Calls `frame` until it returns false, then `finish`. On the desktop a plain loop; in the page
// the browser calls `frame` once per animation frame (requestAnimationFrame) and this returns at
// once, the two functions living on as long as the page.
void run_frames(std::function<bool()> frame, std::function<void()> finish);

// The page's autosave folder lives in the browser's IndexedDB (IDBFS, mounted by index.html
// before main): copies what was written there to IndexedDB. Nothing on the desktop.
void persist_browser_files();

// Hands a file of the page's memory to the browser as a download (Save). False on the desktop.
bool offer_download(const std::string& path);

// The page's canvas and window take the browser window's inner size (CSS pixels) whenever it
// changes (the window's size callback and the next frame's layout follow). Nothing on the desktop.
void follow_browser_window();

// The page's two-finger gestures since the last call (index.html turns touches into these): the
// fingers' centre moved by (dx, dy) pixels (turn the view as a drag does) and their distance
// grew `scale` times (zoom as the wheel does). None on the desktop.
struct TouchGesture {
  double dx = 0, dy = 0, scale = 1;
};
TouchGesture take_touch_gesture();

// File > Open in the page: the browser's file picker (<input type=file>) for files ending in one
// of `extensions`. The chosen file is copied into the page's memory and comes back through
// take_chosen_files. False on the desktop (it has a dialog of its own).
bool choose_file_to_open(const std::vector<std::string>& extensions);
// The page-memory paths of the files chosen since the last call (none on the desktop).
std::vector<std::string> take_chosen_files();

}  // namespace s4d
