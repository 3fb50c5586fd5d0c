// The viewer on a graph file alone, under Xvfb: it opens with the default
// scene render makes of the file (docs/scene-graph.md#a-graph-file-on-its-own),
// and a save reloads it; and on an animated graph, which it plays.
#include <gtest/gtest.h>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

TEST(ViewerGraphAlone, OpensWithRendersDefaultSceneAndReloadsOnSave) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
  TempDir dir;
  std::string json = read_file(source_dir() / "tests" / "data" / "graph" / "part.json");
  write_file(dir / "part.json", json);
  const fs::path log = dir / "log.txt";
  BackgroundProcess proc({"env", x_display(), MARCH_BIN, "view",
                          (dir / "part.json").string(), "--size", "160x90", "--paused", "--no-panel", "--log",
                          log.string(), "--capture-dir", (dir / "cap").string(), "--exit-after", "200"},
                         dir / "out.txt", dir / "err.txt");
  ASSERT_TRUE(proc.started());
  ASSERT_FALSE(wait_for_line(log, "^reload ok 0 ", 120).empty()) << read_file(log) << read_file(dir / "err.txt");
  ASSERT_FALSE(wait_for_line(log, "^capture 0 ", 10).empty());
  const RunResult r = run_marchstudio({"render", (dir / "part.json").string(), "--size", "160x90", "-o",
                                       (dir / "render.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_LE(max_abs_diff(read_image(dir / "cap" / "frame_0.png"), read_image(dir / "render.png")), 2.0 / 255.0);
  // A saved edit reloads the file as a graph again.
  json.replace(json.find("\"r\": 0.35"), 9, "\"r\": 0.45");
  save_by_rename(dir / "part.json", json);
  const std::string line = wait_for_line(log, "^reload (ok|failed) 1 ", 120);
  EXPECT_EQ(line.rfind("reload ok ", 0), 0u) << line << read_file(log) << read_file(dir / "err.txt");
}

// The viewer plays a graph's [[animation]] tracks: paused at a time, it
// shows the pose `render --time` gives there, not the file's pose.
TEST(ViewerGraphAlone, PlaysTheGraphTracksAsRenderPosesThem) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
  TempDir dir;
  const fs::path scene = source_dir() / "scenes" / "assembly.toml";
  const fs::path log = dir / "log.txt";
  BackgroundProcess proc({"env", x_display(), MARCH_BIN, "view", scene.string(), "--size", "160x90", "--time", "1.5",
                          "--paused", "--no-panel", "--log", log.string(), "--capture-dir", (dir / "cap").string(),
                          "--exit-after", "200"},
                         dir / "out.txt", dir / "err.txt");
  ASSERT_TRUE(proc.started());
  ASSERT_FALSE(wait_for_line(log, "^reload ok 0 ", 120).empty()) << read_file(log) << read_file(dir / "err.txt");
  ASSERT_FALSE(wait_for_line(log, "^capture 0 ", 60).empty()) << read_file(log);
  for (const char* t : {"1.5", "0"}) {
    const RunResult r = run_marchstudio({"render", scene.string(), "--size", "160x90", "--spp", "1", "--time", t, "-o",
                                         (dir / (std::string("t") + t + ".png")).string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const Image shown = read_image(dir / "cap" / "frame_0.png");
  EXPECT_LE(max_abs_diff(shown, read_image(dir / "t1.5.png")), 2.0 / 255.0);
  // The gears have turned by 1.5 s: the file's pose is visibly another image.
  EXPECT_GT(max_abs_diff(shown, read_image(dir / "t0.png")), 0.1);
}

}  // namespace
}  // namespace ms::test
