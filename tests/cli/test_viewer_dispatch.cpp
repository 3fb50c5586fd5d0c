// view --dispatch fragment|compute|auto: the scene pass traced by
// the compute dispatch draws what `render --dispatch fragment` draws, within
// 1/255: the one-pass frame (fused) and a frame accumulated to N samples; a
// pass compute cannot run (dFdx) is shown as an error and drawn with
// fragment, never fatal; a bad name is one line and exit 2; the compute
// program is compiled on the compile worker, frames coming meanwhile. Under
// Xvfb, on llvmpipe (GL 4.5: compute shaders).
#include <gtest/gtest.h>

#include <algorithm>

#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// A Shadertoy Image pass that needs derivatives: compute refuses it.
const char* kDerivative = "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(vec3(0.25 + 0.5 * dFdx(f.x)), 1.0);\n}\n";

// kBallMap's ball of radius 1.3 behind ball_map()'s slow-to-compile
// function: the image is the ball's, the compile and JIT take seconds.
std::string heavy_map() { return ball_map("1.3", kHeavyLines); }

class DispatchViewer : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
    write_file(dir / "seed.toml", kBallScene);
    write_file(dir / "seed.glsl", kBallMap);
    write_file(dir / "d.glsl", kDerivative);
  }
  // The viewer on `input` (a file in dir), its cache (auto's choice) in dir.
  void start(const std::string& input, std::vector<std::string> extra) {
    std::vector<std::string> argv = {"env", "XDG_CACHE_HOME=" + (dir / "cache").string(), x_display(), MARCH_BIN,
                                     "view", (dir / input).string(),
                                     "--size", "160x90", "--paused", "--time", "0", "--no-panel", "--log",
                                     log().string(), "--capture-dir", (dir / "cap").string(), "--exit-after", "90"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    proc = std::make_unique<BackgroundProcess>(argv, dir / "out.txt", dir / "err.txt");
    ASSERT_TRUE(proc->started());
    ASSERT_FALSE(wait_for_line(log(), "^reload ok 0 ", 60).empty()) << read_file(log()) << read_file(dir / "err.txt");
    ASSERT_FALSE(wait_for_line(log(), "^capture 0 ", 10).empty()) << read_file(log());
  }
  Image render(const std::string& input, std::vector<std::string> more) {
    std::vector<std::string> args = {"render", (dir / input).string(), "--size", "160x90", "--time", "0",
                                     "--dispatch", "fragment", "-o", (dir / "render.png").string()};
    args.insert(args.end(), more.begin(), more.end());
    const RunResult r = run_marchstudio(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_image(dir / "render.png");
  }
  fs::path log() const { return dir / "log.txt"; }

  TempDir dir;
  std::unique_ptr<BackgroundProcess> proc;
};

TEST_F(DispatchViewer, TheOnePassComputeFrameIsRendersFragmentFrame) {
  start("seed.toml", {"--accumulate", "1", "--dispatch", "compute"});
  EXPECT_FALSE(wait_for_line(log(), "^program fused=1 dispatch=compute$", 5).empty()) << read_file(log());
  EXPECT_LE(max_abs_diff(read_image(dir / "cap/frame_0.png"), render("seed.toml", {})), 1.0 / 255.0);
}

// Accumulated by compute to 4 samples (uMsAccumulate adds) against render --spp 4.
TEST_F(DispatchViewer, AComputeFrameAccumulatedToNIsRenderAtSppN) {
  start("seed.toml", {"--accumulate", "4", "--dispatch", "compute"});
  EXPECT_FALSE(wait_for_line(log(), "^program fused=0 dispatch=compute$", 5).empty()) << read_file(log());
  ASSERT_FALSE(wait_for_line(log(), "^accumulated_shot 4 ", 60).empty()) << read_file(log());
  const Image four = read_image(dir / "cap/converged_4.png");
  EXPECT_LE(max_abs_diff(four, render("seed.toml", {"--spp", "4"})), 1.0 / 255.0);
  EXPECT_GT(mean_abs_diff(four, render("seed.toml", {"--spp", "1"})), 1e-4) << "nothing was accumulated";
}

// --compute-group: the program is wrapped with that group, and its frame is
// the fragment frame still (a 16x8 group covers 160x90 with a partial row).
TEST_F(DispatchViewer, AGivenComputeGroupIsTheOneDrawn) {
  start("seed.toml", {"--accumulate", "1", "--dispatch", "compute", "--compute-group", "16x8"});
  EXPECT_FALSE(wait_for_line(log(), "^dispatch compute=(worker|ui) group=16x8$", 5).empty()) << read_file(log());
  EXPECT_LE(max_abs_diff(read_image(dir / "cap/frame_0.png"), render("seed.toml", {})), 1.0 / 255.0);
}

TEST_F(DispatchViewer, AutoLogsItsChoiceAndDrawsIt) {
  start("seed.toml", {"--accumulate", "1", "--dispatch", "auto"});
  const std::string chosen = wait_for_line(log(), "^dispatch auto=(fragment|compute)$", 5);
  ASSERT_FALSE(chosen.empty()) << read_file(log());
  const std::string name = chosen.substr(chosen.find('=') + 1);
  EXPECT_FALSE(wait_for_line(log(), "^program fused=1 dispatch=" + name + "$", 5).empty()) << read_file(log());
  EXPECT_TRUE(fs::exists(dir / "cache/marchstudio/dispatch")) << "auto's choice was not cached";
  EXPECT_LE(max_abs_diff(read_image(dir / "cap/frame_0.png"), render("seed.toml", {})), 1.0 / 255.0);
}

// A derivative call under --dispatch compute: the refusal is logged and on
// stderr (the window shows it), the frame is drawn with fragment, as render's.
TEST_F(DispatchViewer, ADerivativeShaderIsRefusedAndDrawnWithFragment) {
  start("d.glsl", {"--dispatch", "compute"});
  const std::string refused = wait_for_line(log(), "^dispatch fragment -- ", 5);
  EXPECT_NE(refused.find("dFdx"), std::string::npos) << read_file(log());
  EXPECT_NE(refused.find("d.glsl"), std::string::npos) << "the refusal names the file: " << refused;
  EXPECT_FALSE(wait_for_line(log(), "^program fused=0 dispatch=fragment$", 5).empty()) << read_file(log());
  EXPECT_NE(read_file(dir / "err.txt").find("dispatch fragment -- "), std::string::npos) << read_file(dir / "err.txt");
  EXPECT_TRUE(proc->running()) << "the viewer died of the refusal";
  EXPECT_LE(max_abs_diff(read_image(dir / "cap/frame_0.png"), render("d.glsl", {})), 1.0 / 255.0);
}

// A Shadertoy graph: buffer A (a fragment pass either way) counts frames,
// the Image pass traced by compute reads it. The shot after frame 40 is
// the fragment viewer's, and the count went on.
TEST_F(DispatchViewer, ABufferGraphsImagePassReadsTheBufferWithCompute) {
  write_file(dir / "s.toml",
             "[scene]\nname = \"count\"\n[render]\nwidth = 32\nheight = 24\n"
             "[[passes]]\ntype = \"buffer\"\nbuffer = \"A\"\nfile = \"a.glsl\"\niChannel0 = { buffer = \"A\" }\n"
             "[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\niChannel0 = { buffer = \"A\" }\n");
  write_file(dir / "a.glsl",
             "void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0) + vec4(0.25 / 255.0); }\n");
  write_file(dir / "img.glsl",
             "void mainImage(out vec4 o, in vec2 f) { o = vec4(texelFetch(iChannel0, ivec2(f), 0).r, 0.0, 0.0, 1.0); }\n");
  Image shots[2];
  for (int i = 0; i < 2; ++i) {
    const std::string d = i == 0 ? "fragment" : "compute";
    const fs::path l = dir / (d + ".log");
    BackgroundProcess p({"env", x_display(), MARCH_BIN, "view",
                         (dir / "s.toml").string(), "--size", "32x24", "--no-panel", "--log", l.string(),
                         "--shot-dir", (dir / d).string(), "--shot-frame", "40", "--max-frames", "45",
                         "--dispatch", d},
                        dir / "out.txt", dir / "err.txt");
    ASSERT_EQ(p.wait_exit(60), 0) << read_file(l) << read_file(dir / "err.txt");
    EXPECT_NE(read_file(l).find("program fused=0 dispatch=" + d + "\n"), std::string::npos) << read_file(l);
    shots[i] = read_image(dir / d / "s_1.png");
  }
  EXPECT_LE(max_abs_diff(shots[0], shots[1]), 1.0 / 255.0);
  EXPECT_GT(shots[1].at(0, 0, 0), 5.0f / 255.0f) << "the compute image pass did not see the buffer count";
}

// The compute program comes from the compile worker (compiled and warmed
// up there): the old program keeps drawing while a slow one compiles, the
// UI thread compiles nothing, and the adopted frame is render's.
TEST_F(DispatchViewer, TheComputeProgramCompilesOnTheWorker) {
  start("seed.toml", {"--accumulate", "1", "--dispatch", "compute"});
  save_by_rename(dir / "seed.glsl", heavy_map());
  ASSERT_FALSE(wait_for_line(log(), "^reload compiling 1$", 20).empty()) << read_file(log());
  const std::string line = wait_for_line(log(), "^reload (ok|failed) 1 ", 80);
  ASSERT_EQ(line.rfind("reload ok 1 ", 0), 0u) << line << read_file(dir / "err.txt");
  EXPECT_GT(field(line, "frames_during_compile"), 0) << line;
  ASSERT_FALSE(wait_for_line(log(), "^capture 1 ", 10).empty()) << read_file(log());
  const std::vector<std::string> lines = file_lines(log());
  // reload 0's program and reload 1's, both from the worker, both drawn by compute.
  EXPECT_EQ(std::count(lines.begin(), lines.end(), "dispatch compute=worker group=8x8"), 2) << read_file(log());
  EXPECT_EQ(std::count_if(lines.begin(), lines.end(), [](const std::string& l) { return l.rfind("dispatch compute=ui", 0) == 0; }), 0)
      << read_file(log());
  EXPECT_EQ(std::count(lines.begin(), lines.end(), "program fused=1 dispatch=compute"), 2) << read_file(log());
  const Image got = read_image(dir / "cap/frame_1.png");
  EXPECT_LE(max_abs_diff(got, render("seed.toml", {})), 1.0 / 255.0);
  EXPECT_GT(mean_abs_diff(got, read_image(dir / "cap/frame_0.png")), 1e-3) << "the reload did not change the image";
}

TEST(DispatchViewerFlag, ABadNameOrGroupIsOneLineAndExit2) {
  TempDir dir;
  write_file(dir / "seed.toml", kBallScene);
  write_file(dir / "seed.glsl", kBallMap);
  const RunResult r = run_marchstudio({"view", (dir / "seed.toml").string(), "--dispatch", "gpu"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--dispatch 'gpu'"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  const RunResult g = run_marchstudio({"view", (dir / "seed.toml").string(), "--compute-group", "64x64"});
  EXPECT_EQ(g.exit_code, 2) << g.err;
  EXPECT_NE(g.err.find("--compute-group '64x64'"), std::string::npos) << g.err;
  EXPECT_EQ(std::count(g.err.begin(), g.err.end(), '\n'), 1) << g.err;
}

}  // namespace
}  // namespace ms::test
