// Where marchstudio keeps what it can recompute: $XDG_CACHE_HOME/marchstudio,
// else ~/.cache/marchstudio, else the temporary directory's. One home for
// the irradiance cache (render/environment.h) and the dispatch choice
// (cli/dispatch_probe.h). Header-only: the lean tools link no more for it.
//
//   fs::path p = cache_dir() / "dispatch";
#pragma once
#include <cstdlib>
#include <filesystem>

namespace ms {

inline std::filesystem::path cache_dir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  const std::filesystem::path base = xdg && *xdg    ? std::filesystem::path(xdg)
                                     : home && *home ? std::filesystem::path(home) / ".cache"
                                                     : std::filesystem::temp_directory_path();
  return base / "marchstudio";
}

}  // namespace ms
