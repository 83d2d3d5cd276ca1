// The browser around the web page (the emscripten build): its frame loop and its storage. The
// desktop build compiles the same calls to what a desktop does (a loop of its own, files that are
// on disk already), so the window's code has one path for both.
#pragma once
#include <functional>
#include <string>

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

}  // namespace s4d
