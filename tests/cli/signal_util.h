// Signals during a write, for the still and mesh signal tests:
//   expect_signal_leaves_no_temp(dir, {"render", scene, "-o", "x.png"}, ".x.png.tmp", SIGTERM, {}, 30000);
// tests/shims/slow_temp.c holds each temporary's creation `hold_ms` so the
// signal lands while it exists.
#pragma once
#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {

inline std::string slow_temp_preload() {
  const char* p = std::getenv("LD_PRELOAD");
  return (p && *p ? std::string(p) + ":" : std::string()) + MARCH_SLOW_TEMP_SHIM;
}

// Runs marchstudio `args` in `dir` under the shim, sends `sig` once a file
// named `temp_prefix`... appears, and expects 128 + sig with nothing left
// in `dir` but `keep` and the logs.
inline void expect_signal_leaves_no_temp(const TempDir& dir, const std::vector<std::string>& args,
                                         const std::string& temp_prefix, int sig, std::vector<std::string> keep,
                                         int hold_ms) {
  std::vector<std::string> argv = {"env", "LD_PRELOAD=" + slow_temp_preload(),
                                   "SLOW_TEMP_MS=" + std::to_string(hold_ms), MARCH_BIN};
  argv.insert(argv.end(), args.begin(), args.end());
  BackgroundProcess p(argv, dir / "out.txt", dir / "err.txt", dir.path());
  const auto temp_exists = [&] {
    for (const std::string& name : dir.entries())
      if (name.rfind(temp_prefix, 0) == 0) return true;
    return false;
  };
  ASSERT_TRUE(wait_until(temp_exists, 90)) << read_file(dir / "err.txt");
  p.signal(sig);
  EXPECT_EQ(p.wait_exit(20), 128 + sig) << read_file(dir / "err.txt");
  std::vector<std::string> left = dir.entries();
  keep.insert(keep.end(), {"err.txt", "out.txt"});
  std::sort(left.begin(), left.end());
  std::sort(keep.begin(), keep.end());
  EXPECT_EQ(left, keep) << "no output, no temporary";
}

}  // namespace ms::test
