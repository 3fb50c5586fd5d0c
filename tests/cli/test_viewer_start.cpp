// `marchstudio view` as it starts: the exit codes before any window, and
// the panel's first layout in a small and a large window (under Xvfb).
#include <gtest/gtest.h>

#include <cmath>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// Before any window: a missing scene is bad input (2), no display is a
// system failure (3); neither needs Xvfb.
TEST(ViewerStart, ExitCodesWithoutAWindow) {
  TempDir dir;
  RunResult r = run_marchstudio({"view", (dir / "missing.toml").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("missing.toml: scene file not found"), std::string::npos) << r.err;
  BackgroundProcess proc({"env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", MARCH_BIN, "view",
                          (source_dir() / "scenes/seed.toml").string()},
                         dir / "out.txt", dir / "err.txt");
  EXPECT_EQ(proc.wait_exit(20), 3) << read_file(dir / "err.txt");
  EXPECT_NE(read_file(dir / "err.txt").find("xvfb-run"), std::string::npos);  // the hint
}

// The fraction of pixels of a window shot that the panel changes, against
// the same window with --no-panel. A small window starts with the panel
// collapsed to its title bar; a large one with it open beside the image.
double panel_cover(const fs::path& dir, const std::string& size) {
  double frac = -1;
  std::vector<Image> shots;
  for (const bool panel : {true, false}) {
    const fs::path shots_dir = dir / (size + (panel ? "_panel" : "_none"));
    std::vector<std::string> argv = {"env", x_display(), MARCH_BIN, "view",
                                     (source_dir() / "scenes/seed.toml").string(), "--size", size, "--paused",
                                     "--shot-frame", "3", "--shot-dir", shots_dir.string(), "--max-frames", "5",
                                     "--exit-after", "60"};
    if (!panel) argv.push_back("--no-panel");
    BackgroundProcess p(argv, dir / "out.txt", dir / "err.txt");
    EXPECT_EQ(p.wait_exit(90), 0) << read_file(dir / "err.txt");
    for (const auto& e : fs::directory_iterator(shots_dir))
      if (e.path().filename().string().find("_window_") != std::string::npos) shots.push_back(read_image(e.path()));
  }
  if (shots.size() != 2 || shots[0].width != shots[1].width) return frac;
  long changed = 0;
  for (int y = 0; y < shots[0].height; ++y)
    for (int x = 0; x < shots[0].width; ++x)
      for (int c = 0; c < 3; ++c)
        if (std::abs(shots[0].at(x, y, c) - shots[1].at(x, y, c)) > 2.0f / 255.0f) {
          ++changed;
          break;
        }
  return static_cast<double>(changed) / (static_cast<double>(shots[0].width) * shots[0].height);
}

TEST(ViewerPanel, CollapsesInASmallWindowAndOpensInALargeOne) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH";
  TempDir dir;
  const double small = panel_cover(dir.path(), "640x360");
  EXPECT_GE(small, 0.0) << "no window shots";
  EXPECT_LT(small, 0.08) << "at 640x360 the panel covers " << small * 100 << " % of the image";
  const double large = panel_cover(dir.path(), "960x540");
  EXPECT_GT(large, 0.2) << "at 960x540 the panel should start open (covers " << large * 100 << " %)";
  EXPECT_LT(large, 0.45);
}

}  // namespace
}  // namespace ms::test
