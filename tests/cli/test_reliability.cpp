// Reliability through the real binary (docs/reliability.md): include
// confinement and --allow-include; --timeout on a shader that never ends
// (the watchdog), on too much work (stopped between draws) and in a
// sequence; the memory budget; tiles that leave the image unchanged.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// An unbounded loop with a heavy body. On a GPU it never ends; llvmpipe
// stops all loops of one invocation after 65535 iterations in total (its
// loop limiter), so here a 128x128 frame "only" takes about a minute.
const std::string kStep = "z = vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y) * 0.5 + 0.25 * sin(z.yx + iTime);\n";
std::string endless_loop(const std::string& condition = "true") {
  std::string body;
  for (int i = 0; i < 16; ++i) body += "    " + kStep;
  return "void mainImage(out vec4 c, in vec2 f) {\n"
         "  vec2 z = f / iResolution.xy;\n"
         "  if (" + condition + ") {\n"
         "  for (;;) {\n" + body +
         "    if (z.x > 1e30 && iTime < -1.0) break;\n"
         "  }\n"
         "  }\n"
         "  c = vec4(z, 0.0, 1.0);\n"
         "}\n";
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool one_line(const std::string& err) {
  return !err.empty() && std::count(err.begin(), err.end(), '\n') == 1 && err.back() == '\n';
}

// The seed scene copied into dir/scene/ with `prefix` before its map.
fs::path seed_scene(const TempDir& dir, const std::string& prefix) {
  write_file(dir / "scene/seed.toml", read_file(source_dir() / "scenes/seed.toml"));
  write_file(dir / "scene/seed.glsl", prefix + read_file(source_dir() / "scenes/seed.glsl"));
  return dir / "scene/seed.toml";
}

TEST(Confinement, EtcPasswdIsRefusedAndNothingOfItIsShown) {
  TempDir dir;
  const fs::path scene = seed_scene(dir, "#include \"/etc/passwd\"\n");
  const RunResult r = run_marchstudio({"render", scene.string(), "-o", (dir / "out.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("seed.glsl:1: include '/etc/passwd' resolves to /etc/passwd, outside"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--allow-include"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("root:"), std::string::npos) << "passwd content on stderr: " << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(Confinement, DotDotAndSymlinksOutOfTheSceneAreRefusedUntilAllowed) {
  TempDir dir;
  write_file(dir / "secret/key.glsl", "// SECRET_TOKEN_42\nfloat keyRadius() { return 1.0; }\n");
  const std::string map = read_file(source_dir() / "scenes/seed.glsl");
  const fs::path scene = seed_scene(dir, "#include \"../secret/key.glsl\"\n");
  RunResult r = run_marchstudio({"render", scene.string(), "-o", (dir / "out.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("secret/key.glsl"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("SECRET_TOKEN"), std::string::npos) << r.err;

  // A symlink in the scene's folder that leads out: judged by where it leads.
  fs::create_symlink(dir / "secret/key.glsl", dir / "scene/key.glsl");
  write_file(dir / "scene/seed.glsl", "#include \"key.glsl\"\n" + map);
  r = run_marchstudio({"render", scene.string(), "-o", (dir / "out.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("secret/key.glsl"), std::string::npos) << r.err;
  // A symlinked directory too.
  fs::create_directory_symlink(dir.path(), dir / "scene/up");
  write_file(dir / "scene/seed.glsl", "#include \"up/secret/key.glsl\"\n" + map);
  r = run_marchstudio({"render", scene.string(), "-o", (dir / "out.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));

  // --allow-include DIR widens the roots: the same render works.
  r = run_marchstudio({"render", scene.string(), "-o", (dir / "out.png").string(), "--size", "32x18",
                       "--allow-include", (dir / "secret").string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out.png"));
}

TEST(Confinement, AllowIncludeIsCheckedAndBenchTakesIt) {
  TempDir dir;
  RunResult r = run_marchstudio({"render", (source_dir() / "scenes/seed.toml").string(), "-o",
                                 (dir / "out.png").string(), "--allow-include", (dir / "nope").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--allow-include: '"), std::string::npos) << r.err;
  write_file(dir / "lib/helper.glsl", "float helperRadius() { return 1.0; }\n");
  const fs::path scene = seed_scene(dir, "#include \"../lib/helper.glsl\"\n");
  const std::vector<std::string> bench = {"bench", scene.string(), "--size", "16x16", "--frames", "1", "--warmup", "0"};
  r = run_marchstudio(bench);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  std::vector<std::string> allowed = bench;
  allowed.insert(allowed.end(), {"--allow-include", (dir / "lib").string()});
  r = run_marchstudio(allowed);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// A FIFO named as the map or the Shadertoy file: opening it would block
// until someone writes to it, so it is refused as not a regular file.
TEST(Confinement, AFifoIsRefusedNotWaitedFor) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "fifo.glsl").c_str(), 0600), 0);
  write_file(dir / "map.toml", "[scene]\nmap = \"fifo.glsl\"\n[[materials]]\nname = \"a\"\n");
  write_file(dir / "st.toml", "[scene]\nshadertoy = \"fifo.glsl\"\n");
  for (const char* scene : {"map.toml", "st.toml"}) {
    const auto t0 = std::chrono::steady_clock::now();
    const RunResult r = run_marchstudio({"render", (dir / scene).string(), "-o", (dir / "out.png").string()});
    EXPECT_EQ(r.exit_code, 2) << scene << ": " << r.err;
    EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
    EXPECT_LT(seconds_since(t0), 10.0);
  }
}

TEST(Timeout, AShaderThatNeverEndsIsStoppedWithNoFile) {
  TempDir dir;
  write_file(dir / "endless.glsl", endless_loop());
  const auto t0 = std::chrono::steady_clock::now();
  const RunResult r = run_marchstudio(
      {"render", (dir / "endless.glsl").string(), "-o", (dir / "out.png").string(), "--size", "128x128",
       "--timeout", "2"});
  const double took = seconds_since(t0);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("--timeout: the render did not finish within 2 s"), std::string::npos) << r.err;
  // The draw itself never returns in time: the watchdog ends the process
  // half a second after the deadline (plus start-up), not after the minute.
  EXPECT_LT(took, 8.0);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"endless.glsl"}) << "a file was left behind";
}

TEST(Timeout, TooMuchWorkStopsBetweenDraws) {
  TempDir dir;
  const auto t0 = std::chrono::steady_clock::now();
  const RunResult r = run_marchstudio({"render", (source_dir() / "scenes/seed.toml").string(), "-o",
                                       (dir / "big.png").string(), "--size", "2048x2048", "--spp", "64",
                                       "--timeout", "1.5"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("within 1.5 s"), std::string::npos) << r.err;
  EXPECT_LT(seconds_since(t0), 8.0);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Timeout, AGenerousTimeoutChangesNothingAndBadValuesAreRefused) {
  TempDir dir;
  const std::string scene = (source_dir() / "scenes/seed.toml").string();
  RunResult r = run_marchstudio({"render", scene, "-o", (dir / "a.exr").string(), "--size", "96x54", "--spp", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_marchstudio(
      {"render", scene, "-o", (dir / "b.exr").string(), "--size", "96x54", "--spp", "2", "--timeout", "120"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_image(dir / "a.exr").pixels, read_image(dir / "b.exr").pixels);
  r = run_marchstudio({"render", scene, "-o", (dir / "c.png").string(), "--timeout", "-1"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--timeout"), std::string::npos) << r.err;
}

TEST(Timeout, ASequenceKeepsTheFramesBeforeTheOneThatHangs) {
  TempDir dir;
  write_file(dir / "late.glsl", endless_loop("iTime > 0.5"));  // frame 0 is quick, frame 1 never ends
  const RunResult r = run_marchstudio({"render", "late.glsl", "--frames", "0..3", "--fps", "1", "--size", "128x128",
                                       "-o", "f_%d.png", "--timeout", "2"},
                                      dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("--timeout: frame 1 did not finish within 2 s"), std::string::npos) << r.err;
  std::vector<std::string> files = dir.entries();
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"f_0.png", "late.glsl"})) << "frame 0 kept, nothing partial";
  EXPECT_EQ(read_image(dir / "f_0.png").width, 128);
}

// A still of a scene past the budget is drawn in tiles (test_huge_still.cpp);
// a shader with buffers needs them whole-frame, so it is refused.
TEST(MemoryBudget, AnOversizedFrameIsRefusedUpFrontWithTheFigure) {
  TempDir dir;
  write_file(dir / "c.json",
             R"({"Shader": {"info": {"name": "t"}, "renderpass": [)"
             R"({"name": "Buffer A", "type": "buffer", "code": "void mainImage(out vec4 o, in vec2 f) { o = vec4(1.0); }", )"
             R"("inputs": [], "outputs": [{"id": 257, "channel": 0}]}, )"
             R"({"name": "Image", "type": "image", "code": "void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0); }", )"
             R"("inputs": [{"id": 257, "ctype": "buffer", "channel": 0}], "outputs": []}]}})");
  const auto t0 = std::chrono::steady_clock::now();
  const RunResult r =
      run_marchstudio({"render", (dir / "c.json").string(), "-o", (dir / "big.png").string(), "--size", "12000x12000"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("--size: image size 12000x12000 needs "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("GiB of GPU buffers"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("memory budget"), std::string::npos) << r.err;
  EXPECT_LT(seconds_since(t0), 5.0) << "refused before any GL work";
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"c.json"});
}

TEST(Tiles, TiledAndWholeFrameRendersAreIdentical) {
  TempDir dir;
  const std::string scene = (source_dir() / "scenes/seed.toml").string();
  // 1100x620 is 3x2 tiles of at most 512; 100 gives 11x7 uneven ones.
  for (const std::string& tile : {"512", "0", "100"}) {
    const RunResult r = run_marchstudio({"render", scene, "-o", (dir / ("t" + tile + ".exr")).string(), "--size",
                                         "1100x620", "--spp", "2", "--tile-size", tile});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const Image whole = read_image(dir / "t0.exr");
  EXPECT_EQ(read_image(dir / "t512.exr").pixels, whole.pixels);
  EXPECT_EQ(read_image(dir / "t100.exr").pixels, whole.pixels);
}

}  // namespace
}  // namespace ms::test
