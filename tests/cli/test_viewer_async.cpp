// Reloads compile on the viewer's worker thread (live/compile_worker.h,
// docs/viewer.md "How a reload compiles"), under Xvfb: frames keep coming
// while a heavy shader compiles, a save during a compile ends on the newest
// file, a broken shader keeps the last good frame, and the adopted image is
// render's. Frames are counted, never timed.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

class AsyncReload : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
    write_file(dir / "seed.toml", kBallScene);
    write_file(dir / "seed.glsl", ball_map("1.0"));
    proc = std::make_unique<BackgroundProcess>(
        std::vector<std::string>{"env", x_display(), MARCH_BIN, "view",
                                 (dir / "seed.toml").string(), "--size", "160x90", "--paused", "--no-panel", "--log",
                                 log().string(), "--capture-dir", (dir / "cap").string(), "--exit-after", "120"},
        dir / "out.txt", dir / "err.txt");
    ASSERT_TRUE(proc->started());
    ASSERT_FALSE(wait_for_line(log(), "^reload ok 0 ", 60).empty()) << read_file(log()) << read_file(dir / "err.txt");
    ASSERT_FALSE(wait_for_line(log(), "^capture 0 ", 10).empty());
  }
  fs::path log() const { return dir / "log.txt"; }
  Image capture(int k) { return read_image(dir / "cap" / ("frame_" + std::to_string(k) + ".png")); }
  Image render(const std::string& glsl) {
    TempDir r;
    write_file(r / "seed.toml", kBallScene);
    write_file(r / "seed.glsl", glsl);
    const RunResult run = run_marchstudio({"render", (r / "seed.toml").string(), "--size", "160x90", "-o",
                                           (r / "out.png").string()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return read_image(r / "out.png");
  }

  TempDir dir;
  std::unique_ptr<BackgroundProcess> proc;
};

TEST_F(AsyncReload, FramesKeepComingWhileAHeavyShaderCompiles) {
  const std::string heavy = ball_map("1.3", kHeavyLines);
  save_by_rename(dir / "seed.glsl", heavy);
  ASSERT_FALSE(wait_for_line(log(), "^reload compiling 1$", 20).empty()) << read_file(log());
  const std::string line = wait_for_line(log(), "^reload (ok|failed) 1 ", 90);
  ASSERT_EQ(line.rfind("reload ok 1 ", 0), 0u) << line << read_file(dir / "err.txt");
  // The old program kept drawing while the worker compiled and warmed up.
  EXPECT_GT(field(line, "frames_during_compile"), 0) << line;
  ASSERT_FALSE(wait_for_line(log(), "^capture 1 ", 10).empty());
  const Image want = render(heavy), got = capture(1);
  EXPECT_LE(max_abs_diff(got, want), 1.0 / 255.0) << "the adopted program's frame is not render's";
  EXPECT_GT(mean_abs_diff(got, capture(0)), 1e-3) << "the reload did not change the image";
  EXPECT_TRUE(proc->running());
}

TEST_F(AsyncReload, ASaveDuringACompileEndsOnTheNewestFile) {
  save_by_rename(dir / "seed.glsl", ball_map("1.3", kHeavyLines));
  ASSERT_FALSE(wait_for_line(log(), "^reload compiling 1$", 20).empty()) << read_file(log());
  const std::string last = ball_map("0.7", kHeavyLines, "// the newest\n");
  save_by_rename(dir / "seed.glsl", last);
  // Number 1 is dropped for number 2 (or done first, when it won the race).
  const std::string line = wait_for_line(log(), "^reload (ok|failed) 2 ", 90);
  ASSERT_EQ(line.rfind("reload ok 2 ", 0), 0u) << line << read_file(log());
  const std::string log_text = read_file(log());
  EXPECT_TRUE(log_text.find("reload superseded 1 by 2") != std::string::npos ||
              log_text.find("reload ok 1 ") != std::string::npos)
      << log_text;
  ASSERT_FALSE(wait_for_line(log(), "^capture 2 ", 10).empty());
  EXPECT_LE(max_abs_diff(capture(2), render(last)), 1.0 / 255.0) << "the viewer does not show the newest save";
}

TEST_F(AsyncReload, ABrokenShaderKeepsTheLastGoodFrame) {
  // Heavy and then a type error at its last line: found by the worker's compile.
  const std::string broken = ball_map("1.3", kHeavyLines, "float broken() { return vec3(1.0); }\n");
  const int bad_line = static_cast<int>(std::count(broken.begin(), broken.end(), '\n'));
  save_by_rename(dir / "seed.glsl", broken);
  ASSERT_FALSE(wait_for_line(log(), "^reload compiling 1$", 20).empty()) << read_file(log());
  const std::string line = wait_for_line(log(), "^reload (ok|failed) 1 ", 90);
  ASSERT_EQ(line.rfind("reload failed 1 ", 0), 0u) << line;
  EXPECT_NE(line.find("seed.glsl:" + std::to_string(bad_line) + ":"), std::string::npos) << line;
  EXPECT_NE(read_file(dir / "err.txt").find("seed.glsl:" + std::to_string(bad_line) + ":"), std::string::npos);
  ASSERT_FALSE(wait_for_line(log(), "^capture 1 ", 10).empty());
  EXPECT_LT(mean_abs_diff(capture(1), capture(0)), 1e-3) << "a failed reload changed the image";
  // Fixed: the worker's next program shows.
  const std::string fixed = ball_map("1.3");
  save_by_rename(dir / "seed.glsl", fixed);
  ASSERT_EQ(wait_for_line(log(), "^reload (ok|failed) 2 ", 90).rfind("reload ok 2 ", 0), 0u) << read_file(log());
  ASSERT_FALSE(wait_for_line(log(), "^capture 2 ", 10).empty());
  EXPECT_LE(max_abs_diff(capture(2), render(fixed)), 1.0 / 255.0);
}

// A panel value's rebuilds (live, then folded again) compile on the worker
// too: frames keep coming with the last program while the heavy map
// compiles, and the shot after the drag is render of the final value.
// --drag and --shot-frame count settled frames, so this is deterministic.
TEST(AsyncRebuild, ADraggedValueCompilesOnTheWorker) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
  TempDir dir;
  write_file(dir / "seed.toml", kBallScene);
  write_file(dir / "seed.glsl", ball_map("1.0", 20));
  const fs::path log = dir / "log.txt";
  BackgroundProcess proc({"env", x_display(), MARCH_BIN, "view",
                          (dir / "seed.toml").string(), "--size", "160x90", "--paused", "--no-panel", "--log",
                          log.string(), "--shot-dir", (dir / "shots").string(), "--shot-frame", "20", "--drag",
                          "materials[1].color=0.1,0.3,0.9@3..8", "--exit-after", "150"},
                         dir / "out.txt", dir / "err.txt");
  ASSERT_TRUE(proc.started());
  ASSERT_FALSE(wait_for_line(log, "^screenshot ", 140).empty()) << read_file(log) << read_file(dir / "err.txt");
  std::vector<std::string> values;
  for (const std::string& l : file_lines(log))
    if (l.rfind("values ", 0) == 0) values.push_back(l);
  ASSERT_EQ(values.size(), 2u) << read_file(log);
  EXPECT_EQ(values[0].rfind("values ok live=materials[1].color ", 0), 0u) << values[0];
  EXPECT_EQ(values[1].rfind("values ok live=none ", 0), 0u) << values[1];
  for (const std::string& v : values) EXPECT_GT(field(v, "frames_during_compile"), 0) << v;
  TempDir r;
  write_file(r / "seed.toml", kBallScene);
  write_file(r / "seed.glsl", ball_map("1.0", 20));
  const RunResult run = run_marchstudio({"render", (r / "seed.toml").string(), "--size", "160x90", "--set",
                                         "materials.ball.color=[0.1,0.3,0.9]", "-o", (r / "out.png").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_LE(max_abs_diff(read_image(dir / "shots/seed_1.png"), read_image(r / "out.png")), 1.0 / 255.0);
}

}  // namespace
}  // namespace ms::test
