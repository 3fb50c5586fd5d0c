// The bounds check (render/bounds_check.h): geometry that crosses a scene's
// [bounds] is cut off, so `render`, `bench` and the viewer warn when
// map() is negative on the bounds' surface; points under a declared plane
// do not count. That every shipped scene holds its map is checked by
// test_cost.cpp, whose bench run would warn.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

std::string data(const std::string& name) { return (fs::path(MARCH_TEST_DATA) / "bounds" / name).string(); }

const char* kWarning = "warning: map() is negative on the [bounds] surface";

TEST(BoundsCheck, RenderVerboseWarnsWhenTheMapCrossesItsBounds) {
  TempDir dir;
  RunResult r = run_marchstudio({"render", data("ball_big.toml"), "-o", (dir / "a.png").string(), "--size", "32x18", "-v"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(kWarning), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ball_big.toml: warning"), std::string::npos) << "names the scene file: " << r.err;
  EXPECT_NE(r.err.find("grow [bounds]"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "a.png")) << "a warning, not an error";
  // The same ball at the slider's default fits.
  r = run_marchstudio({"render", data("ball.toml"), "-o", (dir / "b.png").string(), "--size", "32x18", "-v"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find(kWarning), std::string::npos) << r.err;
}

TEST(BoundsCheck, BenchWarnsAndStillReports) {
  const RunResult r = run_marchstudio({"bench", data("ball_big.toml"), "--size", "32x18", "--frames", "1",
                                       "--warmup", "0", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(kWarning), std::string::npos) << r.err;
  EXPECT_TRUE(nlohmann::json::accept(r.out)) << "stdout stays JSON";
}

TEST(BoundsCheck, WhatAPlaneHidesDoesNotCount) {
  TempDir dir;
  const RunResult r = run_marchstudio({"render", data("sunk.toml"), "-o", (dir / "a.png").string(), "--size", "32x18", "-v"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find(kWarning), std::string::npos) << r.err;
}

// The viewer checks after every reload: growing the ball past the bounds on
// disk logs the warning, shrinking it back logs "bounds ok".
TEST(BoundsCheck, TheViewerWarnsAfterAReload) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
  TempDir dir;
  write_file(dir / "ball.toml", read_file(data("ball.toml")));
  write_file(dir / "ball.glsl", read_file(data("ball.glsl")));
  const fs::path log = dir / "log.txt";
  BackgroundProcess proc({"env", x_display(), MARCH_BIN, "view",
                          (dir / "ball.toml").string(), "--size", "64x36", "--paused", "--no-panel", "--log",
                          log.string(), "--exit-after", "40"},
                         dir / "out.txt", dir / "err.txt");
  ASSERT_TRUE(proc.started());
  ASSERT_FALSE(wait_for_line(log, "^reload ok 0 ", 30).empty()) << read_file(dir / "err.txt");
  save_by_rename(dir / "ball.glsl", read_file(data("ball_big.glsl")));
  const std::string warned = wait_for_line(log, "^bounds .*warning: map\\(\\) is negative", 20);
  EXPECT_FALSE(warned.empty()) << read_file(log) << read_file(dir / "err.txt");
  EXPECT_NE(read_file(dir / "err.txt").find(kWarning), std::string::npos) << "and on stderr";
  save_by_rename(dir / "ball.glsl", read_file(data("ball.glsl")));
  EXPECT_FALSE(wait_for_line(log, "^bounds ok$", 20).empty()) << read_file(log);
}

// While the bounds do not hold, the window says so on screen (the amber box
// at the bottom), not only in the log: a window shot with the grown ball
// has it, one with the ball inside its bounds has none.
int amber_pixels(const fs::path& dir, const std::string& glsl) {
  write_file(dir / "ball.toml", read_file(data("ball.toml")));
  write_file(dir / "ball.glsl", read_file(data(glsl)));
  const fs::path shots = dir / ("shots_" + glsl);
  BackgroundProcess proc({"env", x_display(),
                          MARCH_BIN, "view", (dir / "ball.toml").string(), "--size", "640x360", "--paused", "--no-panel",
                          "--shot-frame", "8", "--shot-dir", shots.string(), "--max-frames", "10", "--exit-after", "60"},
                         dir / "out.txt", dir / "err.txt");
  EXPECT_EQ(proc.wait_exit(90), 0) << read_file(dir / "err.txt");
  int n = -1;
  for (const auto& e : fs::directory_iterator(shots)) {
    if (e.path().filename().string().find("_window_") == std::string::npos) continue;
    const Image img = read_image(e.path());
    n = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        n += std::abs(img.at(x, y, 0) - 109 / 255.0f) < 12 / 255.0f &&  // the box's amber over the floor
             std::abs(img.at(x, y, 1) - 83 / 255.0f) < 12 / 255.0f && std::abs(img.at(x, y, 2) - 31 / 255.0f) < 12 / 255.0f;
  }
  return n;
}

TEST(BoundsCheck, TheViewerShowsItOnScreen) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
  TempDir dir;
  EXPECT_GT(amber_pixels(dir.path(), "ball_big.glsl"), 3000) << "no warning box on screen";
  EXPECT_EQ(amber_pixels(dir.path(), "ball.glsl"), 0) << "a warning box where the bounds hold";
}

}  // namespace
}  // namespace ms::test
