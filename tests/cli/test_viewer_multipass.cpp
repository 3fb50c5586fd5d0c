// Multipass in the viewer under Xvfb: a Shadertoy shader's buffer keeps
// evolving while another pass is edited and hot-reloaded, a broken pass
// keeps the last good graph, and the fix renders with the buffer still
// counting (not reset to 0).
#include <gtest/gtest.h>

#include <string>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// Buffer A counts frames (a quarter level a frame); the image shows the
// count in red, and in `green` too.
const char* kA = "void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0) + vec4(0.25 / 255.0); }\n";
std::string image_pass(const std::string& green) {
  return "void mainImage(out vec4 o, in vec2 f) { float n = texelFetch(iChannel0, ivec2(f), 0).r; o = vec4(n, " + green +
         ", 0.0, 1.0); }\n";
}

TEST(ViewerMultipass, ABufferEvolvesAcrossAReloadOfAnotherPass) {
  if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
  TempDir dir;
  write_file(dir / "s.toml",
             "[scene]\nname = \"count\"\n[render]\nwidth = 32\nheight = 24\n"
             "[[passes]]\ntype = \"buffer\"\nbuffer = \"A\"\nfile = \"a.glsl\"\niChannel0 = { buffer = \"A\" }\n"
             "[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\niChannel0 = { buffer = \"A\" }\n");
  write_file(dir / "a.glsl", kA);
  write_file(dir / "img.glsl", image_pass("0.0"));
  const fs::path log = dir / "log.txt";
  BackgroundProcess proc({"env", x_display(), MARCH_BIN, "view",
                          (dir / "s.toml").string(), "--size", "32x24", "--no-panel", "--log", log.string(),
                          "--capture-dir", (dir / "cap").string(), "--exit-after", "60"},
                         dir / "out.txt", dir / "err.txt");
  ASSERT_TRUE(proc.started());
  ASSERT_FALSE(wait_for_line(log, "^capture 0 ", 30).empty()) << read_file(log) << read_file(dir / "err.txt");
  const float first = read_image(dir / "cap/frame_0.png").at(0, 0, 0);
  // Let it count, then break the image pass: the last good graph stays.
  ASSERT_FALSE(wait_for_line(log, "^frames ", 10).empty()) << read_file(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  save_by_rename(dir / "img.glsl", "void mainImage(out vec4 o, in vec2 f) { nope; }\n");
  const std::string broken = wait_for_line(log, "^reload (ok|failed) 1 ", 30);
  EXPECT_EQ(broken.rfind("reload failed 1", 0), 0u) << broken;
  EXPECT_NE(broken.find("img.glsl:1:"), std::string::npos) << broken;
  // The fix: green now shows the count too, and the count went on.
  save_by_rename(dir / "img.glsl", image_pass("n"));
  const std::string fixed = wait_for_line(log, "^reload (ok|failed) 2 ", 30);
  ASSERT_EQ(fixed.rfind("reload ok 2", 0), 0u) << fixed << read_file(dir / "err.txt");
  ASSERT_FALSE(wait_for_line(log, "^capture 2 ", 10).empty());
  const Image after = read_image(dir / "cap/frame_2.png");
  EXPECT_GT(after.at(0, 0, 0), first + 4.0f / 255.0f) << "the buffer was reset by the reload";
  EXPECT_NEAR(after.at(0, 0, 1), after.at(0, 0, 0), 1.5f / 255.0f);
  EXPECT_TRUE(proc.running()) << read_file(dir / "err.txt");
}

}  // namespace
}  // namespace ms::test
