// `marchstudio render --watch`, the viewer's headless twin for people
// editing over SSH: render once, then again after every save of the scene
// or any file it includes, until SIGINT/SIGTERM. Same watcher (and
// debounce) as the viewer; the render itself is the caller's (cli/).
#pragma once
#include <filesystem>
#include <functional>
#include <vector>

namespace ms::live {

struct WatchRenderOptions {
  std::function<void()> render;  // one render exactly as without --watch; throws ms::Error
  // The files that render reads (scene, map, includes); throws ms::Error.
  std::function<std::vector<std::filesystem::path>()> files;
  int debounce_ms = 10;
};

// Returns 0 once interrupted. A failed render prints its one-line error and
// the loop waits for the next save. Throws (ends early) only when the FIRST
// render fails with an error outside the watched files (a bad flag, a
// missing output directory: no save can fix it) or inotify/signalfd are
// missing.
int watch_and_render(const WatchRenderOptions& opts);

}  // namespace ms::live
