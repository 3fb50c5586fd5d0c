// `marchstudio render --watch`: the viewer's headless twin re-renders the
// output on every save (rename-saves included), survives a broken shader,
// and stops cleanly on SIGINT. No window, no Xvfb.
#include <gtest/gtest.h>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

TEST(RenderWatch, RerendersOnSaveAndStopsOnSigint) {
  TempDir dir;
  // Without [bounds]: the test grows the ball, which a tight bounding
  // volume would clip.
  std::string toml = read_file(source_dir() / "scenes/seed.toml");
  const size_t at = toml.find("\n[bounds]\n");
  if (at != std::string::npos) toml.erase(at + 1, toml.find("\n[", at + 1) - at);
  write_file(dir / "seed.toml", toml);
  const std::string good = read_file(source_dir() / "scenes/seed.glsl");
  write_file(dir / "seed.glsl", good);
  BackgroundProcess proc({MARCH_BIN, "render", "--watch", (dir / "seed.toml").string(), "-o",
                          (dir / "out.png").string(), "--size", "160x90"},
                         dir / "out.txt", dir / "err.txt");
  ASSERT_TRUE(proc.started());
  ASSERT_FALSE(wait_for_line(dir / "err.txt", "watch: render 1 ok", 30).empty()) << read_file(dir / "err.txt");
  const Image first = read_image(dir / "out.png");

  std::string bigger = good;
  bigger.replace(bigger.find("1.0), MAT_BALL"), 3, "1.4");
  save_by_rename(dir / "seed.glsl", bigger);
  ASSERT_FALSE(wait_for_line(dir / "err.txt", "watch: render 2 ok", 30).empty()) << read_file(dir / "err.txt");
  EXPECT_GT(redness(read_image(dir / "out.png")), redness(first) + 0.01);

  save_by_rename(dir / "seed.glsl", "vec2 map(vec3 p) { nope; }\n");
  ASSERT_FALSE(wait_for_line(dir / "err.txt", "watch: render 3 failed", 30).empty()) << read_file(dir / "err.txt");
  EXPECT_NE(read_file(dir / "err.txt").find("seed.glsl:1:"), std::string::npos);
  EXPECT_TRUE(proc.running());
  save_by_rename(dir / "seed.glsl", good);
  ASSERT_FALSE(wait_for_line(dir / "err.txt", "watch: render 4 ok", 30).empty()) << read_file(dir / "err.txt");
  EXPECT_LT(mean_abs_diff(read_image(dir / "out.png"), first), 1e-3);
  // One output line (the path) per successful render.
  EXPECT_EQ(file_lines(dir / "out.txt").size(), 3u);

  proc.signal(SIGINT);
  EXPECT_EQ(proc.wait_exit(10), 0);
}

TEST(RenderWatch, ABadFlagStillExitsAtOnce) {
  // No save can fix an output directory that cannot be made (a file is in
  // the way): exit 2 at once, not wait.
  TempDir dir;
  write_file(dir / "afile", "x");
  BackgroundProcess proc({MARCH_BIN, "render", "--watch", (source_dir() / "scenes/seed.toml").string(), "-o",
                          (dir / "afile/sub/out.png").string()},
                         dir / "out.txt", dir / "err.txt");
  EXPECT_EQ(proc.wait_exit(20), 2) << read_file(dir / "err.txt");
  EXPECT_NE(read_file(dir / "err.txt").find("output directory cannot be made"), std::string::npos)
      << read_file(dir / "err.txt");
}

}  // namespace
}  // namespace ms::test
