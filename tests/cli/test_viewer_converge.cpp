// The viewer accumulates a still scene while time runs (not --paused): a
// program that reads neither time nor the frame number draws the same image
// at every time, so its samples add up to the target; one whose map reads
// uTime starts again every frame. Under Xvfb.
#include <gtest/gtest.h>

#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// A ball on a plain floor: no checker, no [[animation]], nothing animated.
const char* kScene = R"(
[scene]
name = "still"
map  = "still.glsl"

[camera]
position = [0.0, 1.6, -5.0]
target   = [0.0, 0.8, 0.0]

[[lights]]
position = [4.0, 5.0, -1.5]

[[materials]]
name = "floor"

[[materials]]
name = "ball"
color = [0.85, 0.1, 0.06]

[[planes]]
normal   = [0.0, 1.0, 0.0]
material = "floor"
)";

std::string map_glsl(const std::string& radius) {
  return "vec2 map(vec3 p) {\n"
         "  return vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), " + radius + "), MAT_BALL);\n"
         "}\n";
}

// Runs the viewer, time running, for `frames` frames; returns its log.
std::string run_view(const TempDir& dir, const std::string& radius, int frames) {
  write_file(dir / "still.toml", kScene);
  write_file(dir / "still.glsl", map_glsl(radius));
  const fs::path log = dir / "log.txt";
  const std::vector<std::string> argv = {"env", x_display(), MARCH_BIN, "view", (dir / "still.toml").string(),
                                         "--size", "160x90", "--no-panel", "--accumulate", "8", "--log",
                                         log.string(), "--capture-dir", (dir / "cap").string(), "--max-frames",
                                         std::to_string(frames), "--exit-after", "90"};
  BackgroundProcess proc(argv, dir / "out.txt", dir / "err.txt");
  EXPECT_TRUE(proc.started());
  EXPECT_EQ(proc.wait_exit(120), 0) << read_file(dir / "err.txt");
  return read_file(log);
}

TEST(ViewerConverge, AStillSceneConvergesWhileTimeRuns) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
  TempDir dir;
  const std::string log = run_view(dir, "1.0", 40);
  EXPECT_NE(log.find("\nconverged 8\n"), std::string::npos) << "time ran and the still scene never converged\n" << log;
  EXPECT_TRUE(fs::exists(dir / "cap" / "converged_8.png")) << log;
}

// The same scene with a radius that follows uTime: every frame is another
// image, so it never gets past one sample (the test can tell them apart).
TEST(ViewerConverge, AMapThatReadsTimeStartsAgainEveryFrame) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
  TempDir dir;
  const std::string log = run_view(dir, "(0.8 + 0.2 * sin(uTime * 3.0))", 40);
  EXPECT_NE(log.find("reload ok 0 "), std::string::npos) << log;
  EXPECT_EQ(log.find("converged"), std::string::npos) << log;
}

}  // namespace
}  // namespace ms::test
